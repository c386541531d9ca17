// δ-SPH on the GPU as a Simulation (see CudaDeltaSimulation.cuh).
#include "cuda/CudaDeltaSimulation.cuh"

#include "parafluid/sph/CudaBackend.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/InitialState.h"
#include "parafluid/sph/OutputFields.h"
#include "parafluid/sph/SolverRegistry.h"
#include "parafluid/sph/TimeStepControl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace parafluid::sph
{
namespace cuda
{
namespace
{
constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

template<class T>
void uploadTo(DeviceBuffer<T>& buffer, const std::vector<T>& values, cudaStream_t stream)
{
  buffer.upload(values.data(), values.size(), stream);
}
} // namespace

CudaDeltaSimulation::CudaDeltaSimulation(const SPHParameters& parameters, ParticleState initial,
                                         std::shared_ptr<const TriangleBoundary> boundary)
  : Parameters(parameters)
  , K(parameters.smoothingLength)
{
  const std::string problem = this->Parameters.validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("SPH: " + problem);
  }
  completeInitialState(initial);
  checkCoincident(initial);
  const SPHParameters& p = this->Parameters;
  this->SpeedLimit = sceneSpeedLimit(p, initial);
  this->Spacing = latticeSpacingForMass(p.particleMass, p.smoothingLength, p.restDensity, DensityKernel::WendlandC2);
  this->LaplacianCorrection =
    latticeMorrisLaplacianCorrection(this->Spacing, p.smoothingLength, DensityKernel::WendlandC2);
  this->PressureCorrection = latticeGradientCorrection(this->Spacing, p.smoothingLength, DensityKernel::WendlandC2);
  this->Walls.bounds = p.domainBounds;
  this->Walls.support = p.smoothingLength;
  this->Walls.noSlip = p.noSlipWalls();
  this->Walls.periodic = p.periodic;
  this->Walls.restitution = p.wallRestitution;
  this->Walls.damping = p.boundaryDamping;
  for (int a = 0; a < 3; ++a)
  {
    this->Walls.gravity[a] = p.gravity[a];
  }
  if (p.surfaceTension > 0.0f)
  {
    this->Tension = AkinciConstants{ detail::CohesionKernel(p.smoothingLength),
                                     WendlandC2Kernel(p.smoothingLength),
                                     p.particleMass,
                                     p.restDensity,
                                     detail::akinciGamma(p),
                                     p.surfaceTensionModel == SurfaceTensionModel::Akinci };
  }
  const bool mesh = boundary && boundary->triangleCount() > 0;
  this->MeshWall = mesh && p.meshWallDensity && solverEntry(PressureSolverType::DeltaSPH).meshWallInSums;
  requireDeviceMemory(initial.size() * this->bytesNeededPerParticle(), std::to_string(initial.size()) + " particles");
  this->Stream = this->Gpu.stream;
  if (mesh)
  {
    // The table of the wall's sums for this kernel and lattice (SPHSolver's, from the same code).
    const detail::MeshWallTable table(DensityKernel::WendlandC2, p.smoothingLength, this->Spacing);
    this->MeshWall = this->MeshWall && !table.empty();
    this->Mesh.upload(*boundary, this->MeshWall ? &table : nullptr, this->Stream);
    check(cudaStreamSynchronize(this->Stream), "copying the boundary mesh to the GPU"); // the table is on the stack
  }
  this->Pinned = this->Gpu.pinned;
  this->Partials.reserve(kMeasureBlocks);
  this->Result.reserve(1);
  const std::size_t n = initial.size();
  this->start(std::move(initial), std::vector<float>(n, 1.0f), std::vector<float>(n, kNone));
}

CudaDeltaSimulation::StreamAndPinned::StreamAndPinned()
{
  check(cudaStreamCreateWithFlags(&this->stream, cudaStreamNonBlocking), "creating a stream");
  const cudaError_t status = cudaMallocHost(&this->pinned, sizeof(StepMeasures));
  if (status != cudaSuccess)
  {
    cudaStreamDestroy(this->stream);
    check(status, "allocating page-locked memory");
  }
}

CudaDeltaSimulation::StreamAndPinned::~StreamAndPinned()
{
  cudaStreamSynchronize(this->stream);
  cudaStreamDestroy(this->stream);
  cudaFreeHost(this->pinned);
}

DeltaArrays CudaDeltaSimulation::arrays() const
{
  DeltaArrays a;
  a.n = this->N;
  a.x = this->X.data();
  a.y = this->Y.data();
  a.z = this->Z.data();
  a.vx = this->VX.data();
  a.vy = this->VY.data();
  a.vz = this->VZ.data();
  a.ax = this->AX.data();
  a.ay = this->AY.data();
  a.az = this->AZ.data();
  a.rho = this->Rho.data();
  a.p = this->P.data();
  a.rate = this->Rate.data();
  a.fullness = this->Fullness.data();
  a.nextFullness = this->NextFullness.data();
  a.slow = this->Slow.data();
  a.correction = this->Parameters.gradientCorrection ? this->Correction.data() : nullptr;
  a.push = this->Push.data();
  a.interior = this->Interior.data();
  a.impulse = this->Impulse.data();
  if (this->MeshWall)
  {
    a.wall.table = this->Mesh.table();
    a.wall.distance = this->WallDistance.data();
    a.wall.normal = this->WallNormal.data();
    a.wall.triangle = this->WallTriangle.data();
    a.wall.wallSum = this->WallSum.data();
  }
  return a;
}

void CudaDeltaSimulation::start(ParticleState s, std::vector<float> fullness, std::vector<float> slow)
{
  const SPHParameters& p = this->Parameters;
  const std::size_t n = s.size();
  if (n > std::numeric_limits<std::uint32_t>::max() / 2)
  {
    throw std::invalid_argument("SPH (CUDA): " + std::to_string(n) + " particles are more than this backend indexes");
  }
  this->N = static_cast<std::uint32_t>(n);
  this->HostFresh = false;
  const cudaStream_t stream = this->Stream;
  // Particles that start outside the box are reflected inside, as the walls would do (on the GPU,
  // as every later move is); the host's start below reads the positions after that.
  uploadTo(this->X, s.x, stream);
  uploadTo(this->Y, s.y, stream);
  uploadTo(this->Z, s.z, stream);
  uploadTo(this->VX, s.vx, stream);
  uploadTo(this->VY, s.vy, stream);
  uploadTo(this->VZ, s.vz, stream);
  launchDrift(this->arrays(), this->Walls, this->Mesh.view(), 0.0f, stream);
  for (auto [buffer, host] : { std::pair{ &this->X, &s.x },
                               { &this->Y, &s.y },
                               { &this->Z, &s.z },
                               { &this->VX, &s.vx },
                               { &this->VY, &s.vy },
                               { &this->VZ, &s.vz } })
  {
    buffer->download(host->data(), n, stream);
  }
  check(cudaStreamSynchronize(stream), "the start's moves");

  this->SoundSpeed = DeltaSPHSolver::automaticSoundSpeed(p, s);
  this->SlowDepartureTime = DeltaSPHSolver::slowDepartureTime(p, s);
  this->K =
    delta::makeConstants(p, this->SoundSpeed, this->Spacing, this->LaplacianCorrection, this->PressureCorrection);
  const bool given = !s.density.empty() && std::all_of(s.density.begin(), s.density.end(),
                                                       [](float rho) { return std::isfinite(rho) && rho > 0.0f; });
  if (!given)
  {
    s.density.assign(n, p.restDensity);
    DeltaSPHSolver::hydrostaticDensity(p, this->SoundSpeed, this->Spacing, s);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!std::isfinite(slow[i]) || !(this->SlowDepartureTime > 0.0))
    {
      slow[i] = this->SlowDepartureTime > 0.0 ? delta::departureFromHydrostatic(this->K, s, i) : 0.0f;
    }
  }
  uploadTo(this->Rho, s.density, stream);
  uploadTo(this->Fullness, fullness, stream);
  uploadTo(this->Slow, slow, stream);
  uploadTo(this->Id, s.id, stream);
  uploadTo(this->Index, s.originalIndex, stream);
  for (auto* buffer : { &this->AX, &this->AY, &this->AZ, &this->P, &this->Rate, &this->NextFullness, &this->Interior,
                        &this->Impulse, &this->Scratch })
  {
    buffer->reserve(n);
  }
  this->Push.reserve(3 * n);
  if (p.gradientCorrection)
  {
    this->Correction.reserve(6 * n);
  }
  this->IdScratch.reserve(n);
  this->IndexScratch.reserve(n);
  if (this->MeshWall)
  {
    for (auto* buffer : { &this->WallDistance, &this->WallSum })
    {
      buffer->reserve(n);
    }
    this->WallNormal.reserve(3 * n);
    this->WallTriangle.reserve(n);
    if (n > 0)
    {
      // No triangle hint: every particle's first search covers the whole reach.
      check(cudaMemsetAsync(this->WallTriangle.data(), 0xff, n * sizeof(std::uint32_t), stream), "clearing hints");
    }
  }
  const std::size_t bytes = n * sizeof(float);
  for (auto* buffer : { &this->AX, &this->AY, &this->AZ, &this->Rate, &this->Impulse })
  {
    if (bytes > 0)
    {
      check(cudaMemsetAsync(buffer->data(), 0, bytes, stream), "clearing an array");
    }
  }
  this->measure(0.0f); // the bounding box the first sort's grid covers
  this->sortByCell();
  if (this->MeshWall)
  {
    launchStartWallSums(this->arrays().wall, this->N, stream); // density counts from where each particle starts
  }
  const DeltaArrays a = this->arrays();
  const auto bulk = static_cast<float>(this->SoundSpeed * this->SoundSpeed * p.restDensity / delta::kGamma);
  launchIntegrateDensity(a, this->K, 0.0f, 0.0f, bulk, stream); // the pressure from the start's density
  launchContinuity(a, this->Grid, this->Walls, this->K, stream);
  this->Fullness.swap(this->NextFullness);
  this->accelerations();
  this->measure(0.0f);
}

void CudaDeltaSimulation::measure(float weight)
{
  launchMeasure(this->arrays(), this->Parameters.restDensity, weight, this->Partials.data(), this->Result.data(),
                this->Stream);
  check(cudaMemcpyAsync(this->Pinned, this->Result.data(), sizeof(StepMeasures), cudaMemcpyDeviceToHost, this->Stream),
        "reading the step's measures");
  check(cudaStreamSynchronize(this->Stream), "a step");
  this->Measures = *this->Pinned;
  const double n = this->N;
  this->Last.meanCompression = this->N > 0 ? this->Measures.compression / (n * this->Parameters.restDensity) : 0.0;
  this->Last.maxDensityRatio = static_cast<double>(this->Measures.densest) / this->Parameters.restDensity;
}

void CudaDeltaSimulation::sortByCell()
{
  const SPHParameters& p = this->Parameters;
  const float h = p.smoothingLength;
  const float half = 0.5f * h;
  this->Grid.reach = h;
  std::uint64_t cells = 1;
  for (int a = 0; a < 3; ++a)
  {
    const float lo = p.domainBounds[2 * a], hi = p.domainBounds[2 * a + 1];
    this->Grid.periodic[a] = p.periodic[a];
    if (p.periodic[a])
    {
      // Whole cells across the period, each at least half the support wide.
      const int count = std::max(5, static_cast<int>(std::floor((hi - lo) / half)));
      this->Grid.origin[a] = lo;
      this->Grid.cells[a] = count;
      this->Grid.cell[a] = (hi - lo) / static_cast<float>(count);
      this->Grid.period[a] = hi - lo;
    }
    else
    {
      // The particles' box at the last measure and a support's margin, inside the domain.
      const float from = this->N > 0 ? std::max(lo, this->Measures.lo[a] - h) : lo;
      const float to = this->N > 0 ? std::min(hi, this->Measures.hi[a] + h) : lo;
      this->Grid.origin[a] = from;
      this->Grid.cells[a] = 1 + static_cast<int>(std::floor(std::max(0.0f, to - from) / half));
      this->Grid.cell[a] = half;
      this->Grid.period[a] = 0.0f;
    }
    this->Grid.inverseCell[a] = 1.0f / this->Grid.cell[a];
    cells *= static_cast<std::uint64_t>(this->Grid.cells[a]);
  }
  if (cells >= (std::uint64_t{ 1 } << 31))
  {
    throw std::runtime_error(
      "SPH (CUDA): the particles span " + std::to_string(cells) +
      " cells of half a SmoothingLength, more than this backend's grid holds; choose Backend CPU");
  }
  const cudaStream_t stream = this->Stream;
  const std::uint32_t* order =
    this->Sort.sort(this->X.data(), this->Y.data(), this->Z.data(), this->Id.data(), this->N, this->Grid, stream);
  auto permute = [&](DeviceBuffer<float>& buffer)
  {
    launchGather(buffer.data(), this->Scratch.data(), order, this->N, stream);
    buffer.swap(this->Scratch);
  };
  for (auto* buffer :
       { &this->X, &this->Y, &this->Z, &this->VX, &this->VY, &this->VZ, &this->Rho, &this->Fullness, &this->Slow })
  {
    permute(*buffer);
  }
  if (this->Accumulating)
  {
    permute(this->Impulse);
  }
  launchGather(this->Id.data(), this->IdScratch.data(), order, this->N, stream);
  this->Id.swap(this->IdScratch);
  launchGather(this->Index.data(), this->IndexScratch.data(), order, this->N, stream);
  this->Index.swap(this->IndexScratch);
  if (this->MeshWall)
  {
    // Each particle's wall sum and last triangle (the next search's hint) go with it.
    permute(this->WallSum);
    launchGather(this->WallTriangle.data(), this->IndexScratch.data(), order, this->N, stream);
    this->WallTriangle.swap(this->IndexScratch);
    launchFindMeshWalls(this->X.data(), this->Y.data(), this->Z.data(), this->N, this->Mesh.view(), this->arrays().wall,
                        stream);
  }
}

void CudaDeltaSimulation::accelerations()
{
  const SPHParameters& p = this->Parameters;
  launchForces(this->arrays(), this->Grid, this->Walls, this->K, p.kinematicViscosity > 0.0f || p.viscosity > 0.0f,
               this->Stream);
  if (this->Tension)
  {
    launchAkinciTension(this->arrays(), this->Grid, *this->Tension, this->Stream);
  }
}

std::size_t CudaDeltaSimulation::bytesNeededPerParticle() const
{
  return kBytesPerParticle + (this->MeshWall ? kMeshWallBytesPerParticle : 0);
}

double CudaDeltaSimulation::proposedTimeStep() const
{
  return sph::proposedTimeStep(this->Parameters, solverEntry(PressureSolverType::DeltaSPH), this->SoundSpeed,
                               std::sqrt(static_cast<double>(this->Measures.fastestSquared)),
                               std::sqrt(static_cast<double>(this->Measures.largestAccelerationSquared)),
                               this->LaplacianCorrection);
}

double CudaDeltaSimulation::step(double remaining)
{
  // DeltaSPHSolver::step: kick, drift, sort, density (continuity), pressure, forces, kick.
  const SPHParameters& p = this->Parameters;
  const double dt = timeStepFor(p, this->proposedTimeStep(), remaining);
  const auto h = static_cast<float>(dt);
  const cudaStream_t stream = this->Stream;
  launchKick(this->arrays(), 0.5f * h, stream);
  launchDrift(this->arrays(), this->Walls, this->Mesh.view(), h, stream);
  this->sortByCell();
  if (p.particleShifting)
  {
    // As the CPU's step: shifted by the speeds of now, then sorted again (finding the mesh walls anew).
    launchMeasure(this->arrays(), p.restDensity, 0.0f, this->Partials.data(), this->Result.data(), stream);
    ShiftConstants shift;
    shift.inverseWSpacing = 1.0f / this->K.w.value(std::min(this->Spacing, 0.99f * p.smoothingLength));
    shift.volume = p.particleMass / p.restDensity;
    shift.limit = 0.2f * this->Spacing;
    shift.margin = 0.01f * this->Spacing;
    shift.twiceSupportDt = 2.0f * p.smoothingLength * h;
    launchShift(this->arrays(), this->Grid, this->Walls, this->K, shift, this->Result.data(), stream);
    this->sortByCell();
  }
  launchContinuity(this->arrays(), this->Grid, this->Walls, this->K, stream);
  this->Fullness.swap(this->NextFullness);
  const float follow = p.densityDiffusion > 0.0f && this->SlowDepartureTime > 0.0
                         ? static_cast<float>(std::min(1.0, h / this->SlowDepartureTime))
                         : 0.0f;
  const auto bulk = static_cast<float>(this->SoundSpeed * this->SoundSpeed * p.restDensity / delta::kGamma);
  launchIntegrateDensity(this->arrays(), this->K, h, follow, bulk, stream);
  this->accelerations();
  launchKick(this->arrays(), 0.5f * h, stream);
  if (p.wallFriction == WallFriction::LogLaw && h > 0.0f)
  {
    launchWallFriction(this->arrays(), detail::logLawWalls(p, this->Spacing), h, stream);
  }
  this->HostFresh = false;
  this->measure(this->Accumulating ? h : 0.0f);
  this->Last.timeStep = dt;
  this->Time += dt;
  ++this->Steps;
  this->checkStep();
  return dt;
}

void CudaDeltaSimulation::checkStep() const
{
  // SPHSolver's checks: non-finite values, a density twice rest, a speed beyond the scene's.
  if (this->Measures.nonFinite > 0)
  {
    throw std::runtime_error("SPH became unstable at step " + std::to_string(this->Steps) + " (" +
                             std::to_string(this->Measures.nonFinite) +
                             " particles with a non-finite position or velocity): " + this->stabilityAdvice());
  }
  if (this->Last.maxDensityRatio > 2.0)
  {
    throw std::runtime_error("SPH stopped at t = " + std::to_string(this->Time) + " s: the density reached " +
                             std::to_string(this->Last.maxDensityRatio) +
                             " x RestDensity (a liquid stays within a few percent): the run has blown up; " +
                             this->stabilityAdvice());
  }
  const double speed = std::sqrt(static_cast<double>(this->Measures.fastestSquared));
  if (speed > this->SpeedLimit)
  {
    throw std::runtime_error("SPH stopped at t = " + std::to_string(this->Time) + " s: a particle moves at " +
                             std::to_string(speed) + " m/s, more than the " + std::to_string(this->SpeedLimit) +
                             " m/s this scene allows: the run has blown up; " + this->stabilityAdvice());
  }
}

std::int64_t CudaDeltaSimulation::advance(double duration, const std::function<bool(double)>& progress)
{
  checkAdvanceDuration(duration);
  const double begin = this->Time;
  if (this->N > 0)
  {
    check(cudaMemsetAsync(this->Impulse.data(), 0, this->N * sizeof(float), this->Stream), "clearing the impulse");
  }
  this->Accumulating = true;
  struct StopAccumulating
  {
    bool& flag;
    ~StopAccumulating() { flag = false; }
  } stop{ this->Accumulating };
  const std::int64_t taken = advanceInSteps(
    this->Parameters, this->Time, duration, [this](double remaining) { return this->step(remaining); }, progress,
    [this] { return this->stabilityAdvice(); });
  const double elapsed = this->Time - begin;
  if (elapsed > 0.0)
  {
    launchMeanPressure(this->arrays(), static_cast<float>(1.0 / elapsed), this->Stream);
    this->HostFresh = false;
  }
  return taken;
}

const ParticleState& CudaDeltaSimulation::hostState() const
{
  if (this->HostFresh)
  {
    return this->Host;
  }
  ParticleState& s = this->Host;
  const std::size_t n = this->N;
  s.resize(n);
  s.density.resize(n);
  s.pressure.resize(n);
  const cudaStream_t stream = this->Stream;
  for (auto [buffer, host] : { std::pair{ &this->X, &s.x },
                               { &this->Y, &s.y },
                               { &this->Z, &s.z },
                               { &this->VX, &s.vx },
                               { &this->VY, &s.vy },
                               { &this->VZ, &s.vz },
                               { &this->AX, &s.ax },
                               { &this->AY, &s.ay },
                               { &this->AZ, &s.az },
                               { &this->Rho, &s.density },
                               { &this->P, &s.pressure } })
  {
    buffer->download(host->data(), n, stream);
  }
  this->Id.download(s.id.data(), n, stream);
  this->Index.download(s.originalIndex.data(), n, stream);
  check(cudaStreamSynchronize(stream), "copying the state from the GPU");
  this->HostFresh = true;
  return s;
}

void CudaDeltaSimulation::downloadSolverState(std::vector<float>& fullness, std::vector<float>& slow) const
{
  fullness.resize(this->N);
  slow.resize(this->N);
  this->Fullness.download(fullness.data(), this->N, this->Stream);
  this->Slow.download(slow.data(), this->N, this->Stream);
  check(cudaStreamSynchronize(this->Stream), "copying the solver's state from the GPU");
}

void CudaDeltaSimulation::addParticles(const std::vector<float>& x, const std::vector<float>& y,
                                       const std::vector<float>& z, const std::vector<float>& vx,
                                       const std::vector<float>& vy, const std::vector<float>& vz)
{
  if (x.empty())
  {
    appendParticles(this->Host, x, y, z, vx, vy, vz, this->Parameters.restDensity); // checks the sizes
    return;
  }
  requireDeviceMemory(x.size() * this->bytesNeededPerParticle(), std::to_string(x.size()) + " more particles");
  ParticleState s = this->hostState();
  std::vector<float> fullness, slow;
  this->downloadSolverState(fullness, slow);
  const std::size_t n = s.size();
  const std::size_t added = appendParticles(s, x, y, z, vx, vy, vz, this->Parameters.restDensity);
  // Added particles have full neighbourhoods until the next continuity pass says otherwise, and a
  // slow departure that the start takes from where they are (DeltaSPHSolver::resize).
  std::vector<float> fullnessBefore(fullness.begin(), fullness.begin() + n), slowBefore(slow.begin(), slow.begin() + n);
  fullness.resize(n + added, 1.0f);
  slow.resize(n + added, kNone);
  this->restartKeeping(std::move(s), std::move(fullness), std::move(slow), std::move(fullnessBefore),
                       std::move(slowBefore));
}

void CudaDeltaSimulation::restartKeeping(ParticleState s, std::vector<float> fullness, std::vector<float> slow,
                                         std::vector<float> fullnessBefore, std::vector<float> slowBefore)
{
  // The state before, from the host copy (the GPU's arrays are remade on a restart).
  ParticleState before = this->hostState();
  try
  {
    this->start(std::move(s), std::move(fullness), std::move(slow));
  }
  catch (const std::exception&)
  {
    // The GPU ran out of memory (or failed) part way: the simulation goes on from where it was,
    // in the memory it had, and the caller hears why the change failed.
    this->releaseArrays();
    this->start(std::move(before), std::move(fullnessBefore), std::move(slowBefore));
    throw;
  }
}

void CudaDeltaSimulation::releaseArrays()
{
  for (auto* buffer : { &this->X,
                        &this->Y,
                        &this->Z,
                        &this->VX,
                        &this->VY,
                        &this->VZ,
                        &this->AX,
                        &this->AY,
                        &this->AZ,
                        &this->Rho,
                        &this->P,
                        &this->Rate,
                        &this->Fullness,
                        &this->NextFullness,
                        &this->Slow,
                        &this->Correction,
                        &this->Push,
                        &this->Interior,
                        &this->Impulse,
                        &this->Scratch,
                        &this->WallDistance,
                        &this->WallNormal,
                        &this->WallSum })
  {
    buffer->release();
  }
  this->Id.release();
  this->IdScratch.release();
  this->Index.release();
  this->IndexScratch.release();
  this->WallTriangle.release();
}

std::size_t CudaDeltaSimulation::removeParticles(const std::vector<std::uint8_t>& remove)
{
  const ParticleState& s = this->hostState();
  const std::size_t n = s.size();
  if (remove.size() != n)
  {
    throw std::invalid_argument("SPH: removeParticles needs one flag per particle");
  }
  ParticleState kept;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (remove[i])
    {
      continue;
    }
    for (auto [from, to] : { std::pair{ &s.x, &kept.x },
                             { &s.y, &kept.y },
                             { &s.z, &kept.z },
                             { &s.vx, &kept.vx },
                             { &s.vy, &kept.vy },
                             { &s.vz, &kept.vz },
                             { &s.ax, &kept.ax },
                             { &s.ay, &kept.ay },
                             { &s.az, &kept.az },
                             { &s.density, &kept.density },
                             { &s.pressure, &kept.pressure } })
    {
      to->push_back((*from)[i]);
    }
    kept.id.push_back(s.id[i]);
    kept.originalIndex.push_back(s.originalIndex[i]);
  }
  const std::size_t removed = n - kept.size();
  if (removed == 0)
  {
    return 0;
  }
  // As the CPU's restart after a removal: every neighbourhood counts as full, every slow
  // departure starts where the particle is.
  std::vector<float> fullnessBefore, slowBefore;
  this->downloadSolverState(fullnessBefore, slowBefore);
  const std::size_t m = kept.size();
  this->restartKeeping(std::move(kept), std::vector<float>(m, 1.0f), std::vector<float>(m, kNone),
                       std::move(fullnessBefore), std::move(slowBefore));
  return removed;
}

std::vector<float> CudaDeltaSimulation::smoothedPressure() const
{
  return sph::smoothedPressure(this->Parameters, this->hostState());
}

std::vector<std::uint32_t> CudaDeltaSimulation::neighbourCounts() const
{
  return sph::neighbourCounts(this->Parameters, this->hostState());
}

double CudaDeltaSimulation::kineticEnergy() const
{
  return 0.5 * this->Parameters.particleMass * this->Measures.speedSquaredSum;
}

double CudaDeltaSimulation::bytesPerParticle() const
{
  if (this->N == 0)
  {
    return 0.0;
  }
  std::size_t total = this->Sort.bytes() + this->Id.bytes() + this->IdScratch.bytes() + this->Index.bytes() +
                      this->IndexScratch.bytes() + this->Mesh.bytes() + this->WallDistance.bytes() +
                      this->WallNormal.bytes() + this->WallSum.bytes() + this->WallTriangle.bytes();
  for (const auto* buffer : { &this->X,          &this->Y,    &this->Z,        &this->VX,           &this->VY,
                              &this->VZ,         &this->AX,   &this->AY,       &this->AZ,           &this->Rho,
                              &this->P,          &this->Rate, &this->Fullness, &this->NextFullness, &this->Slow,
                              &this->Correction, &this->Push, &this->Interior, &this->Impulse,      &this->Scratch })
  {
    total += buffer->bytes();
  }
  return static_cast<double>(total) / this->N;
}

std::string CudaDeltaSimulation::stabilityAdvice() const
{
  return solverEntry(PressureSolverType::DeltaSPH).stabilityAdvice(this->Parameters.adaptiveTimeStep);
}
} // namespace cuda

std::unique_ptr<Simulation> makeCudaSimulation(const SPHParameters& parameters, ParticleState initial,
                                               std::shared_ptr<const TriangleBoundary> boundary)
{
  std::string reason;
  if (!cudaBackendUsable(&reason))
  {
    throw std::invalid_argument("SPH: Backend CUDA: " + reason + "; choose Backend CPU or Automatic");
  }
  const std::string lacking = cudaBackendLacks(parameters);
  if (!lacking.empty())
  {
    throw std::invalid_argument("SPH: Backend CUDA does not run " + lacking + " yet; choose Backend CPU");
  }
  return std::make_unique<cuda::CudaDeltaSimulation>(parameters, std::move(initial), std::move(boundary));
}
} // namespace parafluid::sph
