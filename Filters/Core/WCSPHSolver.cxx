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
template<class T>
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
    const float s = this->State.x[i] + this->State.y[i] + this->State.z[i] + this->State.vx[i] + this->State.vy[i] +
                    this->State.vz[i];
    if (!std::isfinite(s))
    {
      throw std::invalid_argument("SPH: particle " + std::to_string(i) + " (id " + std::to_string(this->State.id[i]) +
                                  ") has a NaN or infinite position or velocity");
    }
  }
  // Particles that start outside the domain are reflected inside, as the walls would do.
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

namespace
{
/// The particles of the 27 cells around one cell, copied contiguously so that the pair loops of
/// all particles of that cell run over one long array (good SIMD use) instead of 9 short ranges.
struct CandidateBuffer
{
  std::vector<float> x, y, z, vx, vy, vz, pressure, inverseDensity;
  std::vector<std::uint32_t> hits; // positions in the buffer of candidates inside the kernel radius
  std::vector<float> distanceSquared;
  std::uint32_t size = 0;

  /// Copies the particles of the 27 cells around (ix, iy, iz) that lie within `reach` of that
  /// cell's box: the others cannot be within reach of any particle in the cell (this drops about
  /// a quarter of the 27 cells' particles). Velocities etc. only when forces are to be summed.
  void gather(const NeighbourGrid& grid, int ix, int iy, int iz, const ParticleState& s,
              const float* inverseDensityOfParticle, float reach)
  {
    std::uint32_t capacity = 0;
    grid.forEachNeighbourRange(ix, iy, iz, [&](std::uint32_t b, std::uint32_t e) { capacity += e - b; });
    const bool forces = inverseDensityOfParticle != nullptr;
    for (auto* a : { &x, &y, &z })
    {
      a->resize(capacity);
    }
    if (forces)
    {
      for (auto* a : { &vx, &vy, &vz, &pressure, &inverseDensity, &distanceSquared })
      {
        a->resize(capacity);
      }
      hits.resize(capacity);
    }
    const float cell = grid.cellSize();
    const float lo[3] = { grid.origin()[0] + ix * cell, grid.origin()[1] + iy * cell, grid.origin()[2] + iz * cell };
    const float hi[3] = { lo[0] + cell, lo[1] + cell, lo[2] + cell };
    const float reach2 = reach * reach;
    size = 0;
    grid.forEachNeighbourRange(ix, iy, iz,
                               [&](std::uint32_t b, std::uint32_t e)
                               {
                                 for (std::uint32_t j = b; j < e; ++j)
                                 {
                                   const float px = s.x[j], py = s.y[j], pz = s.z[j];
                                   const float dx = std::max({ lo[0] - px, 0.0f, px - hi[0] });
                                   const float dy = std::max({ lo[1] - py, 0.0f, py - hi[1] });
                                   const float dz = std::max({ lo[2] - pz, 0.0f, pz - hi[2] });
                                   if (dx * dx + dy * dy + dz * dz >= reach2)
                                   {
                                     continue;
                                   }
                                   x[size] = px;
                                   y[size] = py;
                                   z[size] = pz;
                                   if (forces)
                                   {
                                     vx[size] = s.vx[j];
                                     vy[size] = s.vy[j];
                                     vz[size] = s.vz[j];
                                     pressure[size] = s.pressure[j];
                                     inverseDensity[size] = inverseDensityOfParticle[j];
                                   }
                                   ++size;
                                 }
                               });
  }

  /// Σ_j (h² − r²)³ over candidates inside h of q (the poly6 sum without its constant).
  float poly6Sum(const float q[3], float h2) const
  {
    const float *px = x.data(), *py = y.data(), *pz = z.data();
    const float qx = q[0], qy = q[1], qz = q[2];
    float sum = 0.0f;
#pragma omp simd reduction(+ : sum)
    for (std::uint32_t j = 0; j < size; ++j)
    {
      const float dx = qx - px[j], dy = qy - py[j], dz = qz - pz[j];
      const float d = std::max(h2 - (dx * dx + dy * dy + dz * dz), 0.0f);
      sum += d * d * d;
    }
    return sum;
  }
};

struct PairConstants
{
  float h, h2, minDistance, pressureScale, viscosityScale;
};

/// Pressure + viscosity pair sum for a query particle (position q, velocity v, pressure pi):
/// returns Σ_j [P (pi + pj)/rho_j (h − r)² / r · (q − x_j) + V / rho_j (h − r) (v_j − v)].
void pairForceSum(CandidateBuffer& c, const float q[3], const float v[3], float pi, const PairConstants& k, float f[3])
{
  // First find the ~15 % of candidates inside h, so the square roots and divisions below are
  // spent on real neighbours only.
  const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data();
  float* r2 = c.distanceSquared.data();
#pragma omp simd
  for (std::uint32_t j = 0; j < c.size; ++j)
  {
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    r2[j] = dx * dx + dy * dy + dz * dz;
  }
  std::uint32_t count = 0;
  std::uint32_t* hits = c.hits.data();
  for (std::uint32_t j = 0; j < c.size; ++j)
  {
    hits[count] = j;
    count += r2[j] < k.h2 ? 1u : 0u;
  }
  float fx = 0.0f, fy = 0.0f, fz = 0.0f;
  const float *pvx = c.vx.data(), *pvy = c.vy.data(), *pvz = c.vz.data();
  const float *pp = c.pressure.data(), *pinv = c.inverseDensity.data();
#pragma omp simd reduction(+ : fx, fy, fz)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const std::uint32_t j = hits[n];
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const float dist = std::sqrt(dx * dx + dy * dy + dz * dz);
    const float w = k.h - dist;
    // The particle itself (and any exact overlap) has dx = 0 and adds nothing.
    const float pairPressure = k.pressureScale * (pi + pp[j]) * pinv[j] * w * w / std::max(dist, k.minDistance);
    const float pairViscosity = k.viscosityScale * pinv[j] * w;
    fx += pairPressure * dx + pairViscosity * (pvx[j] - v[0]);
    fy += pairPressure * dy + pairViscosity * (pvy[j] - v[1]);
    fz += pairPressure * dz + pairViscosity * (pvz[j] - v[2]);
  }
  f[0] = fx;
  f[1] = fy;
  f[2] = fz;
}
/// Runs body(candidates, i) for every particle i, cell by cell in parallel, after gathering into
/// a thread-private buffer the candidates of that cell (with per-particle data if
/// inverseDensity is given). Each particle is handled by one thread in a fixed candidate order, so
/// the result does not depend on the thread count.
template<class Body>
void forEachParticleByCell(const NeighbourGrid& grid, const ParticleState& s, const float* inverseDensity, float reach,
                           int threads, Body&& body)
{
  const auto& start = grid.cellStart();
  const auto cells = static_cast<std::int64_t>(grid.cellCount());
#pragma omp parallel num_threads(threads)
  {
    CandidateBuffer candidates;
#pragma omp for schedule(dynamic, 64)
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
      candidates.gather(grid, ix, iy, iz, s, inverseDensity, reach);
      for (std::uint32_t i = begin; i < end; ++i)
      {
        body(candidates, i);
      }
    }
  }
}
} // namespace

void WCSPHSolver::computeDensityAndPressure()
{
  ParticleState& s = this->State;
  const SPHParameters& p = this->Parameters;
  const Poly6Kernel w(p.smoothingLength);
  const float densityScale = p.particleMass * w.coefficient;
  const float k = p.gasStiffness;
  const float rho0 = p.restDensity;
  const bool clamp = p.clampNegativePressure;
  forEachParticleByCell(this->Grid, s, nullptr, p.smoothingLength, threadCount(p),
                        [&](const CandidateBuffer& candidates, std::uint32_t i)
                        {
                          const float position[3] = { s.x[i], s.y[i], s.z[i] };
                          float sum = candidates.poly6Sum(position, w.h2); // includes the particle itself (r = 0)
                          // Near walls the mirrored fluid fills the cut-off neighbourhood: |x_i - R x_j| = |R x_i -
                          // x_j|.
                          const WallMirrors mirrors = WallMirrors::around(position, p.domainBounds, p.smoothingLength);
                          for (int m = 0; m < mirrors.count; ++m)
                          {
                            float image[3];
                            for (int a = 0; a < 3; ++a)
                            {
                              image[a] = mirrors.scale[m][a] * position[a] + mirrors.offset[m][a];
                            }
                            sum += candidates.poly6Sum(image, w.h2);
                          }
                          const float rho = densityScale * sum;
                          s.density[i] = rho;
                          const float pressure = k * (rho - rho0);
                          s.pressure[i] = clamp ? std::max(pressure, 0.0f) : pressure;
                        });
}

void WCSPHSolver::computeAccelerations()
{
  ParticleState& s = this->State;
  const SPHParameters& p = this->Parameters;
  const SpikyKernel spiky(p.smoothingLength);
  const ViscosityKernel viscous(p.smoothingLength);
  PairConstants constants;
  constants.h = p.smoothingLength;
  constants.h2 = constants.h * constants.h;
  // Smallest distance divided by; pairs closer than this push along a direction of zero length.
  constants.minDistance = 1e-6f * constants.h;
  // a_i(pressure) = -sum_j m (p_i + p_j) / (2 rho_i rho_j) grad W_spiky, grad W = dW/dr r_ij / r,
  // dW/dr = -3 c (h - r)^2, so the pair term is +1.5 c m (p_i + p_j)/(rho_i rho_j) (h - r)^2 r_ij / r.
  constants.pressureScale = 1.5f * spiky.coefficient * p.particleMass;
  // a_i(viscosity) = mu / rho_i sum_j m (v_j - v_i) / rho_j lap W, lap W = lc (h - r).
  constants.viscosityScale = p.viscosity * p.particleMass * viscous.laplacianCoefficient;

  const std::size_t n = s.size();
  this->InverseDensity.resize(n);
  float* inverseDensity = this->InverseDensity.data();
  const int threads = threadCount(p);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
  {
    inverseDensity[i] = 1.0f / s.density[i]; // density > 0: every particle counts itself
  }
  forEachParticleByCell(this->Grid, s, inverseDensity, constants.h, threads,
                        [&](CandidateBuffer& candidates, std::uint32_t i)
                        {
                          const float position[3] = { s.x[i], s.y[i], s.z[i] };
                          const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
                          const float pi = s.pressure[i];
                          float f[3];
                          pairForceSum(candidates, position, velocity, pi, constants, f);
                          // Mirror images: the pair term of x_i with R x_j equals R times the term of R x_i with x_j
                          // (R is a reflection, its own inverse), velocities likewise.
                          const WallMirrors mirrors = WallMirrors::around(position, p.domainBounds, constants.h);
                          for (int m = 0; m < mirrors.count; ++m)
                          {
                            float image[3], imageVelocity[3], g[3];
                            for (int a = 0; a < 3; ++a)
                            {
                              image[a] = mirrors.scale[m][a] * position[a] + mirrors.offset[m][a];
                              imageVelocity[a] = mirrors.scale[m][a] * velocity[a];
                            }
                            pairForceSum(candidates, image, imageVelocity, pi, constants, g);
                            for (int a = 0; a < 3; ++a)
                            {
                              f[a] += mirrors.scale[m][a] * g[a];
                            }
                          }
                          const float inv = inverseDensity[i];
                          s.ax[i] = f[0] * inv + p.gravity[0];
                          s.ay[i] = f[1] * inv + p.gravity[1];
                          s.az[i] = f[2] * inv + p.gravity[2];
                        });
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
      // Damped reflection: a particle that left the box has its overshoot mirrored back inside and
      // its normal velocity reversed and scaled, so walls take energy out instead of adding it.
      // Not clamped onto the wall: a particle on the plane would coincide with its own mirror
      // image, which then could not push it.
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
                            this->ScratchId.capacity() * sizeof(std::int64_t) +
                            this->ScratchIndex.capacity() * sizeof(std::uint32_t) +
                            this->InverseDensity.capacity() * sizeof(float) + this->Grid.bytes();
  return static_cast<double>(total) / static_cast<double>(n);
}
} // namespace parafluid::sph
