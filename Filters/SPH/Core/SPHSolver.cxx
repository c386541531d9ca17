#include "parafluid/sph/SPHSolver.h"

#include "parafluid/sph/InitialState.h"

#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/SolverRegistry.h"
#include "parafluid/sph/TimeStepControl.h"
#include "private/MeshWall.h"
#include "private/NeighbourCandidates.h"
#include "private/OutputFields.h"
#include "private/ParticleDrift.h"
#include "private/SimulationParts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

namespace parafluid::sph
{
using detail::permute;
using detail::threadCount;

SPHSolver::SPHSolver(const SPHParameters& parameters, ParticleState initial,
                     std::shared_ptr<const TriangleBoundary> boundary)
  : SPHSolver(parameters, std::move(initial), std::move(boundary), nullptr)
{
}

SPHSolver::SPHSolver(const SPHParameters& parameters, ParticleState initial,
                     std::shared_ptr<const TriangleBoundary> boundary, GhostLayer* ghosts)
  : Ghosts(ghosts)
  , Parameters(parameters)
  , State(std::move(initial))
  , Boundary(std::move(boundary))
{
  const std::string problem = this->Parameters.validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("SPH: " + problem);
  }
  completeInitialState(this->State);
  checkCoincident(this->State);
  this->SpeedLimit = this->globalMax(sceneSpeedLimit(this->Parameters, this->State));
  // Particles that start outside the domain are reflected inside, as the walls would do.
  this->drift(0.0f);
  this->sortByCell();
  const SPHParameters& p = this->Parameters;
  this->ParticleSpacing = latticeSpacingForMass(p.particleMass, p.smoothingLength, p.restDensity, p.densityKernel());
  const SolverEntry& solver = solverEntry(p.pressureSolver);
  this->LaplacianCorrection = latticeViscousCorrection(p, this->ParticleSpacing);
  this->SpikyGradientCorrection = latticeSpikyGradientCorrection(this->ParticleSpacing, p.smoothingLength);
  if (this->Boundary && this->Boundary->triangleCount() > 0 && p.meshWallDensity && solver.meshWallInSums)
  {
    this->Wall = std::make_unique<detail::MeshWall>();
    this->Wall->table = detail::MeshWallTable(p.densityKernel(), p.smoothingLength, this->ParticleSpacing);
    this->findMeshWalls();
  }
  this->Pressure = solver.create();
  {
    SimulationParts parts(*this);
    this->Pressure->start(parts);
  }
  this->measureCompression();
}

SPHSolver::~SPHSolver() = default;
SPHSolver::SPHSolver(SPHSolver&&) noexcept = default;
SPHSolver& SPHSolver::operator=(SPHSolver&&) noexcept = default;

std::int64_t SPHSolver::advance(double duration, const std::function<bool(double)>& progress)
{
  checkAdvanceDuration(duration);
  const double begin = this->Time;
  this->beginPressureMean();
  const std::int64_t taken = advanceInSteps(
    this->Parameters, this->Time, duration,
    [&](double remaining)
    {
      const double dt = this->step(remaining);
      this->addToPressureMean(dt);
      return dt;
    },
    progress, [this] { return this->stabilityAdvice(); });
  this->endPressureMean(this->Time - begin);
  return taken;
}

void SPHSolver::beginPressureMean()
{
  this->PressureImpulse.assign(this->State.size(), 0.0f);
  this->AveragingPressure = true;
}

void SPHSolver::addToPressureMean(double dt)
{
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  const auto weight = static_cast<float>(dt);
#pragma omp parallel for schedule(static) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    this->PressureImpulse[i] += weight * s.pressure[i];
  }
}

void SPHSolver::endPressureMean(double elapsed)
{
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  if (elapsed > 0.0)
  {
    const auto scale = static_cast<float>(1.0 / elapsed);
#pragma omp parallel for schedule(static) num_threads(threadCount(this->Parameters))
    for (std::int64_t i = 0; i < n; ++i)
    {
      s.pressure[i] = scale * this->PressureImpulse[i];
    }
  }
  this->PressureImpulse.clear(); // step() on its own leaves each step's pressure
  this->AveragingPressure = false;
}

double SPHSolver::step(double maxStep)
{
  try
  {
    SimulationParts parts(*this);
    this->Pressure->step(parts, maxStep);
  }
  catch (const std::invalid_argument&)
  {
    // The neighbour grid refuses non-finite positions: the step blew up before the check below.
    throw std::runtime_error("SPH became unstable at step " + std::to_string(this->Steps) +
                             " (non-finite positions): " + this->stabilityAdvice());
  }
  ++this->Steps;
  this->checkFinite();
  this->measureCompression();
  this->checkPhysical();
  return this->Last.timeStep;
}

void SPHSolver::addParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                             const std::vector<float>& vx, const std::vector<float>& vy, const std::vector<float>& vz)
{
  if (this->appendParticles(x, y, z, vx, vy, vz) == 0)
  {
    return;
  }
  this->sortByCell();
  this->restartPressure();
}

std::size_t SPHSolver::appendParticles(const std::vector<float>& x, const std::vector<float>& y,
                                       const std::vector<float>& z, const std::vector<float>& vx,
                                       const std::vector<float>& vy, const std::vector<float>& vz)
{
  ParticleState& s = this->State;
  const std::size_t n = s.size();
  const std::size_t added = sph::appendParticles(s, x, y, z, vx, vy, vz, this->Parameters.restDensity);
  if (added > 0)
  {
    if (this->AveragingPressure)
    {
      this->PressureImpulse.resize(n + added, 0.0f);
    }
    this->Pressure->resize(n + added);
    this->drift(0.0f); // inside the walls
  }
  return added;
}

void SPHSolver::numberParticles(std::size_t from, std::int64_t firstId, std::uint32_t firstIndex)
{
  ParticleState& s = this->State;
  for (std::size_t i = from; i < s.size(); ++i)
  {
    s.id[i] = firstId + static_cast<std::int64_t>(i - from);
    s.originalIndex[i] = firstIndex + static_cast<std::uint32_t>(i - from);
  }
}

void SPHSolver::restartPressure()
{
  SimulationParts parts(*this);
  this->Pressure->restart(parts);
}

void SPHSolver::startPressure()
{
  SimulationParts parts(*this);
  this->Pressure->start(parts);
}

std::size_t SPHSolver::removeParticles(const std::vector<std::uint8_t>& remove)
{
  ParticleState& s = this->State;
  const std::size_t n = s.size();
  if (remove.size() != n)
  {
    throw std::invalid_argument("SPH: removeParticles needs one flag per particle");
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (remove[i])
    {
      continue;
    }
    if (kept != i)
    {
      for (auto* a : { &s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.ax, &s.ay, &s.az, &s.density, &s.pressure })
      {
        (*a)[kept] = (*a)[i];
      }
      s.id[kept] = s.id[i];
      s.originalIndex[kept] = s.originalIndex[i];
      if (this->PressureImpulse.size() == n)
      {
        this->PressureImpulse[kept] = this->PressureImpulse[i];
      }
    }
    ++kept;
  }
  if (kept == n)
  {
    return 0;
  }
  for (auto* a : { &s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.ax, &s.ay, &s.az, &s.density, &s.pressure })
  {
    a->resize(kept);
  }
  s.id.resize(kept);
  s.originalIndex.resize(kept);
  if (this->PressureImpulse.size() == n)
  {
    this->PressureImpulse.resize(kept);
  }
  this->sortByCell();
  this->startPressure();
  return n - kept;
}

void SPHSolver::sortState()
{
  // sortByCell leaves behind what the step recomputes after it (accelerations, WCSPH's density and
  // pressure); between steps these are state, so they move with their particles here.
  ParticleState& s = this->State;
  std::vector<float>* kept[] = { &s.ax, &s.ay, &s.az, &s.density, &s.pressure };
  std::vector<std::vector<float>> before;
  for (std::vector<float>* column : kept)
  {
    before.push_back(*column);
  }
  this->sortByCell();
  const std::vector<std::uint32_t>& order = this->Grid.sortedOrder();
  for (std::size_t c = 0; c < before.size(); ++c)
  {
    std::vector<float>& column = *kept[c];
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      column[k] = before[c][order[k]];
    }
  }
}

std::size_t SPHSolver::ownCount() const
{
  const std::uint8_t* ghost = this->ghostFlags();
  const std::size_t n = this->State.size();
  return ghost ? n - static_cast<std::size_t>(std::count(ghost, ghost + n, std::uint8_t(1))) : n;
}

std::vector<std::vector<float>*> SPHSolver::carriedColumns()
{
  ParticleState& s = this->State;
  std::vector<std::vector<float>*> columns = { &s.x,  &s.y,  &s.z,  &s.vx,      &s.vy,      &s.vz,
                                               &s.ax, &s.ay, &s.az, &s.density, &s.pressure };
  for (std::vector<float>* c : this->Pressure->carried())
  {
    columns.push_back(c);
  }
  if (this->AveragingPressure)
  {
    columns.push_back(&this->PressureImpulse);
  }
  return columns;
}

ParticleRows SPHSolver::takeRows(const std::vector<std::uint8_t>& take)
{
  ParticleState& s = this->State;
  const std::size_t n = s.size();
  if (take.size() != n)
  {
    throw std::invalid_argument("SPH: takeRows needs one flag per particle");
  }
  ParticleRows rows;
  const std::vector<std::vector<float>*> columns = this->carriedColumns();
  rows.columns.resize(columns.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (take[i])
    {
      for (std::size_t c = 0; c < columns.size(); ++c)
      {
        rows.columns[c].push_back((*columns[c])[i]);
      }
      rows.id.push_back(s.id[i]);
      rows.originalIndex.push_back(s.originalIndex[i]);
      continue;
    }
    for (std::vector<float>* column : columns)
    {
      (*column)[kept] = (*column)[i];
    }
    s.id[kept] = s.id[i];
    s.originalIndex[kept] = s.originalIndex[i];
    ++kept;
  }
  for (std::vector<float>* column : columns)
  {
    column->resize(kept);
  }
  s.id.resize(kept);
  s.originalIndex.resize(kept);
  this->Pressure->resize(kept);
  if (this->Wall)
  {
    this->Wall->contacts.triangle.clear(); // the next search starts without hints
  }
  return rows;
}

void SPHSolver::appendRows(const ParticleRows& rows)
{
  const std::vector<std::vector<float>*> columns = this->carriedColumns();
  if (rows.columns.size() != columns.size())
  {
    throw std::invalid_argument("SPH: appendRows got " + std::to_string(rows.columns.size()) + " columns, not " +
                                std::to_string(columns.size()));
  }
  ParticleState& s = this->State;
  for (std::size_t c = 0; c < columns.size(); ++c)
  {
    columns[c]->insert(columns[c]->end(), rows.columns[c].begin(), rows.columns[c].end());
  }
  s.id.insert(s.id.end(), rows.id.begin(), rows.id.end());
  s.originalIndex.insert(s.originalIndex.end(), rows.originalIndex.begin(), rows.originalIndex.end());
  // The solver's other arrays are summed afresh in the next step.
  this->Pressure->resize(s.size());
  if (this->Wall)
  {
    this->Wall->contacts.triangle.clear();
  }
}

double SPHSolver::largestLength(const std::vector<float>& x, const std::vector<float>& y,
                                const std::vector<float>& z) const
{
  const auto n = static_cast<std::int64_t>(x.size());
  const std::uint8_t* ghost = this->ghostFlags();
  float l2 = 0.0f;
#pragma omp parallel for schedule(static) reduction(max : l2) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const float length2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    l2 = ghost && ghost[i] ? l2 : std::max(l2, length2);
  }
  return this->globalMax(std::sqrt(static_cast<double>(l2)));
}

double SPHSolver::maxAcceleration() const
{
  return this->largestLength(this->State.ax, this->State.ay, this->State.az);
}

double SPHSolver::proposedTimeStep() const
{
  if (!this->Parameters.adaptiveTimeStep)
  {
    return this->Parameters.timeStep;
  }
  const ParticleState& s = this->State;
  return sph::proposedTimeStep(this->Parameters, solverEntry(this->Parameters.pressureSolver),
                               this->Pressure->signalSpeed(this->Parameters), this->largestLength(s.vx, s.vy, s.vz),
                               this->maxAcceleration(), this->LaplacianCorrection);
}

double SPHSolver::chooseTimeStep(double remaining) const
{
  return timeStepFor(this->Parameters, this->proposedTimeStep(), remaining);
}

void SPHSolver::checkFinite() const
{
  // A blown-up simulation shows as a non-finite velocity; stop rather than hand on NaN.
  const auto n = static_cast<std::int64_t>(this->State.size());
  const float* vx = this->State.vx.data();
  const float* vy = this->State.vy.data();
  const float* vz = this->State.vz.data();
  const std::uint8_t* ghost = this->ghostFlags();
  double total = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : total) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    total += ghost && ghost[i] ? 0.0 : std::fabs(vx[i]) + std::fabs(vy[i]) + std::fabs(vz[i]);
  }
  if (!std::isfinite(this->globalSum(total)))
  {
    throw std::runtime_error("SPH became unstable at step " + std::to_string(this->Steps) +
                             " (non-finite velocity): " + this->stabilityAdvice());
  }
}

void SPHSolver::measureCompression()
{
  const auto n = static_cast<std::int64_t>(this->State.size());
  const float* rho = this->State.density.data();
  const float rho0 = this->Parameters.restDensity;
  const std::uint8_t* ghost = this->ghostFlags();
  double total = 0.0;
  float highest = 0.0f;
#pragma omp parallel for schedule(static) reduction(+ : total) reduction(max : highest)                          \
  num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const bool own = !(ghost && ghost[i]);
    total += own ? std::max(rho[i] - rho0, 0.0f) : 0.0f;
    highest = own ? std::max(highest, rho[i]) : highest;
  }
  const double count = this->globalSum(static_cast<double>(this->ownCount()));
  total = this->globalSum(total);
  this->Last.meanCompression = count > 0.0 ? total / (count * rho0) : 0.0;
  this->Last.maxDensityRatio = this->globalMax(static_cast<double>(highest)) / rho0;
}

std::string SPHSolver::stabilityAdvice() const
{
  return solverEntry(this->Parameters.pressureSolver).stabilityAdvice(this->Parameters.adaptiveTimeStep);
}

void SPHSolver::checkPhysical() const
{
  // Weakly compressible water stays within a few percent of rest density and DFSPH within its
  // tolerance; twice the rest density, or a particle ten times faster than anything in the scene
  // can make it go, is a run that has blown up even if no number is NaN yet.
  constexpr double kMaxDensityRatio = 2.0;
  if (this->Last.maxDensityRatio > kMaxDensityRatio)
  {
    throw std::runtime_error("SPH stopped at t = " + std::to_string(this->Time) + " s: the density reached " +
                             std::to_string(this->Last.maxDensityRatio) +
                             " x RestDensity (a liquid stays within a few percent): the run has blown up; " +
                             this->stabilityAdvice());
  }
  const double speed = this->largestLength(this->State.vx, this->State.vy, this->State.vz);
  if (speed > this->SpeedLimit)
  {
    throw std::runtime_error("SPH stopped at t = " + std::to_string(this->Time) + " s: a particle moves at " +
                             std::to_string(speed) + " m/s, more than the " + std::to_string(this->SpeedLimit) +
                             " m/s this scene allows (ten times free fall across the domain plus the fastest start): "
                             "the run has blown up; " +
                             this->stabilityAdvice());
  }
}

void SPHSolver::sortByCell()
{
  ParticleState& s = this->State;
  if (this->Ghosts)
  {
    // The grid refuses a non-finite position; every process refuses together, none is left waiting.
    double bad = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      bad += std::isfinite(s.x[i] + s.y[i] + s.z[i]) ? 0.0 : 1.0;
    }
    if (this->globalSum(bad) > 0.0)
    {
      throw std::invalid_argument("SPH: non-finite positions");
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    if (this->Parameters.periodic[a])
    {
      this->Grid.setPeriodic(a, this->Parameters.domainBounds[2 * a], this->Parameters.domainBounds[2 * a + 1]);
    }
  }
  this->Grid.build(s.x.data(), s.y.data(), s.z.data(), s.size(), this->Parameters.smoothingLength);
  const auto& order = this->Grid.sortedOrder();
  const int threads = threadCount(this->Parameters);
  for (auto* a : { &s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz })
  {
    permute(*a, this->ScratchFloat, order, threads);
  }
  if (this->PressureImpulse.size() == s.size())
  {
    permute(this->PressureImpulse, this->ScratchFloat, order, threads);
  }
  if (this->Pressure)
  {
    SimulationParts parts(*this);
    this->Pressure->permute(parts, order, this->ScratchFloat, threads);
  }
  else if (s.density.size() == s.size())
  {
    // The constructor's sort of the initial state, before there is a pressure solver: a given
    // starting density (which δ-SPH keeps as its initial condition) moves with its particle.
    permute(s.density, this->ScratchFloat, order, threads);
  }
  permute(s.id, this->ScratchId, order, threads);
  permute(s.originalIndex, this->ScratchIndex, order, threads);
  if (this->Wall && this->Wall->contacts.triangle.size() == s.size())
  {
    // Each particle's last mesh triangle goes with it: the next search starts from it.
    permute(this->Wall->contacts.triangle, this->ScratchIndex, order, threads);
  }
  if (this->Ghosts)
  {
    this->Ghosts->permuted(order);
  }
  this->findMeshWalls();
  // Summed densities and every pressure are recomputed from the sorted positions next.
}

void SPHSolver::findMeshWalls()
{
  if (!this->Wall)
  {
    return;
  }
  const ParticleState& s = this->State;
  detail::MeshWallContacts& c = this->Wall->contacts;
  const auto n = static_cast<std::int64_t>(s.size());
  c.distance.resize(s.size());
  c.normal.resize(3 * s.size());
  // No hint for particles new since the last search (added ones, or the first search).
  c.triangle.resize(s.size(), std::numeric_limits<std::uint32_t>::max());
  const float reach = this->Wall->table.reach();
  const TriangleMeshView mesh = this->Boundary->view();
#pragma omp parallel for schedule(dynamic, 512) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const float p[3] = { s.x[i], s.y[i], s.z[i] };
    detail::findMeshWall(mesh, p, reach, c.distance[i], &c.normal[3 * i], c.triangle[i]);
  }
}

void SPHSolver::kick(float dt)
{
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  float* vx = s.vx.data();
  float* vy = s.vy.data();
  float* vz = s.vz.data();
  const float* ax = s.ax.data();
  const float* ay = s.ay.data();
  const float* az = s.az.data();
#pragma omp parallel for simd schedule(static) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    vx[i] += dt * ax[i];
    vy[i] += dt * ay[i];
    vz[i] += dt * az[i];
  }
}

void SPHSolver::drift(float dt)
{
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  const SPHParameters& p = this->Parameters;
  const TriangleBoundary* boundary =
    this->Boundary && this->Boundary->triangleCount() > 0 ? this->Boundary.get() : nullptr;
  const TriangleMeshView mesh = boundary ? boundary->view() : TriangleMeshView{};
  detail::DriftWalls walls{};
  for (int a = 0; a < 6; ++a)
  {
    walls.bounds[a] = p.domainBounds[a];
  }
  for (int a = 0; a < 3; ++a)
  {
    walls.periodic[a] = p.periodic[a];
  }
  walls.restitution = p.wallRestitution;
  walls.mesh = boundary ? &mesh : nullptr;
  walls.damping = p.boundaryDamping;
  walls.offset = 1e-3f * p.smoothingLength;
  float* position[3] = { s.x.data(), s.y.data(), s.z.data() };
  float* velocity[3] = { s.vx.data(), s.vy.data(), s.vz.data() };
#pragma omp parallel for schedule(static) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    float x[3] = { position[0][i], position[1][i], position[2][i] };
    float v[3] = { velocity[0][i], velocity[1][i], velocity[2][i] };
    detail::driftParticle(x, v, dt, walls);
    for (int a = 0; a < 3; ++a)
    {
      position[a][i] = x[a];
      velocity[a][i] = v[a];
    }
  }
}

std::vector<std::uint32_t> SPHSolver::neighbourCounts() const
{
  return detail::neighbourCountsOnGrid(this->Grid, this->State, this->Parameters);
}

std::vector<std::uint32_t> detail::neighbourCountsOnGrid(const NeighbourGrid& grid, const ParticleState& s,
                                                         const SPHParameters& p)
{
  std::vector<std::uint32_t> counts(s.size(), 0);
  const float h2 = p.smoothingLength * p.smoothingLength;
  detail::forEachParticleByCell(grid, s, p.smoothingLength, threadCount(p), {},
                                [&](detail::CandidateBuffer& candidates, std::uint32_t i)
                                {
                                  const float q[3] = { s.x[i], s.y[i], s.z[i] };
                                  counts[i] = candidates.findHits(q, h2) - 1; // the particle itself is a candidate
                                });
  return counts;
}

double SPHSolver::kineticEnergy() const
{
  const ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  const std::uint8_t* ghost = this->ghostFlags();
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const double v2 = static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
                      static_cast<double>(s.vz[i]) * s.vz[i];
    sum += ghost && ghost[i] ? 0.0 : v2;
  }
  return 0.5 * this->Parameters.particleMass * this->globalSum(sum);
}

double SPHSolver::bytesPerParticle() const
{
  const std::size_t n = this->State.size();
  if (n == 0)
  {
    return 0.0;
  }
  std::size_t total = this->State.bytes() + this->ScratchFloat.capacity() * sizeof(float) +
                      this->ScratchId.capacity() * sizeof(std::int64_t) +
                      this->ScratchIndex.capacity() * sizeof(std::uint32_t) +
                      this->InverseDensity.capacity() * sizeof(float) + this->Grid.bytes() + this->Pressure->bytes();
  for (const auto& normal : this->SurfaceNormal)
  {
    total += normal.capacity() * sizeof(float);
  }
  return static_cast<double>(total) / static_cast<double>(n);
}
} // namespace parafluid::sph
