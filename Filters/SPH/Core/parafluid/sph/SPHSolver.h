#pragma once
// SPH fluid in an axis-aligned box, optionally with a triangle-mesh boundary, advanced by one of two
// pressure solvers (SPHParameters::pressureSolver; PressureSolver.h, one class each):
//  - WCSPH, Müller, Charypar & Gross (SCA 2003): density by poly6, p = k (rho - rho0) with the spiky
//    gradient, velocity-Verlet leapfrog (kick-drift-kick);
//  - DFSPH, Bender & Koschier (SCA 2015 / TVCG 2017): cubic-spline kernel, a density solve before
//    the position update and a divergence solve after it, both warm-started from the last step.
// Both share the neighbour grid, the box walls (mirror images plus damped reflection), the mesh
// boundary, Müller's viscosity and colour-field surface tension, and the adaptive time step.
// Passes a scene does not need are skipped: viscosity when mu = 0, the colour field when sigma = 0.
// The state is kept sorted by grid cell so neighbour loops read memory contiguously.
#include "parafluid/common/NeighbourGrid.h"
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/GhostLayer.h"
#include "parafluid/sph/PressureSolver.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/Simulation.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace parafluid
{
class TriangleBoundary;
}

namespace parafluid::sph
{
namespace detail
{
struct MeshWall;
}

/// Whole particles as columns, to move between the processes of a distributed run: every float
/// column SPHSolver::carriedColumns() lists, in that order, then the ids and original indices.
struct ParticleRows
{
  std::vector<std::vector<float>> columns;
  std::vector<std::int64_t> id;
  std::vector<std::uint32_t> originalIndex;
  std::size_t size() const { return id.size(); }
};

/// The CPU implementation of Simulation (OpenMP, SIMD pair loops).
class SPHSolver final : public Simulation
{
public:
  /// Takes the initial state (positions, velocities, ids; the rest is computed) and an optional
  /// boundary mesh. Throws std::invalid_argument for bad parameters or non-finite input.
  SPHSolver(const SPHParameters& parameters, ParticleState initial,
            std::shared_ptr<const TriangleBoundary> boundary = nullptr);
  /// One process's region of a distributed run: `initial` holds its own particles and, flagged by
  /// `ghosts` (which outlives this), the ghosts; its reductions and refreshes are the layer's.
  SPHSolver(const SPHParameters& parameters, ParticleState initial, std::shared_ptr<const TriangleBoundary> boundary,
            GhostLayer* ghosts);
  ~SPHSolver();
  SPHSolver(SPHSolver&&) noexcept;
  SPHSolver& operator=(SPHSolver&&) noexcept;

  /// Advances exactly `duration` seconds in as many steps as the time-step control needs (the last
  /// steps are shortened to land on the end time). `progress(fraction)` is called every few steps
  /// and stops the advance when it returns false. Returns the number of steps taken. Throws
  /// std::runtime_error when the simulation becomes unstable. Afterwards each particle's pressure
  /// is its time-weighted mean over the steps taken: DFSPH's per-step pressure is an impulse that
  /// also removes the last step's density error in one step (so it swings from step to step, the
  /// more the shorter the step), and WCSPH's rings acoustically; the mean is what moved the fluid.
  std::int64_t advance(double duration, const std::function<bool(double)>& progress = {}) override;
  /// One step of at most maxStep seconds; returns the step taken [s]. Pressure is that step's.
  double step(double maxStep = 1e30);
  /// Adds particles to the running simulation (a source: rain, an inflow) at the given positions
  /// [m] and velocities [m/s], at rest density; their ids continue after the largest id so far and
  /// their originalIndex after the largest one. The pressure solver restarts on the new set (a
  /// DFSPH warm start is lost). Throws std::invalid_argument for mismatched sizes or non-finite
  /// values.
  void addParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                    const std::vector<float>& vx, const std::vector<float>& vy, const std::vector<float>& vz) override;
  /// Removes the particles whose flag is non-zero (a sink: infiltration, an outflow), flags in state
  /// order; returns how many were removed.
  std::size_t removeParticles(const std::vector<std::uint8_t>& remove) override;
  /// The step the time-step control would take now [s] (WCSPH; DFSPH adds non-pressure forces first).
  double proposedTimeStep() const override;

  // What a distributed run moves particles with (DistributedSimulation): whole particles leave
  // and join the state without the pressure solver restarting, so a particle handed to another
  // process carries on as it would have here.
  /// The per-particle float columns a particle carries from step to step, in a fixed order: the
  /// state's, the pressure solver's, and the pressure mean's while an advance runs.
  std::vector<std::vector<float>*> carriedColumns();
  /// Takes out the particles whose flag is non-zero (state order) and returns them whole.
  ParticleRows takeRows(const std::vector<std::uint8_t>& take);
  /// Appends whole particles at the end of the state (unsorted until sortState()).
  void appendRows(const ParticleRows& rows);
  /// Sorts the state by grid cell after rows moved, every carried column with its particle (the
  /// ghost layer is told the order).
  void sortState();
  /// Appends particles as addParticles() does, neither sorted nor started (restartPressure()).
  std::size_t appendParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                              const std::vector<float>& vx, const std::vector<float>& vy, const std::vector<float>& vz);
  /// Gives the particles from index `from` on consecutive ids and original indices.
  void numberParticles(std::size_t from, std::int64_t firstId, std::uint32_t firstIndex);
  /// The pressure solver's restart after particles were added, or its start after some were removed.
  void restartPressure();
  void startPressure();
  /// The time-weighted mean pressure of advance(), for a caller that takes the steps itself.
  void beginPressureMean();
  void addToPressureMean(double dt);
  void endPressureMean(double elapsed);

  const ParticleState& state() const { return this->State; }
  const ParticleState& hostState() const override { return this->State; }
  const SPHParameters& parameters() const override { return this->Parameters; }
  std::int64_t stepCount() const override { return this->Steps; }
  double time() const override { return this->Time; }
  const char* backendName() const override { return "CPU"; }

  using StepStatistics = sph::StepStatistics;
  const StepStatistics& lastStep() const override { return this->Last; }

  /// Neighbours of each particle within h (itself excluded), in state order. A separate pass:
  /// computed only when called.
  std::vector<std::uint32_t> neighbourCounts() const override;
  /// The pressure field at each particle, in state order [Pa]: a linear field fitted by weighted
  /// least squares over each neighbourhood (poly6 weights; wall images carry their particles'
  /// pressures lifted hydrostatically), read at the particle (SmoothedPressure.cxx). It drops the
  /// layer-by-layer alternating pattern that a collocated SPH pressure gradient cannot see (it
  /// exerts no force, so no solver removes it) and that makes single-particle pressures noisy, and
  /// it reproduces a linear field exactly where free surfaces and walls cut the neighbourhood. A
  /// separate pass: computed only when called.
  std::vector<float> smoothedPressure() const override;
  /// Kinetic energy [J].
  double kineticEnergy() const override;
  /// Bytes held per particle by the state, scratch and the neighbour grid.
  double bytesPerParticle() const override;
  /// The fastest a particle may move in this scene before the run counts as blown up [m/s]: ten
  /// times the free-fall speed over the domain's largest extent plus the fastest initial speed.
  double speedLimit() const { return this->SpeedLimit; }
  /// What to change when the run blows up, in the properties of the chosen solver.
  std::string stabilityAdvice() const override;

private:
  void sortByCell();
  /// Each particle's nearest point of the boundary mesh (when the solver adds the mesh's wall to
  /// its sums, SPHParameters::meshWallDensity); after every sort and every move that follows one.
  void findMeshWalls();
  void checkFinite() const;
  double chooseTimeStep(double remaining) const;
  double maxAcceleration() const;
  /// The largest |(x_i, y_i, z_i)| over the particles (0 for none); in a distributed run over every
  /// process's own particles.
  double largestLength(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z) const;
  void kick(float dt);
  void drift(float dt);
  /// The LogLaw wall shear over dt, implicit in the tangential velocity (WallFriction.cxx).
  void applyWallFriction(float dt);
  void measureCompression();
  /// Throws when the density or a speed is far beyond what the scene allows (a blown-up run
  /// that has not reached NaN yet).
  void checkPhysical() const;

  /// Viscosity, surface tension, gravity and (when withPressure) the equation-of-state pressure
  /// into State.a*; each pass is compiled in only when its coefficient is non-zero (SPHForces.cxx).
  void computeAccelerations(bool withPressure);
  /// Adds Akinci et al.'s (2013) cohesion, and with SurfaceTensionModel::Akinci their curvature
  /// term, to State.a* (SurfaceTension.cxx), when sigma > 0 and one of those models is chosen.
  void addSurfaceTension();
  /// The surface normals of Akinci's curvature term into SurfaceNormal.
  void computeSurfaceNormals();

  // The pressure solvers advance the simulation through its shared parts (grid, walls, forces,
  // time-step control), which they reach only through SimulationParts, and keep their own arrays.
  friend class SimulationParts;

  /// An advance is summing the time-weighted pressure (PressureImpulse).
  bool AveragingPressure = false;
  /// The other processes of a distributed run, or null.
  GhostLayer* Ghosts = nullptr;
  /// The value reduced over the processes (itself in a serial run).
  double globalSum(double value) const { return this->Ghosts ? this->Ghosts->sum(value) : value; }
  double globalMax(double value) const { return this->Ghosts ? this->Ghosts->max(value) : value; }
  /// Null, or a flag per particle that is 1 for a ghost.
  const std::uint8_t* ghostFlags() const { return this->Ghosts ? this->Ghosts->ghostFlags().data() : nullptr; }
  /// Each process's own particles in the state.
  std::size_t ownCount() const;

  SPHParameters Parameters;
  ParticleState State;
  std::shared_ptr<const TriangleBoundary> Boundary;
  NeighbourGrid Grid;
  std::vector<float> ScratchFloat;
  std::vector<std::int64_t> ScratchId;
  std::vector<std::uint32_t> ScratchIndex;
  std::vector<float> InverseDensity;
  std::array<std::vector<float>, 3> SurfaceNormal; // Akinci's n_i = h sum_j (m / rho_j) grad W_ij
  // Akinci's gamma for the parameters it was computed from (model, sigma, h, m, rho0, kernel).
  float AkinciGamma = 0.0f;
  std::array<float, 6> AkinciGammaKey = {};
  std::vector<float> PressureImpulse; // sum of p dt over the steps of advance() [Pa s]
  float ParticleSpacing = 0.0f;       // [m] edge of the cube a particle fills at rest density
  // Lattice corrections of the chosen solver's viscous operator and of Müller's spiky pressure
  // gradient (SPHParameters.h), fixed for a run.
  float LaplacianCorrection = 1.0f;
  float SpikyGradientCorrection = 1.0f;
  std::int64_t Steps = 0;
  double Time = 0.0;
  double SpeedLimit = 0.0; // [m/s], see speedLimit()
  StepStatistics Last;
  std::unique_ptr<PressureSolver> Pressure; // WCSPH or DFSPH (SPHParameters::pressureSolver)
  std::unique_ptr<detail::MeshWall> Wall;   // the mesh's wall sums (DFSPH, δ-SPH), else null
};
} // namespace parafluid::sph
