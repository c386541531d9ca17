#include "parafluid/sph/SPHSolver.h"

#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/SolverRegistry.h"
#include "private/MeshWall.h"
#include "private/NeighbourCandidates.h"
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
  : Parameters(parameters)
  , State(std::move(initial))
  , Boundary(std::move(boundary))
{
  const std::string problem = this->Parameters.validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("SPH: " + problem);
  }
  this->completeInitialState();
  this->checkCoincident();
  this->SpeedLimit = this->sceneSpeedLimit();
  // Particles that start outside the domain are reflected inside, as the walls would do.
  this->drift(0.0f);
  this->sortByCell();
  const SPHParameters& p = this->Parameters;
  this->ParticleSpacing = latticeSpacingForMass(p.particleMass, p.smoothingLength, p.restDensity, p.densityKernel());
  const SolverEntry& solver = solverEntry(p.pressureSolver);
  switch (solver.viscousOperator)
  {
    case ViscousOperator::Morris:
      this->LaplacianCorrection =
        latticeMorrisLaplacianCorrection(this->ParticleSpacing, p.smoothingLength, p.densityKernel());
      break;
    case ViscousOperator::MonaghanSpiky:
      this->LaplacianCorrection =
        latticeLaplacianCorrection(this->ParticleSpacing, p.smoothingLength, DensityKernel::Poly6, true);
      break;
    case ViscousOperator::Monaghan:
      this->LaplacianCorrection =
        latticeLaplacianCorrection(this->ParticleSpacing, p.smoothingLength, p.densityKernel(), false);
      break;
  }
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

void SPHSolver::completeInitialState()
{
  const std::size_t n = this->State.x.size();
  if (this->State.y.size() != n || this->State.z.size() != n)
  {
    throw std::invalid_argument("SPH: position arrays have different lengths");
  }
  const bool hasVelocity = this->State.vx.size() == n && this->State.vy.size() == n && this->State.vz.size() == n;
  const bool hasId = this->State.id.size() == n;
  const bool hasIndex = this->State.originalIndex.size() == n;
  if (!hasVelocity && !(this->State.vx.empty() && this->State.vy.empty() && this->State.vz.empty()))
  {
    throw std::invalid_argument("SPH: velocity arrays do not match the particle count");
  }
  std::vector<std::int64_t> ids;
  std::vector<std::uint32_t> indices;
  if (hasId)
  {
    ids.swap(this->State.id);
  }
  if (hasIndex)
  {
    indices.swap(this->State.originalIndex);
  }
  this->State.resize(n); // zero velocity when none was given; ids and indices default to the index
  if (hasId)
  {
    this->State.id.swap(ids);
  }
  if (hasIndex)
  {
    this->State.originalIndex.swap(indices);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const float s = this->State.x[i] + this->State.y[i] + this->State.z[i] + this->State.vx[i] + this->State.vy[i] +
                    this->State.vz[i];
    if (!std::isfinite(s))
    {
      throw std::invalid_argument("SPH: particle " + std::to_string(i) + " (id " + std::to_string(this->State.id[i]) +
                                  ") has a NaN or infinite position or velocity");
    }
  }
}

double SPHSolver::sceneSpeedLimit() const
{
  // The scene's own speed scale: free fall over the domain's largest extent, and the fastest
  // particle at the start.
  const SPHParameters& p = this->Parameters;
  double extent = 0.0, g = 0.0, v0 = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent = std::max(extent, static_cast<double>(p.domainBounds[2 * a + 1] - p.domainBounds[2 * a]));
    g += static_cast<double>(p.gravity[a]) * p.gravity[a];
  }
  const ParticleState& s = this->State;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    v0 = std::max(v0, std::sqrt(static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
                                static_cast<double>(s.vz[i]) * s.vz[i]));
  }
  // 1 m/s floor: a weightless scene at rest may still start to move (surface tension).
  return 10.0 * (std::sqrt(2.0 * std::sqrt(g) * extent) + v0) + 1.0;
}

SPHSolver::~SPHSolver() = default;
SPHSolver::SPHSolver(SPHSolver&&) noexcept = default;
SPHSolver& SPHSolver::operator=(SPHSolver&&) noexcept = default;

std::int64_t SPHSolver::advance(double duration, const std::function<bool(double)>& progress)
{
  if (!(duration >= 0.0) || !std::isfinite(duration))
  {
    throw std::invalid_argument("SPH: the time to advance must be a non-negative number of seconds");
  }
  const double begin = this->Time, end = this->Time + duration;
  std::int64_t taken = 0;
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  const int threads = threadCount(this->Parameters);
  this->PressureImpulse.assign(s.size(), 0.0f);
  // A step this much shorter than the longest allowed one means forces have blown up; stop rather
  // than crawl forever.
  const double smallest = 1e-7 * std::min(this->Parameters.maxTimeStep, this->Parameters.timeStep);
  while (this->Time < end)
  {
    const double remaining = end - this->Time;
    const double dt = this->step(remaining);
    ++taken;
    const auto weight = static_cast<float>(dt);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      this->PressureImpulse[i] += weight * s.pressure[i];
    }
    if (dt >= remaining)
    {
      this->Time = end; // exactly, whatever the rounding of the sum
    }
    if (dt < smallest && dt < remaining)
    {
      throw std::runtime_error("SPH became unstable at t = " + std::to_string(this->Time) +
                               " s: the adaptive time step fell to " + std::to_string(dt) + " s; " +
                               this->stabilityAdvice());
    }
    if (progress && taken % 8 == 0 && !progress(duration > 0.0 ? 1.0 - (end - this->Time) / duration : 1.0))
    {
      break;
    }
  }
  const double elapsed = this->Time - begin;
  if (elapsed > 0.0)
  {
    const auto scale = static_cast<float>(1.0 / elapsed);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      s.pressure[i] = scale * this->PressureImpulse[i];
    }
  }
  this->PressureImpulse.clear(); // step() on its own leaves each step's pressure
  return taken;
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
  const std::size_t added = x.size();
  if (y.size() != added || z.size() != added || vx.size() != added || vy.size() != added || vz.size() != added)
  {
    throw std::invalid_argument("SPH: the added particles' arrays have different lengths");
  }
  for (std::size_t i = 0; i < added; ++i)
  {
    if (!std::isfinite(x[i] + y[i] + z[i] + vx[i] + vy[i] + vz[i]))
    {
      throw std::invalid_argument("SPH: added particle " + std::to_string(i) +
                                  " has a NaN or infinite position or velocity");
    }
  }
  if (added == 0)
  {
    return;
  }
  ParticleState& s = this->State;
  const std::size_t n = s.size();
  std::int64_t nextId = 0;
  std::uint32_t nextIndex = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    nextId = std::max(nextId, s.id[i] + 1);
    nextIndex = std::max(nextIndex, s.originalIndex[i] + 1);
  }
  s.x.insert(s.x.end(), x.begin(), x.end());
  s.y.insert(s.y.end(), y.begin(), y.end());
  s.z.insert(s.z.end(), z.begin(), z.end());
  s.vx.insert(s.vx.end(), vx.begin(), vx.end());
  s.vy.insert(s.vy.end(), vy.begin(), vy.end());
  s.vz.insert(s.vz.end(), vz.begin(), vz.end());
  for (auto* a : { &s.ax, &s.ay, &s.az, &s.pressure })
  {
    a->resize(n + added, 0.0f);
  }
  s.density.resize(n + added, this->Parameters.restDensity);
  for (std::size_t i = 0; i < added; ++i)
  {
    s.id.push_back(nextId + static_cast<std::int64_t>(i));
    s.originalIndex.push_back(nextIndex + static_cast<std::uint32_t>(i));
  }
  if (!this->PressureImpulse.empty())
  {
    this->PressureImpulse.resize(n + added, 0.0f);
  }
  this->Pressure->resize(n + added);
  this->drift(0.0f); // inside the walls
  this->sortByCell();
  {
    SimulationParts parts(*this);
    this->Pressure->restart(parts);
  }
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
  {
    SimulationParts parts(*this);
    this->Pressure->start(parts);
  }
  return n - kept;
}

double SPHSolver::largestLength(const std::vector<float>& x, const std::vector<float>& y,
                                const std::vector<float>& z) const
{
  const auto n = static_cast<std::int64_t>(x.size());
  float l2 = 0.0f;
#pragma omp parallel for schedule(static) reduction(max : l2) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    l2 = std::max(l2, x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
  }
  return std::sqrt(static_cast<double>(l2));
}

double SPHSolver::maxAcceleration() const
{
  return this->largestLength(this->State.ax, this->State.ay, this->State.az);
}

double SPHSolver::proposedTimeStep() const
{
  const SPHParameters& p = this->Parameters;
  if (!p.adaptiveTimeStep)
  {
    return p.timeStep;
  }
  const ParticleState& s = this->State;
  const double fastest = this->largestLength(s.vx, s.vy, s.vz);
  const double h = p.smoothingLength;
  double dt = p.maxTimeStep;
  // CFL: information (sound for WCSPH, the flow itself for incompressible DFSPH) may cross only a
  // fraction lambda of the kernel radius per step.
  const double c = this->Pressure->signalSpeed(p);
  const double speed = c + fastest;
  if (speed > 0.0)
  {
    dt = std::min(dt, p.cflNumber * h / speed);
  }
  const SolverEntry& solver = solverEntry(p.pressureSolver);
  if (p.viscosity > 0.0f && solver.separateExtraViscosity)
  {
    // Explicit diffusion is stable for dt nu S < 1, S the sum of Müller's Laplacian weights over a
    // neighbourhood: about 15 / h^2, up to twice that beside a wall's mirror images. Kept at 0.75.
    dt = std::min(dt, h * h * p.restDensity / (40.0 * p.viscosity));
  }
  // A solver without a term of its own for Müller's extra viscosity folds it into its laminar term.
  const double nu = p.kinematicViscosity + (solver.separateExtraViscosity ? 0.0 : p.viscosity / p.restDensity);
  if (nu > 0.0 && solver.explicitLaminarViscosity)
  {
    // The explicit laminar term: nu dt / (h/2)^2 <= 0.125 (Morris et al. 1997), with nu scaled by
    // the operator's lattice correction and halved again beside no-slip walls, whose images double
    // the term; an implicit one has no such limit.
    dt = std::min(dt, 0.015 * h * h / (nu * this->LaplacianCorrection));
  }
  const double a = this->maxAcceleration();
  if (a > 0.0) // a particle may not move more than ~h/16 from its acceleration alone
  {
    dt = std::min(dt, 0.25 * std::sqrt(h / a));
  }
  if (p.surfaceTension > 0.0f) // capillary waves (Brackbill et al. 1992)
  {
    dt = std::min(dt, std::sqrt(p.restDensity * h * h * h / (2.0 * kPiF * p.surfaceTension)));
  }
  return dt;
}

double SPHSolver::chooseTimeStep(double remaining) const
{
  const double dt = this->proposedTimeStep();
  if (!this->Parameters.adaptiveTimeStep)
  {
    // Fixed steps: equal steps that fit the remaining time exactly (TimeStep 2e-4 over 4e-3 s is
    // 20 steps of exactly 2e-4, whatever the float rounding of 2e-4).
    const double steps = std::max(1.0, std::ceil(remaining / dt - 1e-6));
    return remaining / steps;
  }
  // Land exactly on the end time without a sliver of a last step: split the last two evenly.
  if (remaining <= dt)
  {
    return remaining;
  }
  if (remaining < 2.0 * dt)
  {
    return 0.5 * remaining;
  }
  return dt;
}

void SPHSolver::checkFinite() const
{
  // A blown-up simulation shows as a non-finite velocity; stop rather than hand on NaN.
  const auto n = static_cast<std::int64_t>(this->State.size());
  const float* vx = this->State.vx.data();
  const float* vy = this->State.vy.data();
  const float* vz = this->State.vz.data();
  double total = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : total) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    total += std::fabs(vx[i]) + std::fabs(vy[i]) + std::fabs(vz[i]);
  }
  if (!std::isfinite(total))
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
  double total = 0.0;
  float highest = 0.0f;
#pragma omp parallel for schedule(static) reduction(+ : total) reduction(max : highest)                          \
  num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    total += std::max(rho[i] - rho0, 0.0f);
    highest = std::max(highest, rho[i]);
  }
  this->Last.meanCompression = n > 0 ? total / (static_cast<double>(n) * rho0) : 0.0;
  this->Last.maxDensityRatio = static_cast<double>(highest) / rho0;
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

void SPHSolver::checkCoincident() const
{
  const ParticleState& s = this->State;
  std::vector<std::uint32_t> order(s.size());
  std::iota(order.begin(), order.end(), 0u);
  auto key = [&](std::uint32_t i) { return std::make_tuple(s.x[i], s.y[i], s.z[i]); };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::size_t shared = 0;
  std::uint32_t first = 0, second = 0;
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    if (key(order[k]) == key(order[k - 1]) && shared++ == 0)
    {
      first = std::min(order[k], order[k - 1]);
      second = std::max(order[k], order[k - 1]);
    }
  }
  if (shared > 0)
  {
    throw std::invalid_argument(
      "SPH: " + std::to_string(shared) + " particles share their position with another (first: particles " +
      std::to_string(first) + " and " + std::to_string(second) + " at (" + std::to_string(s.x[first]) + ", " +
      std::to_string(s.y[first]) + ", " + std::to_string(s.z[first]) +
      ")); SPH forces vanish at zero distance, so they would never separate: remove the duplicates upstream (the "
      "Clean filter) or move them apart");
  }
}

void SPHSolver::sortByCell()
{
  ParticleState& s = this->State;
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
  const TriangleBoundary& mesh = *this->Boundary;
#pragma omp parallel for schedule(dynamic, 512) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const float p[3] = { s.x[i], s.y[i], s.z[i] };
    float distance = reach;
    float* normal = &c.normal[3 * i];
    std::uint32_t triangle = c.triangle[i];
    // The fluid's side of a mesh is the one its faces' normals point to (a terrain's top, an
    // obstacle's outside). A particle behind it (on a container's mesh that faces out, or pushed
    // through) gets no wall: the wall would push it further in.
    bool near = mesh.nearest(p, reach, distance, normal, &triangle, triangle);
    if (near)
    {
      const float* face = mesh.faceNormal(triangle);
      near = normal[0] * face[0] + normal[1] * face[1] + normal[2] * face[2] > 0.0f;
    }
    if (!near)
    {
      distance = reach;
      normal[0] = normal[1] = normal[2] = 0.0f;
    }
    c.distance[i] = distance;
    c.triangle[i] = triangle;
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
  const auto& b = this->Parameters.domainBounds;
  const float restitution = this->Parameters.wallRestitution;
  const TriangleBoundary* mesh = this->Boundary && this->Boundary->triangleCount() > 0 ? this->Boundary.get() : nullptr;
  const float damping = this->Parameters.boundaryDamping;
  const std::array<bool, 3> periodic = this->Parameters.periodic;
  // Particles are put back this far off a mesh, so the next step starts on a definite side of it.
  const float offset = 1e-3f * this->Parameters.smoothingLength;
  float* position[3] = { s.x.data(), s.y.data(), s.z.data() };
  float* velocity[3] = { s.vx.data(), s.vy.data(), s.vz.data() };
#pragma omp parallel for schedule(static) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const float from[3] = { position[0][i], position[1][i], position[2][i] };
    float to[3];
    float v[3];
    for (int a = 0; a < 3; ++a)
    {
      float xa = from[a] + dt * velocity[a][i];
      float va = velocity[a][i];
      // Damped reflection: a particle that left the box has its overshoot mirrored back inside and
      // its normal velocity reversed and scaled, so walls take energy out instead of adding it.
      // Not clamped onto the wall: a particle on the plane would coincide with its own mirror
      // image, which then could not push it.
      if (periodic[a])
      {
        // Through the face and back in through the opposite one (fmod keeps a far jump inside too).
        const float length = b[2 * a + 1] - b[2 * a];
        xa = b[2 * a] + std::fmod(xa - b[2 * a], length);
        xa = xa < b[2 * a] ? xa + length : (xa >= b[2 * a + 1] ? xa - length : xa);
      }
      else if (xa < b[2 * a])
      {
        xa = std::min(b[2 * a] + restitution * (b[2 * a] - xa), b[2 * a + 1]);
        va = va < 0.0f ? -restitution * va : va;
      }
      else if (xa > b[2 * a + 1])
      {
        xa = std::max(b[2 * a + 1] - restitution * (xa - b[2 * a + 1]), b[2 * a]);
        va = va > 0.0f ? -restitution * va : va;
      }
      to[a] = xa;
      v[a] = va;
    }
    // The box is convex and both ends of the move are inside it, so the mesh can only move the end
    // point back towards the start, except by the small offset, which the clamp takes care of.
    if (mesh && mesh->resolve(from, to, v, damping, offset))
    {
      float clamped[3];
      bool moved = false;
      for (int a = 0; a < 3; ++a)
      {
        clamped[a] = periodic[a] ? to[a] : std::clamp(to[a], b[2 * a], b[2 * a + 1]);
        moved = moved || clamped[a] != to[a];
      }
      // Clamping into the box can push a particle back across the mesh where the mesh leaves the
      // box (a sphere cut by a wall); then it stays where it was, which is on the right side.
      parafluid::TriangleBoundary::Crossing crossing;
      if (moved && mesh->firstCrossing(from, clamped, crossing))
      {
        std::copy(from, from + 3, clamped);
      }
      std::copy(clamped, clamped + 3, to);
    }
    for (int a = 0; a < 3; ++a)
    {
      position[a][i] = to[a];
      velocity[a][i] = v[a];
    }
  }
}

std::vector<std::uint32_t> SPHSolver::neighbourCounts() const
{
  const ParticleState& s = this->State;
  std::vector<std::uint32_t> counts(s.size(), 0);
  const float h2 = this->Parameters.smoothingLength * this->Parameters.smoothingLength;
  detail::forEachParticleByCell(this->Grid, s, this->Parameters.smoothingLength, threadCount(this->Parameters), {},
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
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    sum += static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
           static_cast<double>(s.vz[i]) * s.vz[i];
  }
  return 0.5 * this->Parameters.particleMass * sum;
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
