#pragma once
// A running SPH simulation, whatever runs it: the one interface SPH Step, the Rain filter's runoff
// and the benchmarks hold. makeSimulation is the one place that chooses an implementation; the
// CPU's is SPHSolver. A backend that keeps its state elsewhere (a GPU's memory) copies it to the
// host only when hostState() or an output pass asks, so nothing leaves the device between outputs.
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace parafluid
{
class TriangleBoundary;
}

namespace parafluid::sph
{
/// Where a simulation runs. Automatic picks the fastest this build and machine have.
enum class Backend
{
  Automatic,
  CPU,
  CUDA
};

struct StepStatistics
{
  double timeStep = 0.0;
  int densityIterations = 0;    // DFSPH only
  int divergenceIterations = 0; // DFSPH only
  int viscosityIterations = 0;  // DFSPH only: conjugate-gradient iterations of the implicit viscosity
  /// Mean over all particles of max(rho - rho0, 0) / rho0 after the step (measured, not predicted).
  double meanCompression = 0.0;
  /// Largest density over rho0 after the step.
  double maxDensityRatio = 0.0;
};

class Simulation
{
public:
  virtual ~Simulation() = default;

  /// Advances exactly `duration` seconds in as many steps as the time-step control needs (the last
  /// steps are shortened to land on the end time). `progress(fraction)` is called every few steps
  /// and stops the advance when it returns false. Returns the number of steps taken. Throws
  /// std::runtime_error, with what to change, when the simulation becomes unstable. Afterwards
  /// each particle's pressure is its time-weighted mean over the steps taken.
  virtual std::int64_t advance(double duration, const std::function<bool(double)>& progress = {}) = 0;
  /// Adds particles at the given positions [m] and velocities [m/s], at rest density; their ids
  /// continue after the largest so far. Throws std::invalid_argument for mismatched sizes or
  /// non-finite values.
  virtual void addParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                            const std::vector<float>& vx, const std::vector<float>& vy,
                            const std::vector<float>& vz) = 0;
  /// Removes the particles whose flag is non-zero, flags in hostState() order; returns how many.
  virtual std::size_t removeParticles(const std::vector<std::uint8_t>& remove) = 0;
  /// Takes out the particles outside the box (xmin, xmax, ymin, ymax, zmin, zmax) [m] and returns
  /// them, positions, velocities, densities and ids as they were (a distributed run hands them to
  /// the process that owns where they went).
  ParticleState removeParticlesOutside(const std::array<double, 6>& region);

  /// The state on the host, in the simulation's own order (ParticleState::originalIndex maps
  /// back to the initial order).
  virtual const ParticleState& hostState() const = 0;
  std::size_t particleCount() const { return this->hostState().size(); }
  /// The pressure field at each particle in hostState() order [Pa], a linear fit over each
  /// neighbourhood (SPHSolver.h says how); computed only when called.
  virtual std::vector<float> smoothedPressure() const = 0;
  /// Neighbours of each particle within h (itself excluded), in hostState() order.
  virtual std::vector<std::uint32_t> neighbourCounts() const = 0;

  virtual const SPHParameters& parameters() const = 0;
  virtual const StepStatistics& lastStep() const = 0;
  virtual double time() const = 0;
  virtual std::int64_t stepCount() const = 0;
  /// The step the time-step control would take now [s].
  virtual double proposedTimeStep() const = 0;
  /// Kinetic energy [J].
  virtual double kineticEnergy() const = 0;
  /// Bytes held per particle by the state, scratch and the neighbour search.
  virtual double bytesPerParticle() const = 0;
  /// What to change when the run blows up, in the properties of the chosen solver.
  virtual std::string stabilityAdvice() const = 0;
  /// The backend's name for messages ("CPU").
  virtual const char* backendName() const = 0;
};

/// The simulation of the initial state (positions, velocities, ids; the rest is computed) with an
/// optional boundary mesh, on `backend`: Automatic takes the GPU when the CUDA backend is usable
/// here and runs the scene, else the CPU. `choice`, when given, gets which backend runs and, for
/// the CPU under Automatic, why not the GPU. Throws std::invalid_argument for bad parameters,
/// non-finite input, or Backend CUDA where it cannot run (the message says why), and
/// std::runtime_error when the GPU lacks the memory.
std::unique_ptr<Simulation> makeSimulation(const SPHParameters& parameters, ParticleState initial,
                                           std::shared_ptr<const TriangleBoundary> boundary = nullptr,
                                           Backend backend = Backend::Automatic, std::string* choice = nullptr);
} // namespace parafluid::sph
