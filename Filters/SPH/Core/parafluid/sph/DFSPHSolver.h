#pragma once
// Divergence-free SPH (Bender & Koschier, "Divergence-Free Smoothed Particle Hydrodynamics",
// SCA 2015 / TVCG 2017): cubic-spline kernel, a density solve before the position update and a
// divergence solve after it, both Jacobi iterations on per-particle stiffnesses warm-started from
// the last step. The fluid's viscosity is solved implicitly before the density solve (Weiler et
// al. 2018), so it does not limit the step.
#include "parafluid/sph/PressureSolver.h"

namespace parafluid::sph
{
class DFSPHSolver final : public PressureSolver
{
public:
  void start(SPHSolver& sim) override;
  double step(SPHSolver& sim, double remaining) override;
  double signalSpeed(const SPHParameters&) const override { return 0.0; }
  void permute(SPHSolver& sim, const std::vector<std::uint32_t>& order, std::vector<float>& scratch,
               int threads) override;
  std::size_t bytes() const override;
  void resize(std::size_t n) override;
  void restart(SPHSolver& sim) override;

private:
  void computeDensityAndFactor(SPHSolver& sim);
  void warmStart(SPHSolver& sim, std::vector<float>& accumulated, float dt);
  int solveDensity(SPHSolver& sim, float dt);
  int solveDivergence(SPHSolver& sim, float dt);
  /// Sum over neighbours j of m (v_i - v_j) . grad W_ij into DensityRate (D rho / D t).
  void computeDensityRate(SPHSolver& sim);
  /// Replaces the predicted velocities by the implicit viscous solve (ImplicitViscosity.cxx);
  /// returns the conjugate-gradient iterations.
  int solveViscosity(SPHSolver& sim, float dt);
  /// v_i -= dt sum_j m (k_i + k_j) grad W_ij with k = Stiffness.
  void applyPressureImpulse(SPHSolver& sim, float dt);

  // alpha factor, D rho / D t, the stiffness of the current iteration, and the accumulated
  // stiffness of both solves (the warm start of the next step; p = rho^2 k).
  std::vector<float> Factor, DensityRate, Stiffness, DensityStiffness, DivergenceStiffness;
  std::vector<std::uint16_t> NeighbourCount; // neighbours incl. images, for the surface test
  float GradientCorrection = 1.0f;           // pressure forces, see latticeGradientCorrection
};
} // namespace parafluid::sph
