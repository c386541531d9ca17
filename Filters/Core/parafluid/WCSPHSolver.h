#pragma once
// Weakly compressible SPH after Müller, Charypar & Gross (SCA 2003): density by poly6, pressure
// p = k (rho - rho0) with the spiky gradient, viscosity with the viscosity-kernel Laplacian,
// gravity, velocity-Verlet leapfrog (kick-drift-kick), an axis-aligned box with damped reflection.
// Neighbours come from a uniform grid rebuilt every step; the state is kept sorted by grid cell so
// neighbour loops read memory contiguously.
#include "parafluid/NeighbourGrid.h"
#include "parafluid/ParticleState.h"
#include "parafluid/SPHParameters.h"

#include <cstdint>

namespace parafluid::sph
{
class WCSPHSolver
{
public:
  /// Takes the initial state (positions, velocities, ids; the rest is computed). Throws
  /// std::invalid_argument for bad parameters or non-finite input.
  WCSPHSolver(const SPHParameters& parameters, ParticleState initial);

  /// Advances one time step. Throws std::runtime_error if the state becomes non-finite.
  void step();
  /// Density, pressure and acceleration for the current positions (step() keeps them current).
  void computeForces();

  const ParticleState& state() const { return this->State; }
  const SPHParameters& parameters() const { return this->Parameters; }
  std::int64_t stepCount() const { return this->Steps; }
  /// Bytes held per particle by the state and the neighbour grid (scratch included).
  double bytesPerParticle() const;

private:
  void sortByCell();
  void computeDensityAndPressure();
  void computeAccelerations();
  void kick(float dt);
  void drift(float dt);

  SPHParameters Parameters;
  ParticleState State;
  NeighbourGrid Grid;
  std::vector<float> ScratchFloat;
  std::vector<std::int64_t> ScratchId;
  std::vector<std::uint32_t> ScratchIndex;
  std::vector<float> InverseDensity;
  std::int64_t Steps = 0;
};
} // namespace parafluid::sph
