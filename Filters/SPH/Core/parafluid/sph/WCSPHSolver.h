#pragma once
// Weakly compressible SPH after Müller, Charypar & Gross (SCA 2003): density by poly6, the
// equation of state p = k (rho - rho0) (negative pressure clamped), the spiky pressure gradient
// summed with the other forces, and a kick-drift-kick leapfrog step.
#include "parafluid/sph/PressureSolver.h"
#include "parafluid/sph/SolverRegistry.h"

namespace parafluid::sph
{
class WCSPHSolver final : public PressureSolver
{
public:
  /// This solver's entry of the registry (SolverRegistry.h).
  static SolverEntry registryEntry();
  void start(SimulationParts& sim) override;
  double step(SimulationParts& sim, double remaining) override;
  double signalSpeed(const SPHParameters& p) const override;
  void permute(SimulationParts&, const std::vector<std::uint32_t>&, std::vector<float>&, int) override {}
  std::size_t bytes() const override { return 0; }

private:
  void computeDensityAndPressure(SimulationParts& sim);
};
} // namespace parafluid::sph
