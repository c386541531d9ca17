#pragma once
// SPH Step's optional output fields of a state in any order, computed on the CPU (for a backend
// whose own order is not the CPU grid's: the fields come back in the state's order).
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"

#include <cstdint>
#include <vector>

namespace parafluid::sph
{
/// The pressure field at each particle [Pa] (SPHSolver::smoothedPressure).
std::vector<float> smoothedPressure(const SPHParameters& p, const ParticleState& s);
/// Neighbours of each particle within h, itself excluded (SPHSolver::neighbourCounts).
std::vector<std::uint32_t> neighbourCounts(const SPHParameters& p, const ParticleState& s);
} // namespace parafluid::sph
