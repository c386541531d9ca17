#pragma once
// Internal to the CUDA backend: Müller's WCSPH on the GPU as a Simulation, each step the CPU's
// (WCSPHSolver::step) with the passes of MullerKernels.cuh.
#include "cuda/CudaSimulation.cuh"
#include "cuda/MullerKernels.cuh"
#include "cuda/SurfaceTensionKernels.cuh"

#include <optional>

namespace parafluid::sph::cuda
{
class CudaWCSPHSimulation final : public CudaSimulation
{
public:
  /// `boundary` (may be null) is copied to the GPU; it need not outlive the simulation.
  CudaWCSPHSimulation(const SPHParameters& parameters, ParticleState initial,
                      std::shared_ptr<const TriangleBoundary> boundary);

private:
  /// WCSPH's bytes per particle beyond the state: the 3 of Akinci's surface normals, when on.
  static std::size_t solverBytesPerParticle(const SPHParameters& p);

  void prepare(ParticleState& s, Columns& columns) override;
  void startPasses() override;
  double stepPasses(double remaining) override;
  std::vector<DeviceBuffer<float>*> solverArrays() override { return { &this->Normals }; }
  double signalSpeed() const override;

  /// Density and pressure from the positions, then the accelerations (WCSPHSolver::start).
  void densityAndForces();

  MullerDensityConstants Density{};
  detail::MullerConstants Forces{};
  bool Viscosity = false, ColourTension = false;
  std::optional<AkinciConstants<Poly6Kernel>> Tension; // Akinci's models
  DeviceBuffer<float> Normals;                         // 3 n with Akinci's curvature term
};
} // namespace parafluid::sph::cuda
