#pragma once
// The CUDA implementation of Simulation (Filters/SPH/Core/cuda): whether this build and machine
// can run it, what it runs, and its factory. The rest of the code calls makeSimulation, which
// asks these.
#include "parafluid/common/ParticleState.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/Simulation.h"

#include <memory>
#include <string>

namespace parafluid::sph
{
/// Whether this build has the CUDA backend and a GPU it can run on; when not, why in `reason`
/// (no GPU, no driver, code for another GPU generation, or a build without CUDA).
bool cudaBackendUsable(std::string* reason = nullptr);
/// The GPU the CUDA backend runs on, for messages ("NVIDIA H200"); empty when none is usable.
std::string cudaDeviceName();
/// What of these parameters the CUDA backend does not run yet, named by SPH Step's properties;
/// empty when it runs all of it.
std::string cudaBackendLacks(const SPHParameters& parameters);
/// The simulation on the GPU, with the boundary mesh when one is given. Throws
/// std::invalid_argument as SPHSolver does, or std::runtime_error when the GPU fails or lacks the
/// memory (the message gives the bytes asked and free).
std::unique_ptr<Simulation> makeCudaSimulation(const SPHParameters& parameters, ParticleState initial,
                                               std::shared_ptr<const TriangleBoundary> boundary = nullptr);
} // namespace parafluid::sph
