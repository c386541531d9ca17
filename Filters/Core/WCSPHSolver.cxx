#include "parafluid/WCSPHSolver.h"

#include "parafluid/SPHKernels.h"
#include "parafluid/WallMirrors.h"

#include <algorithm>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <cmath>
#include <stdexcept>
#include <string>

namespace parafluid::sph
{
namespace
{
int threadCount(const SPHParameters& p)
{
#ifdef _OPENMP
  return p.threads > 0 ? p.threads : omp_get_max_threads();
#else
  (void)p;
  return 1;
#endif
}

/// Gathers a into sorted order through scratch, then swaps, so each array is copied once.
template <class T>
void permute(std::vector<T>& a, std::vector<T>& scratch, const std::vector<std::uint32_t>& order, int threads)
{
  const auto n = static_cast<std::int64_t>(order.size());
  scratch.resize(order.size());
  const T* source = a.data();
  T* target = scratch.data();
  const std::uint32_t* o = order.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < n; ++k)
  {
    target[k] = source[o[k]];
  }
  a.swap(scratch);
}
} // namespace

WCSPHSolver::WCSPHSolver(const SPHParameters& parameters, ParticleState initial)
  : Parameters(parameters)
  , State(std::move(initial))
{
  const std::string problem = this->Parameters.validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("SPH: " + problem);
  }
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
    const float s = this->State.x[i] + this->State.y[i] + this->State.z[i] + this->State.vx[i] +
      this->State.vy[i] + this->State.vz[i];
    if (!std::isfinite(s))
    {
      throw std::invalid_argument("SPH: particle " + std::to_string(i) + " (id " +
        std::to_string(this->State.id[i]) + ") has a NaN or infinite position or velocity");
    }
  }
  // Particles that start outside the domain are put on its boundary, as the walls would.
  this->drift(0.0f);
  this->computeForces();
}

void WCSPHSolver::computeForces()
{
  this->sortByCell();
  this->computeDensityAndPressure();
  this->computeAccelerations();
}

void WCSPHSolver::step()
{
  const float dt = this->Parameters.timeStep;
  this->kick(0.5f * dt);
  this->drift(dt);
  this->computeForces();
  this->kick(0.5f * dt);
  ++this->Steps;

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
      " (non-finite velocity): reduce TimeStep or GasStiffness, or raise Viscosity");
  }
}

void WCSPHSolver::sortByCell()
{
  ParticleState& s = this->State;
  this->Grid.build(s.x.data(), s.y.data(), s.z.data(), s.size(), this->Parameters.smoothingLength);
  const auto& order = this->Grid.sortedOrder();
  const int threads = threadCount(this->Parameters);
  for (auto* a : { &s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz })
  {
    permute(*a, this->ScratchFloat, order, threads);
  }
  permute(s.id, this->ScratchId, order, threads);
  permute(s.originalIndex, this->ScratchIndex, order, threads);
  // Accelerations, densities and pressures are recomputed from the sorted positions next.
}

void WCSPHSolver::computeDensityAndPressure()
{
  ParticleState& s = this->State;
  const SPHParameters& p = this->Parameters;
  const Poly6Kernel w(p.smoothingLength);
  const float h2 = w.h2;
  const float densityScale = p.particleMass * w.coefficient;
  const float k = p.gasStiffness;
  const float rho0 = p.restDensity;
  const bool clamp = p.clampNegativePressure;
  const float h = p.smoothingLength;
  const float* x = s.x.data();
  const float* y = s.y.data();
  const float* z = s.z.data();
  float* density = s.density.data();
  float* pressure = s.pressure.data();
  const NeighbourGrid& grid = this->Grid;
  const auto& start = grid.cellStart();
  const auto cells = static_cast<std::int64_t>(grid.cellCount());

#pragma omp parallel for schedule(dynamic, 256) num_threads(threadCount(p))
  for (std::int64_t c = 0; c < cells; ++c)
  {
    const std::uint32_t begin = start[c];
    const std::uint32_t end = start[c + 1];
    if (begin == end)
    {
      continue;
    }
    int ix, iy, iz;
    grid.cellCoordinates(static_cast<std::size_t>(c), ix, iy, iz);
    std::uint32_t rangeBegin[9], rangeEnd[9];
    int ranges = 0;
    grid.forEachNeighbourRange(ix, iy, iz, [&](std::uint32_t b, std::uint32_t e) {
      rangeBegin[ranges] = b;
      rangeEnd[ranges] = e;
      ++ranges;
    });
    for (std::uint32_t i = begin; i < end; ++i)
    {
      const float xi = x[i], yi = y[i], zi = z[i];
      float sum = 0.0f;
      for (int r = 0; r < ranges; ++r)
      {
#pragma omp simd reduction(+ : sum)
        for (std::uint32_t j = rangeBegin[r]; j < rangeEnd[r]; ++j)
        {
          const float dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
          const float d = std::max(h2 - (dx * dx + dy * dy + dz * dz), 0.0f);
          sum += d * d * d;
        }
      }
      const float position[3] = { xi, yi, zi };
      const WallMirrors mirrors = WallMirrors::around(position, p.domainBounds, h);
      for (int m = 0; m < mirrors.count; ++m)
      {
        const float* sc = mirrors.scale[m];
        const float* of = mirrors.offset[m];
        for (int r = 0; r < ranges; ++r)
        {
#pragma omp simd reduction(+ : sum)
          for (std::uint32_t j = rangeBegin[r]; j < rangeEnd[r]; ++j)
          {
            const float dx = xi - (sc[0] * x[j] + of[0]);
            const float dy = yi - (sc[1] * y[j] + of[1]);
            const float dz = zi - (sc[2] * z[j] + of[2]);
            const float d = std::max(h2 - (dx * dx + dy * dy + dz * dz), 0.0f);
            sum += d * d * d;
          }
        }
      }
      const float rho = densityScale * sum; // includes the particle itself (r = 0)
      density[i] = rho;
      const float pi = k * (rho - rho0);
      pressure[i] = clamp ? std::max(pi, 0.0f) : pi;
    }
  }
}

void WCSPHSolver::computeAccelerations()
{
  ParticleState& s = this->State;
  const SPHParameters& p = this->Parameters;
  const SpikyKernel spiky(p.smoothingLength);
  const ViscosityKernel viscous(p.smoothingLength);
  const float h = p.smoothingLength;
  const float h2 = h * h;
  // Smallest distance divided by; pairs closer than this push along a direction of zero length.
  const float minDistance = 1e-6f * h;
  const float m = p.particleMass;
  // a_i(pressure) = -sum_j m (p_i + p_j) / (2 rho_i rho_j) grad W_spiky, grad W = dW/dr r_ij / r,
  // dW/dr = -3 c (h - r)^2, so the pair term is +1.5 c m (p_i + p_j)/(rho_i rho_j) (h - r)^2 r_ij / r.
  const float pressureScale = 1.5f * spiky.coefficient * m;
  // a_i(viscosity) = mu / rho_i sum_j m (v_j - v_i) / rho_j lap W, lap W = lc (h - r).
  const float viscosityScale = p.viscosity * m * viscous.laplacianCoefficient;
  const float gx = p.gravity[0], gy = p.gravity[1], gz = p.gravity[2];

  const float* x = s.x.data();
  const float* y = s.y.data();
  const float* z = s.z.data();
  const float* vx = s.vx.data();
  const float* vy = s.vy.data();
  const float* vz = s.vz.data();
  const float* pressure = s.pressure.data();
  const std::size_t n = s.size();
  this->InverseDensity.resize(n);
  float* inverseDensity = this->InverseDensity.data();
  const float* density = s.density.data();
  const int threads = threadCount(p);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
  {
    inverseDensity[i] = 1.0f / density[i]; // density > 0: every particle counts itself
  }
  float* ax = s.ax.data();
  float* ay = s.ay.data();
  float* az = s.az.data();
  const NeighbourGrid& grid = this->Grid;
  const auto& start = grid.cellStart();
  const auto cells = static_cast<std::int64_t>(grid.cellCount());

#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::int64_t c = 0; c < cells; ++c)
  {
    const std::uint32_t begin = start[c];
    const std::uint32_t end = start[c + 1];
    if (begin == end)
    {
      continue;
    }
    int ix, iy, iz;
    grid.cellCoordinates(static_cast<std::size_t>(c), ix, iy, iz);
    std::uint32_t rangeBegin[9], rangeEnd[9];
    int ranges = 0;
    grid.forEachNeighbourRange(ix, iy, iz, [&](std::uint32_t b, std::uint32_t e) {
      rangeBegin[ranges] = b;
      rangeEnd[ranges] = e;
      ++ranges;
    });
    for (std::uint32_t i = begin; i < end; ++i)
    {
      const float xi = x[i], yi = y[i], zi = z[i];
      const float vxi = vx[i], vyi = vy[i], vzi = vz[i];
      const float pi = pressure[i];
      float fx = 0.0f, fy = 0.0f, fz = 0.0f;
      for (int r = 0; r < ranges; ++r)
      {
#pragma omp simd reduction(+ : fx, fy, fz)
        for (std::uint32_t j = rangeBegin[r]; j < rangeEnd[r]; ++j)
        {
          const float dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
          const float r2 = dx * dx + dy * dy + dz * dz;
          const float dist = std::sqrt(r2);
          const float q = r2 < h2 ? h - dist : 0.0f; // zero outside the support
          const float pairPressure =
            pressureScale * (pi + pressure[j]) * inverseDensity[j] * q * q / std::max(dist, minDistance);
          const float pairViscosity = viscosityScale * inverseDensity[j] * q;
          fx += pairPressure * dx + pairViscosity * (vx[j] - vxi);
          fy += pairPressure * dy + pairViscosity * (vy[j] - vyi);
          fz += pairPressure * dz + pairViscosity * (vz[j] - vzi);
        }
      }
      const float position[3] = { xi, yi, zi };
      const WallMirrors mirrors = WallMirrors::around(position, p.domainBounds, h);
      for (int m = 0; m < mirrors.count; ++m)
      {
        const float* sc = mirrors.scale[m];
        const float* of = mirrors.offset[m];
        for (int r = 0; r < ranges; ++r)
        {
#pragma omp simd reduction(+ : fx, fy, fz)
          for (std::uint32_t j = rangeBegin[r]; j < rangeEnd[r]; ++j)
          {
            const float dx = xi - (sc[0] * x[j] + of[0]);
            const float dy = yi - (sc[1] * y[j] + of[1]);
            const float dz = zi - (sc[2] * z[j] + of[2]);
            const float r2 = dx * dx + dy * dy + dz * dz;
            const float dist = std::sqrt(r2);
            const float q = r2 < h2 ? h - dist : 0.0f;
            const float pairPressure =
              pressureScale * (pi + pressure[j]) * inverseDensity[j] * q * q / std::max(dist, minDistance);
            const float pairViscosity = viscosityScale * inverseDensity[j] * q;
            fx += pairPressure * dx + pairViscosity * (sc[0] * vx[j] - vxi);
            fy += pairPressure * dy + pairViscosity * (sc[1] * vy[j] - vyi);
            fz += pairPressure * dz + pairViscosity * (sc[2] * vz[j] - vzi);
          }
        }
      }
      const float inv = inverseDensity[i];
      ax[i] = fx * inv + gx;
      ay[i] = fy * inv + gy;
      az[i] = fz * inv + gz;
    }
  }
}

void WCSPHSolver::kick(float dt)
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

void WCSPHSolver::drift(float dt)
{
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  const auto& b = this->Parameters.domainBounds;
  const float restitution = this->Parameters.wallRestitution;
  float* position[3] = { s.x.data(), s.y.data(), s.z.data() };
  float* velocity[3] = { s.vx.data(), s.vy.data(), s.vz.data() };
#pragma omp parallel for schedule(static) num_threads(threadCount(this->Parameters))
  for (std::int64_t i = 0; i < n; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      float xa = position[a][i] + dt * velocity[a][i];
      float va = velocity[a][i];
      // Damped reflection: a particle that left the box is put back on the wall and its normal
      // velocity reversed and scaled, so walls take energy out instead of adding it.
      // The overshoot is mirrored back (damped too), not clamped onto the wall: a particle on the
      // plane would coincide with its own mirror image, which then could not push it.
      if (xa < b[2 * a])
      {
        xa = std::min(b[2 * a] + restitution * (b[2 * a] - xa), b[2 * a + 1]);
        va = va < 0.0f ? -restitution * va : va;
      }
      else if (xa > b[2 * a + 1])
      {
        xa = std::max(b[2 * a + 1] - restitution * (xa - b[2 * a + 1]), b[2 * a]);
        va = va > 0.0f ? -restitution * va : va;
      }
      position[a][i] = xa;
      velocity[a][i] = va;
    }
  }
}

double WCSPHSolver::bytesPerParticle() const
{
  const std::size_t n = this->State.size();
  if (n == 0)
  {
    return 0.0;
  }
  const std::size_t total = this->State.bytes() + this->ScratchFloat.capacity() * sizeof(float) +
    this->ScratchId.capacity() * sizeof(std::int64_t) + this->ScratchIndex.capacity() * sizeof(std::uint32_t) +
    this->InverseDensity.capacity() * sizeof(float) + this->Grid.bytes();
  return static_cast<double>(total) / static_cast<double>(n);
}
} // namespace parafluid::sph
