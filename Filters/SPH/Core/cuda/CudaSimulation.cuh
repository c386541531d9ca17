#pragma once
// Internal to the CUDA backend: what every solver's Simulation on the GPU shares. The state stays
// in GPU memory between steps and between outputs (hostState() copies it to the host when
// asked); each step sorts it by cell; particles added or removed restart the solver from the host
// copy. A solver (CudaDeltaSimulation, CudaWCSPHSimulation) adds its own arrays and passes through
// the hooks below, as a PressureSolver does on the CPU.
#include "cuda/CellSort.cuh"
#include "cuda/DeviceBuffer.h"
#include "cuda/DeviceMesh.cuh"
#include "cuda/StateKernels.cuh"
#include "parafluid/sph/Simulation.h"

#include <vector>

namespace parafluid::sph::cuda
{
class CudaSimulation : public Simulation
{
public:
  std::int64_t advance(double duration, const std::function<bool(double)>& progress = {}) override;
  void addParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                    const std::vector<float>& vx, const std::vector<float>& vy, const std::vector<float>& vz) override;
  std::size_t removeParticles(const std::vector<std::uint8_t>& remove) override;
  const ParticleState& hostState() const override;
  std::vector<float> smoothedPressure() const override;
  std::vector<std::uint32_t> neighbourCounts() const override;
  const SPHParameters& parameters() const override { return this->Parameters; }
  const StepStatistics& lastStep() const override { return this->Last; }
  double time() const override { return this->Time; }
  std::int64_t stepCount() const override { return this->Steps; }
  double proposedTimeStep() const override;
  double kineticEnergy() const override;
  double bytesPerParticle() const override;
  std::string stabilityAdvice() const override;
  const char* backendName() const override { return "CUDA"; }

protected:
  /// Per-particle values a solver carries from step to step beyond the state (δ-SPH: each
  /// particle's fullness and slow departure), one vector each, in hostState() order.
  using Columns = std::vector<std::vector<float>>;

  /// `boundary` (may be null) is copied to the GPU; it need not outlive the simulation.
  /// `solverBytesPerParticle`: what the solver's own arrays take, for the check before the arrays
  /// are made. The solver's constructor calls begin() once its own members are set.
  /// `initial` is completed (completeInitialState) and checked here.
  CudaSimulation(const SPHParameters& parameters, ParticleState& initial,
                 std::shared_ptr<const TriangleBoundary> boundary, std::size_t solverBytesPerParticle);
  /// The first start: `initial` with every column at its new particles' value.
  void begin(ParticleState initial);

  // The solver's hooks.
  /// Host side of a start, after the moves out of the walls: fills s.density (the uploaded
  /// density) and the columns' missing values, uploads the columns and makes its arrays room for N.
  virtual void prepare(ParticleState& s, Columns& columns) = 0;
  /// The passes of a start after the first sort: density, pressure and accelerations.
  virtual void startPasses() = 0;
  /// One step of at most `remaining` seconds (timeStepFor), which the state's measures follow;
  /// returns its length.
  virtual double stepPasses(double remaining) = 0;
  /// Each column's value for a particle that has none (added, or after a removal): NaN means the
  /// start computes it. One value per column.
  virtual std::vector<float> newParticleColumns() const { return {}; }
  /// The columns in hostState() order.
  virtual Columns downloadColumns() const { return {}; }
  /// Float arrays of the solver's own that move with their particle when the state is sorted.
  virtual std::vector<DeviceBuffer<float>*> sortedSolverArrays() { return {}; }
  /// Every float array of the solver's own (for bytesPerParticle and a restart's release).
  virtual std::vector<DeviceBuffer<float>*> solverArrays() = 0;
  /// The speed the time-step control and SPH's CFL condition use [m/s].
  virtual double signalSpeed() const = 0;

  // What the hooks use.
  DeviceState state() const;
  /// Sorts the state by cell (and the solver's sorted arrays with it) and finds each particle's
  /// mesh wall where it now is.
  void sortByCell();
  /// The measures of the state into Measures and Last (impulse += weight p first).
  void measure(float weight);
  /// v += dt a; the moves of dt through the walls; the law of the wall (when on) over dt.
  void kick(float dt);
  void drift(float dt);
  void applyWallFriction(float dt);
  /// dst = src[order[k]] through the scratch array.
  void permute(DeviceBuffer<float>& buffer, const std::uint32_t* order);

  /// The stream the passes run on and the page-locked copy of the measures, released last.
  struct StreamAndPinned
  {
    cudaStream_t stream = nullptr;
    StepMeasures* pinned = nullptr;
    StreamAndPinned();
    ~StreamAndPinned();
  };

  StreamAndPinned Gpu;
  SPHParameters Parameters;
  DeviceWalls Walls{};
  cudaStream_t Stream = nullptr; // Gpu.stream
  std::uint32_t N = 0;
  DeviceBuffer<float> X, Y, Z, VX, VY, VZ, AX, AY, AZ, Rho, P, Impulse, Scratch;
  DeviceBuffer<StepMeasures> Partials, Result;
  DeviceMesh Mesh;       // triangleCount 0: no boundary mesh
  bool MeshWall = false; // the mesh's wall is in the sums (SPHParameters::meshWallDensity, the solver's meshWallInSums)
  StepMeasures Measures{};
  DeviceGrid Grid{};
  float Spacing = 0.0f;             // the lattice spacing of the particles' mass [m]
  float LaplacianCorrection = 1.0f; // latticeViscousCorrection
  double SpeedLimit = 0.0;

private:
  /// The GPU's bytes per particle of the state: 13 floats, the id and index with their scratches,
  /// the sort's keys and values in and out (the cells' starts and the sort's scratch come on top,
  /// a few bytes a particle); with a mesh wall in the sums each particle's distance, normal,
  /// triangle and wall sum.
  static constexpr std::size_t kStateBytesPerParticle = 4 * 13 + (8 + 4) * 2 + (8 + 4) * 2;
  static constexpr std::size_t kMeshWallBytesPerParticle = 4 * 6;
  std::size_t bytesNeededPerParticle() const;
  /// Uploads `s`, moves particles outside the walls in, and starts the solver on it.
  void start(ParticleState s, Columns columns);
  /// start() with s, or, when that fails (the GPU's memory ran out part way), start() again from
  /// the state before (in the memory it had) and rethrow: a failed add or removal loses nothing.
  void restartKeeping(ParticleState s, Columns columns, Columns columnsBefore);
  /// Calls f on every float array, then g on every index array, the state's and the solver's.
  template<class F, class G>
  void forEachArray(F&& f, G&& g);
  void releaseArrays();
  double step(double remaining);
  void checkStep() const;

  std::size_t SolverBytesPerParticle;
  DeviceBuffer<std::int64_t> Id, IdScratch;
  DeviceBuffer<std::uint32_t> Index, IndexScratch;
  DeviceBuffer<float> WallDistance, WallNormal, WallSum;
  DeviceBuffer<std::uint32_t> WallTriangle;
  StepMeasures* Pinned = nullptr; // Gpu.pinned
  CellSort Sort;
  mutable ParticleState Host;
  mutable bool HostFresh = false;
  bool Accumulating = false; // inside advance(): impulse sums p dt
  double Time = 0.0;
  std::int64_t Steps = 0;
  StepStatistics Last;
};
} // namespace parafluid::sph::cuda
