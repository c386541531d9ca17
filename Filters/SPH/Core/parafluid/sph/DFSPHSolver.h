#pragma once
// Divergence-free SPH (Bender & Koschier, "Divergence-Free Smoothed Particle Hydrodynamics",
// SCA 2015 / TVCG 2017): cubic-spline kernel, a density solve before the position update (a
// conjugate gradient, or Jacobi iterations: SPHParameters::pressureConjugateGradient) and a
// divergence solve after it (Jacobi iterations), on per-particle stiffnesses warm-started from
// the last step. The fluid's viscosity is solved implicitly before the density solve (Weiler et
// al. 2018), so it does not limit the step.
#include "parafluid/sph/PressureSolver.h"
#include "parafluid/sph/SolverRegistry.h"

namespace parafluid::sph
{
class DFSPHSolver final : public PressureSolver
{
public:
  /// This solver's entry of the registry (SolverRegistry.h).
  static SolverEntry registryEntry();
  void start(SimulationParts& sim) override;
  double step(SimulationParts& sim, double remaining) override;
  double signalSpeed(const SPHParameters&) const override { return 0.0; }
  void permute(SimulationParts& sim, const std::vector<std::uint32_t>& order, std::vector<float>& scratch,
               int threads) override;
  std::size_t bytes() const override;
  void resize(std::size_t n) override;
  void restart(SimulationParts& sim) override;

private:
  /// A particle with fewer neighbours than this (itself and wall images included) is at the free
  /// surface: a full neighbourhood at h = 2 spacings holds 27, a surface layer 18. The divergence
  /// solve leaves surface particles free to separate, as Bender & Koschier's implementation does.
  static constexpr std::uint16_t kSurfaceNeighbours = 20;

  void computeDensityAndFactor(SimulationParts& sim);
  /// Scales the last step's stiffnesses by `keep` and applies their impulse.
  void warmStart(SimulationParts& sim, std::vector<float>& accumulated, float dt, float keep);
  int solveDensity(SimulationParts& sim, float dt);
  int solveDivergence(SimulationParts& sim, float dt);
  /// Sum over neighbours j of m (v_i - v_j) . grad W_ij into DensityRate (D rho / D t).
  void computeDensityRate(SimulationParts& sim);
  /// Replaces the predicted velocities by the implicit viscous solve (ImplicitViscosity.cxx);
  /// returns the conjugate-gradient iterations.
  int solveViscosity(SimulationParts& sim, float dt);
  /// v_i -= dt sum_j m (k_i + k_j) grad W_ij with k = Stiffness; `record` adds it to the
  /// accelerations output too.
  void applyPressureImpulse(SimulationParts& sim, float dt, bool record = true);
  /// The density solve as a conjugate gradient (DFSPHConjugateGradient.cxx); returns iterations.
  int solveDensityByConjugateGradient(SimulationParts& sim, float dt);
  /// From the warm start DensityStiffness (already applied), finds the stiffness increments on the
  /// particles in Active that make the predicted density error in Residual (kg/m^3, one per
  /// particle) vanish within at most `budget` iterations, adds them to DensityStiffness (clamped to
  /// no tension) and applies their impulse. Returns iterations.
  int solveConjugateGradient(SimulationParts& sim, float dt, int budget);
  /// Where no particle is at a free surface, takes the mean over the particles in Active out of
  /// `error` (no pressure can change an enclosed fluid's volume).
  void removeEnclosedMean(SimulationParts& sim, std::vector<float>& error) const;
  /// B x = -dt D(dv(x)): the density change the impulse of stiffnesses x takes away, rows outside
  /// `active` zero (velocities and accelerations left as they were).
  void densityChangeOperator(SimulationParts& sim, float dt, const std::vector<float>& x,
                             const std::vector<char>& active, std::vector<float>& out);

  // alpha factor, D rho / D t, the stiffness of the current iteration, and the accumulated
  // stiffness of both solves (the warm start of the next step; p = rho^2 k).
  std::vector<float> Factor, DensityRate, Stiffness, DensityStiffness, DivergenceStiffness;
  std::vector<std::uint16_t> NeighbourCount; // neighbours incl. images, for the surface test
  // The conjugate gradient's vectors, and the velocities kept aside while its operator runs.
  std::vector<float> Residual, Direction, Product, Preconditioned, Increment, SavedVelocity[3];
  std::vector<char> Active;
  float GradientCorrection = 1.0f; // pressure forces, see latticeGradientCorrection
};
} // namespace parafluid::sph
