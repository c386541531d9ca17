// What every solver's Simulation on the GPU shares (see CudaSimulation.cuh).
#include "cuda/CudaSimulation.cuh"

#include "parafluid/sph/InitialState.h"
#include "parafluid/sph/OutputFields.h"
#include "parafluid/sph/SolverRegistry.h"
#include "parafluid/sph/TimeStepControl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace parafluid::sph::cuda
{
namespace
{
template<class T>
void uploadTo(DeviceBuffer<T>& buffer, const std::vector<T>& values, cudaStream_t stream)
{
  buffer.upload(values.data(), values.size(), stream);
}
} // namespace

CudaSimulation::CudaSimulation(const SPHParameters& parameters, ParticleState& initial,
                               std::shared_ptr<const TriangleBoundary> boundary, std::size_t solverBytesPerParticle)
  : Parameters(parameters)
  , SolverBytesPerParticle(solverBytesPerParticle)
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
  this->Spacing = latticeSpacingForMass(p.particleMass, p.smoothingLength, p.restDensity, p.densityKernel());
  this->LaplacianCorrection = latticeViscousCorrection(p, this->Spacing);
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
  const bool mesh = boundary && boundary->triangleCount() > 0;
  this->MeshWall = mesh && p.meshWallDensity && solverEntry(p.pressureSolver).meshWallInSums;
  requireDeviceMemory(initial.size() * this->bytesNeededPerParticle(), std::to_string(initial.size()) + " particles");
  this->Stream = this->Gpu.stream;
  if (mesh)
  {
    // The table of the wall's sums for this kernel and lattice (SPHSolver's, from the same code).
    const detail::MeshWallTable table(p.densityKernel(), p.smoothingLength, this->Spacing);
    this->MeshWall = this->MeshWall && !table.empty();
    this->Mesh.upload(*boundary, this->MeshWall ? &table : nullptr, this->Stream);
    check(cudaStreamSynchronize(this->Stream), "copying the boundary mesh to the GPU"); // the table is on the stack
  }
  this->Pinned = this->Gpu.pinned;
  this->Partials.reserve(kMeasureBlocks);
  this->Result.reserve(1);
}

void CudaSimulation::begin(ParticleState initial)
{
  const std::size_t n = initial.size();
  Columns columns;
  for (float value : this->newParticleColumns())
  {
    columns.emplace_back(n, value);
  }
  this->start(std::move(initial), std::move(columns));
}

CudaSimulation::StreamAndPinned::StreamAndPinned()
{
  check(cudaStreamCreateWithFlags(&this->stream, cudaStreamNonBlocking), "creating a stream");
  const cudaError_t status = cudaMallocHost(&this->pinned, sizeof(StepMeasures));
  if (status != cudaSuccess)
  {
    cudaStreamDestroy(this->stream);
    check(status, "allocating page-locked memory");
  }
}

CudaSimulation::StreamAndPinned::~StreamAndPinned()
{
  cudaStreamSynchronize(this->stream);
  cudaStreamDestroy(this->stream);
  cudaFreeHost(this->pinned);
}

DeviceState CudaSimulation::state() const
{
  DeviceState a;
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

void CudaSimulation::start(ParticleState s, Columns columns)
{
  const std::size_t n = s.size();
  if (n > std::numeric_limits<std::uint32_t>::max() / 2)
  {
    throw std::invalid_argument("SPH (CUDA): " + std::to_string(n) + " particles are more than this backend indexes");
  }
  this->N = static_cast<std::uint32_t>(n);
  this->HostFresh = false;
  const cudaStream_t stream = this->Stream;
  // Particles that start outside the box are reflected inside, as the walls would do (on the GPU,
  // as every later move is); the host's part of the start reads the positions after that.
  uploadTo(this->X, s.x, stream);
  uploadTo(this->Y, s.y, stream);
  uploadTo(this->Z, s.z, stream);
  uploadTo(this->VX, s.vx, stream);
  uploadTo(this->VY, s.vy, stream);
  uploadTo(this->VZ, s.vz, stream);
  this->drift(0.0f);
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
  this->prepare(s, columns);
  if (s.density.size() != n)
  {
    throw std::logic_error("SPH (CUDA): the solver's start gave no density");
  }
  uploadTo(this->Rho, s.density, stream);
  uploadTo(this->Id, s.id, stream);
  uploadTo(this->Index, s.originalIndex, stream);
  for (auto* buffer : { &this->AX, &this->AY, &this->AZ, &this->P, &this->Impulse, &this->Scratch })
  {
    buffer->reserve(n);
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
  if (n > 0)
  {
    for (auto* buffer : { &this->AX, &this->AY, &this->AZ, &this->Impulse })
    {
      check(cudaMemsetAsync(buffer->data(), 0, n * sizeof(float), stream), "clearing an array");
    }
  }
  this->measure(0.0f); // the bounding box the first sort's grid covers
  this->sortByCell();
  this->startPasses();
  this->measure(0.0f);
}

void CudaSimulation::measure(float weight)
{
  launchMeasure(this->state(), this->Parameters.restDensity, weight, this->Partials.data(), this->Result.data(),
                this->Stream);
  check(cudaMemcpyAsync(this->Pinned, this->Result.data(), sizeof(StepMeasures), cudaMemcpyDeviceToHost, this->Stream),
        "reading the step's measures");
  check(cudaStreamSynchronize(this->Stream), "a step");
  this->Measures = *this->Pinned;
  const double n = this->N;
  this->Last.meanCompression = this->N > 0 ? this->Measures.compression / (n * this->Parameters.restDensity) : 0.0;
  this->Last.maxDensityRatio = static_cast<double>(this->Measures.densest) / this->Parameters.restDensity;
}

void CudaSimulation::kick(float dt)
{
  launchKick(this->state(), dt, this->Stream);
}

void CudaSimulation::drift(float dt)
{
  launchDrift(this->state(), this->Walls, this->Mesh.view(), dt, this->Stream);
}

void CudaSimulation::applyWallFriction(float dt)
{
  if (this->Parameters.wallFriction == WallFriction::LogLaw && dt > 0.0f)
  {
    launchWallFriction(this->state(), detail::logLawWalls(this->Parameters, this->Spacing), dt, this->Stream);
  }
}

void CudaSimulation::permute(DeviceBuffer<float>& buffer, const std::uint32_t* order)
{
  launchGather(buffer.data(), this->Scratch.data(), order, this->N, this->Stream);
  buffer.swap(this->Scratch);
}

void CudaSimulation::sortByCell()
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
  for (auto* buffer : { &this->X, &this->Y, &this->Z, &this->VX, &this->VY, &this->VZ, &this->Rho })
  {
    this->permute(*buffer, order);
  }
  for (auto* buffer : this->sortedSolverArrays())
  {
    this->permute(*buffer, order);
  }
  if (this->Accumulating)
  {
    this->permute(this->Impulse, order);
  }
  launchGather(this->Id.data(), this->IdScratch.data(), order, this->N, stream);
  this->Id.swap(this->IdScratch);
  launchGather(this->Index.data(), this->IndexScratch.data(), order, this->N, stream);
  this->Index.swap(this->IndexScratch);
  if (this->MeshWall)
  {
    // Each particle's wall sum and last triangle (the next search's hint) go with it.
    this->permute(this->WallSum, order);
    launchGather(this->WallTriangle.data(), this->IndexScratch.data(), order, this->N, stream);
    this->WallTriangle.swap(this->IndexScratch);
    launchFindMeshWalls(this->X.data(), this->Y.data(), this->Z.data(), this->N, this->Mesh.view(), this->state().wall,
                        stream);
  }
}

std::size_t CudaSimulation::bytesNeededPerParticle() const
{
  return kStateBytesPerParticle + this->SolverBytesPerParticle + (this->MeshWall ? kMeshWallBytesPerParticle : 0);
}

double CudaSimulation::proposedTimeStep() const
{
  return sph::proposedTimeStep(this->Parameters, solverEntry(this->Parameters.pressureSolver), this->signalSpeed(),
                               std::sqrt(static_cast<double>(this->Measures.fastestSquared)),
                               std::sqrt(static_cast<double>(this->Measures.largestAccelerationSquared)),
                               this->LaplacianCorrection);
}

double CudaSimulation::step(double remaining)
{
  const double dt = this->stepPasses(remaining);
  this->HostFresh = false;
  this->measure(this->Accumulating ? static_cast<float>(dt) : 0.0f);
  this->Last.timeStep = dt;
  this->Time += dt;
  ++this->Steps;
  this->checkStep();
  return dt;
}

void CudaSimulation::checkStep() const
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

std::int64_t CudaSimulation::advance(double duration, const std::function<bool(double)>& progress)
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
    launchMeanPressure(this->state(), static_cast<float>(1.0 / elapsed), this->Stream);
    this->HostFresh = false;
  }
  return taken;
}

const ParticleState& CudaSimulation::hostState() const
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

void CudaSimulation::addParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                                  const std::vector<float>& vx, const std::vector<float>& vy,
                                  const std::vector<float>& vz)
{
  if (x.empty())
  {
    appendParticles(this->Host, x, y, z, vx, vy, vz, this->Parameters.restDensity); // checks the sizes
    return;
  }
  requireDeviceMemory(x.size() * this->bytesNeededPerParticle(), std::to_string(x.size()) + " more particles");
  ParticleState s = this->hostState();
  Columns columns = this->downloadColumns();
  Columns before = columns;
  const std::size_t added = appendParticles(s, x, y, z, vx, vy, vz, this->Parameters.restDensity);
  // Added particles get each column's value for new ones (SPHSolver::addParticles's resize).
  const std::vector<float> fresh = this->newParticleColumns();
  for (std::size_t c = 0; c < columns.size(); ++c)
  {
    columns[c].resize(columns[c].size() + added, fresh[c]);
  }
  this->restartKeeping(std::move(s), std::move(columns), std::move(before));
}

void CudaSimulation::restartKeeping(ParticleState s, Columns columns, Columns columnsBefore)
{
  // The state before, from the host copy (the GPU's arrays are remade on a restart).
  ParticleState before = this->hostState();
  try
  {
    this->start(std::move(s), std::move(columns));
  }
  catch (const std::exception&)
  {
    // The GPU ran out of memory (or failed) part way: the simulation goes on from where it was,
    // in the memory it had, and the caller hears why the change failed.
    this->releaseArrays();
    this->start(std::move(before), std::move(columnsBefore));
    throw;
  }
}

template<class F, class G>
void CudaSimulation::forEachArray(F&& f, G&& g)
{
  for (auto* buffer :
       { &this->X, &this->Y, &this->Z, &this->VX, &this->VY, &this->VZ, &this->AX, &this->AY, &this->AZ, &this->Rho,
         &this->P, &this->Impulse, &this->Scratch, &this->WallDistance, &this->WallNormal, &this->WallSum })
  {
    f(*buffer);
  }
  for (auto* buffer : this->solverArrays())
  {
    f(*buffer);
  }
  g(this->Id);
  g(this->IdScratch);
  g(this->Index);
  g(this->IndexScratch);
  g(this->WallTriangle);
}

void CudaSimulation::releaseArrays()
{
  const auto release = [](auto& buffer) { buffer.release(); };
  this->forEachArray(release, release);
}

std::size_t CudaSimulation::removeParticles(const std::vector<std::uint8_t>& remove)
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
  // As the CPU's restart after a removal: every column starts anew (δ-SPH: every neighbourhood
  // counts as full, every slow departure starts where the particle is).
  Columns before = this->downloadColumns();
  Columns columns;
  for (float value : this->newParticleColumns())
  {
    columns.emplace_back(kept.size(), value);
  }
  this->restartKeeping(std::move(kept), std::move(columns), std::move(before));
  return removed;
}

std::vector<float> CudaSimulation::smoothedPressure() const
{
  return sph::smoothedPressure(this->Parameters, this->hostState());
}

std::vector<std::uint32_t> CudaSimulation::neighbourCounts() const
{
  return sph::neighbourCounts(this->Parameters, this->hostState());
}

double CudaSimulation::kineticEnergy() const
{
  return 0.5 * this->Parameters.particleMass * this->Measures.speedSquaredSum;
}

double CudaSimulation::bytesPerParticle() const
{
  if (this->N == 0)
  {
    return 0.0;
  }
  std::size_t total = this->Sort.bytes() + this->Mesh.bytes();
  const auto add = [&total](const auto& buffer) { total += buffer.bytes(); };
  // forEachArray only reads here; it is not const because a restart's release goes through it too.
  const_cast<CudaSimulation*>(this)->forEachArray(add, add);
  return static_cast<double>(total) / this->N;
}

std::string CudaSimulation::stabilityAdvice() const
{
  return solverEntry(this->Parameters.pressureSolver).stabilityAdvice(this->Parameters.adaptiveTimeStep);
}
} // namespace parafluid::sph::cuda
