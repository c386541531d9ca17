#pragma once
// Internal to the CUDA backend: δ-SPH on the GPU as a Simulation. The state stays in GPU memory
// between steps and between outputs; hostState() copies it to the host when asked. Each step is
// the CPU's (DeltaSPHSolver::step) with the passes of DeltaSPHKernels.cuh.
#include "cuda/CellSort.cuh"
#include "cuda/DeltaSPHKernels.cuh"
#include "cuda/DeviceBuffer.h"
#include "cuda/DeviceMesh.cuh"
#include "cuda/SurfaceTensionKernels.cuh"
#include "parafluid/sph/Simulation.h"

#include <optional>

namespace parafluid::sph::cuda
{
class CudaDeltaSimulation final : public Simulation
{
public:
  /// `boundary` (may be null) is copied to the GPU; it need not outlive the simulation.
  CudaDeltaSimulation(const SPHParameters& parameters, ParticleState initial,
                      std::shared_ptr<const TriangleBoundary> boundary);

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

private:
  /// The GPU's bytes per particle, for the check before the arrays are made: 27 floats (the state,
  /// δ-SPH's arrays, the 6 of the gradient correction, the 3 of the push, a scratch), the id and
  /// index with their scratches, and the sort's keys and values, in and out (the cells' starts
  /// and the sort's scratch come on top, a few bytes a particle).
  static constexpr std::size_t kBytesPerParticle = 4 * 27 + (8 + 4) * 2 + (8 + 4) * 2;
  /// With a boundary mesh in the sums: each particle's distance, normal, triangle and wall sum.
  static constexpr std::size_t kMeshWallBytesPerParticle = 4 * 6;
  std::size_t bytesNeededPerParticle() const;
  /// Uploads `s` (and each particle's fullness and slow departure: NaN for none) and starts:
  /// sound speed, density (hydrostatic unless s has one), pressures and accelerations
  /// (DeltaSPHSolver::start).
  void start(ParticleState s, std::vector<float> fullness, std::vector<float> slow);
  /// start() with s, or, when that fails (the GPU's memory ran out part way), start() again from
  /// the state before (in the memory it had) and rethrow: a failed add or removal loses nothing.
  void restartKeeping(ParticleState s, std::vector<float> fullness, std::vector<float> slow,
                      std::vector<float> fullnessBefore, std::vector<float> slowBefore);
  void releaseArrays();
  double step(double remaining);
  /// Sorts the state by cell and finds each particle's mesh wall where it now is.
  void sortByCell();
  /// The accelerations of the state as it is: the force pass, then the surface tension.
  void accelerations();
  /// The measures of the state into Measures and Last (impulse += weight p first).
  void measure(float weight);
  void checkStep() const;
  DeltaArrays arrays() const;
  /// Host copies of each particle's fullness and slow departure, in hostState() order.
  void downloadSolverState(std::vector<float>& fullness, std::vector<float>& slow) const;

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
  delta::Constants K;
  cudaStream_t Stream = nullptr; // Gpu.stream
  std::uint32_t N = 0;
  DeviceBuffer<float> X, Y, Z, VX, VY, VZ, AX, AY, AZ, Rho, P, Rate, Fullness, NextFullness, Slow, Correction, Push,
    Interior, Impulse, Scratch;
  DeviceBuffer<std::int64_t> Id, IdScratch;
  DeviceBuffer<std::uint32_t> Index, IndexScratch;
  DeviceBuffer<StepMeasures> Partials, Result;
  DeviceMesh Mesh;                        // triangleCount 0: no boundary mesh
  bool MeshWall = false;                  // the mesh's wall is in the sums (SPHParameters::meshWallDensity)
  std::optional<AkinciConstants> Tension; // SPHParameters::surfaceTension > 0
  DeviceBuffer<float> WallDistance, WallNormal, WallSum;
  DeviceBuffer<std::uint32_t> WallTriangle;
  StepMeasures* Pinned = nullptr; // Gpu.pinned
  StepMeasures Measures{};
  CellSort Sort;
  DeviceGrid Grid{};
  mutable ParticleState Host;
  mutable bool HostFresh = false;
  bool Accumulating = false; // inside advance(): impulse sums p dt
  double SoundSpeed = 0.0, SlowDepartureTime = 0.0, SpeedLimit = 0.0, Time = 0.0;
  float Spacing = 0.0f, LaplacianCorrection = 1.0f, PressureCorrection = 1.0f;
  std::int64_t Steps = 0;
  StepStatistics Last;
};
} // namespace parafluid::sph::cuda
