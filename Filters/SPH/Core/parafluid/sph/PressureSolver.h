#pragma once
// A pressure solver of the SPH simulation (in the manner of SPlisHSPlasH's TimeStep classes): it
// owns the per-particle arrays only it needs and advances the simulation it is handed by one step,
// using the simulation's shared parts (neighbour grid, walls, non-pressure forces, time-step control).
//
// Adding a solver: docs/extending.md (a class deriving from PressureSolver with its registry
// entry, a value of PressureSolverType, and the enumeration entry of the plugin XML's
// PressureSolver properties, which a test holds to the registry).
#include "parafluid/sph/SPHParameters.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace parafluid::sph
{
class SimulationParts;

class PressureSolver
{
public:
  virtual ~PressureSolver() = default;
  /// Densities, pressures and accelerations of the initial state (sorted by cell).
  virtual void start(SimulationParts& simulation) = 0;
  /// One step of at most `remaining` seconds, its length chosen by the simulation's time-step
  /// control; returns the step taken [s]. Leaves each particle's pressure of that step.
  virtual double step(SimulationParts& simulation, double remaining) = 0;
  /// The speed [m/s] the CFL condition adds to the flow speed: the sound speed of a weakly
  /// compressible fluid, 0 for an incompressible one.
  virtual double signalSpeed(const SPHParameters& parameters) const = 0;
  /// Reorders the per-particle arrays this solver carries from step to step after the simulation
  /// sorted its particles by grid cell (`order[k]`: the old index of new particle k).
  virtual void permute(SimulationParts& simulation, const std::vector<std::uint32_t>& order,
                       std::vector<float>& scratch, int threads) = 0;
  /// Particles were added at the end of the state (SPHSolver::addParticles): the arrays this
  /// solver carries from step to step grow to n (new entries zero), before the state is sorted.
  virtual void resize(std::size_t /*n*/) {}
  /// After particles were added and the state sorted: what start() computes, keeping what the
  /// solver carries from step to step (DFSPH's warm starts). By default start() again.
  virtual void restart(SimulationParts& simulation) { this->start(simulation); }
  /// The per-particle arrays (one float per particle, state order) this solver carries from one
  /// step to the next, which a particle handed to another process of a distributed run takes along.
  virtual std::vector<std::vector<float>*> carried() { return {}; }
  /// Bytes held by this solver's arrays.
  virtual std::size_t bytes() const = 0;
};

/// The solver `type` names (its registry entry's creator, SolverRegistry.h).
std::unique_ptr<PressureSolver> makePressureSolver(PressureSolverType type);
} // namespace parafluid::sph
