#pragma once
// What a pressure solver reaches of the CPU simulation it advances: the particle state, the
// parameters, the neighbour grid, the mesh walls, the non-pressure forces, the moves and the
// time-step control. The solvers see only this, not SPHSolver's other members.
#include "parafluid/sph/SPHSolver.h"
#include "private/MeshWall.h"

namespace parafluid::sph
{
class SimulationParts
{
public:
  explicit SimulationParts(SPHSolver& simulation)
    : Sim(simulation)
  {
  }

  ParticleState& state() { return this->Sim.State; }
  const SPHParameters& parameters() const { return this->Sim.Parameters; }
  const NeighbourGrid& grid() const { return this->Sim.Grid; }
  /// The boundary mesh's wall sums at each particle, or null when the solver or scene has none.
  const detail::MeshWall* wall() const { return this->Sim.Wall.get(); }
  /// [m] the edge of the cube a particle fills at rest density.
  float particleSpacing() const { return this->Sim.ParticleSpacing; }
  /// The lattice correction of the solver's viscous operator (SolverEntry::viscousOperator).
  float laplacianCorrection() const { return this->Sim.LaplacianCorrection; }
  /// The step's statistics the solver fills in (time step, iterations).
  StepStatistics& statistics() { return this->Sim.Last; }
  void advanceTime(double dt) { this->Sim.Time += dt; }

  /// v += dt a.
  void kick(float dt) { this->Sim.kick(dt); }
  /// x += dt v, reflected by the walls and stopped by the boundary mesh.
  void drift(float dt) { this->Sim.drift(dt); }
  /// Sorts the state by grid cell (the solver's own arrays through its permute()) and finds the
  /// mesh walls of the sorted particles.
  void sortByCell() { this->Sim.sortByCell(); }
  /// The step to take with `remaining` seconds left (SPHSolver.cxx).
  double chooseTimeStep(double remaining) const { return this->Sim.chooseTimeStep(remaining); }
  void applyWallFriction(float dt) { this->Sim.applyWallFriction(dt); }
  /// Müller's forces, viscosity, gravity and surface tension into the accelerations (SPHForces.cxx).
  void computeAccelerations(bool withPressure) { this->Sim.computeAccelerations(withPressure); }
  /// Akinci's surface tension added to the accelerations (SurfaceTension.cxx).
  void addSurfaceTension() { this->Sim.addSurfaceTension(); }
  /// In a distributed run, the owners' values of these per-particle columns copied into the ghosts
  /// (GhostLayer::refresh); nothing in a serial run.
  void refreshGhosts(std::initializer_list<float*> columns)
  {
    if (this->Sim.Ghosts)
    {
      this->Sim.Ghosts->refresh(columns);
    }
  }
  /// A distributed run's ghost flag per particle (null in a serial run).
  const std::uint8_t* ghostFlags() const { return this->Sim.ghostFlags(); }
  /// The largest value over the processes of a distributed run (the value in a serial run).
  double globalMax(double value) const { return this->Sim.globalMax(value); }
  /// The largest |(x_i, y_i, z_i)| over the particles.
  double largestLength(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z) const
  {
    return this->Sim.largestLength(x, y, z);
  }

private:
  SPHSolver& Sim;
};
} // namespace parafluid::sph
