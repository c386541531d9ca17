// Divergence-free SPH (Bender & Koschier, "Divergence-Free Smoothed Particle Hydrodynamics",
// SCA 2015): each step predicts velocities from the non-pressure forces, corrects them so that the
// density predicted at the end of the step is rest density (density solve), moves the particles,
// then corrects the velocities again so that the density does not change (divergence solve).
// Both solves work on per-particle stiffnesses k_i (= p_i / rho_i^2), warm-started with the previous
// step's sums; the divergence solve by Jacobi iterations, the density solve by a conjugate gradient
// (DFSPHConjugateGradient.cxx) or, as Bender & Koschier's implementation, Jacobi iterations. Density and its gradient
// use the cubic spline, so what the solver predicts is what the next density pass measures.
#include "parafluid/sph/DFSPHSolver.h"

#include "private/SimulationParts.h"

#include "parafluid/common/Kernels.h"
#include "private/MeshWall.h"
#include "private/NeighbourCandidates.h"
#include "private/WallImages.h"

#include <algorithm>
#include <cmath>

namespace parafluid::sph
{
using detail::CandidateBuffer;
using detail::forEachParticleByCell;
using detail::threadCount;

namespace
{
/// Cubic-spline W(r) and (dW/dr)/r without branches, for the vectorised pair loops.
struct CubicPair
{
  float h2, inverseH, coefficient;
  explicit CubicPair(float h)
    : h2(h * h)
    , inverseH(1.0f / h)
    , coefficient(CubicSplineKernel(h).coefficient)
  {
  }
  float value(float r, float q) const
  {
    (void)r;
    const float d = 1.0f - q;
    return q <= 0.5f ? coefficient * (6.0f * q * q * (q - 1.0f) + 1.0f) : coefficient * 2.0f * d * d * d;
  }
  /// (dW/dr) / r: finite at r = 0 (where it multiplies a zero vector).
  float gradientFactor(float r, float q) const
  {
    const float d = 1.0f - q;
    const float inner = coefficient * inverseH * inverseH * (18.0f * q - 12.0f);
    const float outer = -6.0f * coefficient * inverseH * d * d / std::max(r, 1e-30f);
    return q <= 0.5f ? inner : outer;
  }
};

} // namespace

SolverEntry DFSPHSolver::registryEntry()
{
  SolverEntry e{};
  e.type = PressureSolverType::DFSPH;
  e.key = "DFSPH";
  e.label = "DFSPH";
  e.propertyValue = 1;
  e.kernel = DensityKernel::CubicSpline;
  e.defaultSupport = 2.0f;
  // Its Jacobi solves' diagonal factor is tight enough at 2 spacings; wider kernels overshoot and
  // diverge within a step (docs/design-notes.md).
  e.maximumSupport = 2.25f;
  e.viscousOperator = ViscousOperator::Monaghan;
  e.separateExtraViscosity = true;
  e.meshWallInSums = true;
  e.meshWallInRunoff = true;
  e.colourFieldSurfaceTension = true;
  e.implicitViscosity = true;
  e.runoffCFLNumber = 0.2f; // every seed of the basin's cloudburst held its pond at it
  e.create = [] { return std::unique_ptr<PressureSolver>(std::make_unique<DFSPHSolver>()); };
  e.stabilityAdvice = [](bool adaptive) -> std::string
  {
    return adaptive ? "lower CFLNumber or MaxTimeStep, or raise MaxPressureIterations"
                    : "lower TimeStep or turn on AdaptiveTimeStep, or raise MaxPressureIterations";
  };
  return e;
}

void DFSPHSolver::start(SimulationParts& sim)
{
  const SPHParameters& p = sim.parameters();
  const std::size_t n = sim.state().size();
  this->GradientCorrection = latticeGradientCorrection(sim.particleSpacing(), p.smoothingLength, p.densityKernel());
  this->DensityStiffness.assign(n, 0.0f);
  this->DivergenceStiffness.assign(n, 0.0f);
  this->computeDensityAndFactor(sim);
  sim.computeAccelerations(false);
}

void DFSPHSolver::permute(SimulationParts& sim, const std::vector<std::uint32_t>& order, std::vector<float>& scratch,
                          int threads)
{
  // DFSPH sorts in the middle of a step: the accelerations summed so far and the warm starts move
  // with their particles.
  ParticleState& s = sim.state();
  for (auto* a : { &s.ax, &s.ay, &s.az, &this->DensityStiffness, &this->DivergenceStiffness })
  {
    if (a->size() == s.size())
    {
      detail::permute(*a, scratch, order, threads);
    }
  }
}

void DFSPHSolver::resize(std::size_t n)
{
  // The warm starts of the particles already there are kept (losing them every time rain adds a
  // particle leaves each step's solve to start from nothing).
  this->DensityStiffness.resize(n, 0.0f);
  this->DivergenceStiffness.resize(n, 0.0f);
}

void DFSPHSolver::restart(SimulationParts& sim)
{
  this->computeDensityAndFactor(sim);
  sim.computeAccelerations(false);
}

std::size_t DFSPHSolver::bytes() const
{
  std::size_t total = this->NeighbourCount.capacity() * sizeof(std::uint16_t);
  total += this->Active.capacity();
  for (const auto* a :
       { &this->Factor, &this->DensityRate, &this->Stiffness, &this->DensityStiffness, &this->DivergenceStiffness,
         &this->Residual, &this->Direction, &this->Product, &this->Preconditioned, &this->Increment,
         &this->SavedVelocity[0], &this->SavedVelocity[1], &this->SavedVelocity[2] })
  {
    total += a->capacity() * sizeof(float);
  }
  return total;
}

void DFSPHSolver::computeDensityAndFactor(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const std::size_t n = s.size();
  this->Factor.resize(n);
  this->NeighbourCount.resize(n);
  const CubicPair w(p.smoothingLength);
  const float m = p.particleMass;
  forEachParticleByCell(sim.grid(), s, p.smoothingLength, threadCount(p), {},
                        [&](CandidateBuffer& c, std::uint32_t i)
                        {
                          const float position[3] = { s.x[i], s.y[i], s.z[i] };
                          float rho = 0.0f, gx = 0.0f, gy = 0.0f, gz = 0.0f, squares = 0.0f;
                          unsigned neighbours = 0;
                          detail::forEachWallImage(
                            position, position, p,
                            [&](const float* q, const float*, const float*, const float* scale, bool)
                            {
                              const std::uint32_t count = c.findHits(q, w.h2);
                              neighbours += count;
                              const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data(),
                                          *r2 = c.distanceSquared.data();
                              const std::uint32_t* hits = c.hits.data();
                              float sr = 0.0f, sx = 0.0f, sy = 0.0f, sz = 0.0f, ss = 0.0f;
#pragma omp simd reduction(+ : sr, sx, sy, sz, ss)
                              for (std::uint32_t k = 0; k < count; ++k)
                              {
                                const std::uint32_t j = hits[k];
                                const float r = std::sqrt(r2[j]);
                                const float q01 = r * w.inverseH;
                                sr += w.value(r, q01);
                                const float g = w.gradientFactor(r, q01);
                                const float dx = g * (q[0] - px[j]), dy = g * (q[1] - py[j]), dz = g * (q[2] - pz[j]);
                                sx += dx;
                                sy += dy;
                                sz += dz;
                                ss += dx * dx + dy * dy + dz * dz;
                              }
                              rho += sr;
                              gx += scale[0] * sx;
                              gy += scale[1] * sy;
                              gz += scale[2] * sz;
                              squares += ss;
                            });
                          detail::MeshWallTable::Weight wall;
                          const float* normal = nullptr;
                          if (sim.wall() && sim.wall()->of(i, wall, normal))
                          {
                            // The lattice beyond the mesh: density and the gradient of the particle's own move (it
                            // stays put, so it has no term of its own in the sum of squares: Bender & Koschier 2017).
                            rho += wall.sum;
                            gx += wall.slope * normal[0];
                            gy += wall.slope * normal[1];
                            gz += wall.slope * normal[2];
                            neighbours += static_cast<unsigned>(wall.neighbours + 0.5f);
                          }
                          rho *= m;
                          s.density[i] = rho;
                          // alpha_i = rho_i / (|sum_j m grad W_ij|^2 + sum_j |m grad W_ij|^2); an isolated particle has
                          // no gradient to correct with and gets 0.
                          const float denominator = m * m * (gx * gx + gy * gy + gz * gz + squares);
                          this->Factor[i] = denominator > 1e-12f * rho * rho / (p.smoothingLength * p.smoothingLength)
                                              ? rho / denominator
                                              : 0.0f;
                          this->NeighbourCount[i] = static_cast<std::uint16_t>(std::min(neighbours, 65535u));
                        });
}

void DFSPHSolver::computeDensityRate(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  this->DensityRate.resize(s.size());
  const CubicPair w(p.smoothingLength);
  const float m = p.particleMass;
  forEachParticleByCell(
    sim.grid(), s, p.smoothingLength, threadCount(p), { s.vx.data(), s.vy.data(), s.vz.data() },
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
      float rate = 0.0f;
      detail::forEachWallImage(
        position, velocity, p,
        [&](const float* q, const float* v, const float*, const float*, bool)
        {
          // An image moves with the mirrored velocity; the scalar sum needs no mapping back.
          const std::uint32_t count = c.findHits(q, w.h2);
          const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data(), *r2 = c.distanceSquared.data();
          const float *vx = c.channel[0].data(), *vy = c.channel[1].data(), *vz = c.channel[2].data();
          const std::uint32_t* hits = c.hits.data();
          float sum = 0.0f;
#pragma omp simd reduction(+ : sum)
          for (std::uint32_t k = 0; k < count; ++k)
          {
            const std::uint32_t j = hits[k];
            const float r = std::sqrt(r2[j]);
            const float g = w.gradientFactor(r, r * w.inverseH);
            sum +=
              g * ((q[0] - px[j]) * (v[0] - vx[j]) + (q[1] - py[j]) * (v[1] - vy[j]) + (q[2] - pz[j]) * (v[2] - vz[j]));
          }
          rate += sum;
        });
      detail::MeshWallTable::Weight wall;
      const float* normal = nullptr;
      if (sim.wall() && sim.wall()->of(i, wall, normal))
      {
        // The wall is at rest: v_i . sum_b grad W_ib.
        rate += wall.slope * (velocity[0] * normal[0] + velocity[1] * normal[1] + velocity[2] * normal[2]);
      }
      this->DensityRate[i] = m * rate;
    });
}

void DFSPHSolver::applyPressureImpulse(SimulationParts& sim, float dt, bool record)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const CubicPair w(p.smoothingLength);
  // The pressure force uses the gradient corrected to be exact for a linear field on the rest
  // lattice; the prediction (density rate) keeps the plain one, which matches the measured density.
  const float m = p.particleMass * this->GradientCorrection;
  // Velocities change in place: the pass reads the stiffnesses only, never the velocities.
  forEachParticleByCell(sim.grid(), s, p.smoothingLength, threadCount(p), { this->Stiffness.data() },
                        [&](CandidateBuffer& c, std::uint32_t i)
                        {
                          const float position[3] = { s.x[i], s.y[i], s.z[i] };
                          const float ki = this->Stiffness[i];
                          float f[3] = { 0.0f, 0.0f, 0.0f };
                          detail::forEachWallImage(
                            position, position, p,
                            [&](const float* q, const float*, const float*, const float* scale, bool)
                            {
                              const std::uint32_t count = c.findHits(q, w.h2);
                              const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data(),
                                          *r2 = c.distanceSquared.data();
                              const float* kj = c.channel[0].data();
                              const std::uint32_t* hits = c.hits.data();
                              float fx = 0.0f, fy = 0.0f, fz = 0.0f;
#pragma omp simd reduction(+ : fx, fy, fz)
                              for (std::uint32_t k = 0; k < count; ++k)
                              {
                                const std::uint32_t j = hits[k];
                                const float r = std::sqrt(r2[j]);
                                const float g = (ki + kj[j]) * w.gradientFactor(r, r * w.inverseH);
                                fx += g * (q[0] - px[j]);
                                fy += g * (q[1] - py[j]);
                                fz += g * (q[2] - pz[j]);
                              }
                              f[0] += scale[0] * fx;
                              f[1] += scale[1] * fy;
                              f[2] += scale[2] * fz;
                            });
                          detail::MeshWallTable::Weight wall;
                          const float* normal = nullptr;
                          if (sim.wall() && sim.wall()->of(i, wall, normal))
                          {
                            // The wall's particles have no pressure of their own: k_i alone.
                            for (int a = 0; a < 3; ++a)
                            {
                              f[a] += ki * wall.slope * normal[a];
                            }
                          }
                          // a_i = -sum_j m (k_i + k_j) grad W_ij, k = p / rho^2
                          const float a[3] = { -m * f[0], -m * f[1], -m * f[2] };
                          s.vx[i] += dt * a[0];
                          s.vy[i] += dt * a[1];
                          s.vz[i] += dt * a[2];
                          if (record)
                          {
                            s.ax[i] += a[0];
                            s.ay[i] += a[1];
                            s.az[i] += a[2];
                          }
                        });
}

void DFSPHSolver::warmStart(SimulationParts& sim, std::vector<float>& accumulated, float dt, float keep)
{
  const auto n = static_cast<std::int64_t>(accumulated.size());
#pragma omp parallel for schedule(static) num_threads(threadCount(sim.parameters()))
  for (std::int64_t i = 0; i < n; ++i)
  {
    accumulated[i] *= keep;
  }
  this->Stiffness = accumulated;
  this->applyPressureImpulse(sim, dt);
}

int DFSPHSolver::solveDensity(SimulationParts& sim, float dt)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const auto n = static_cast<std::int64_t>(s.size());
  const int threads = threadCount(p);
  const float rho0 = p.restDensity;
  // Jacobi's iterations only ever add pressure, so they start from half the last step's, a good
  // guess that still decays where it was too high; the conjugate gradient lowers pressure as well
  // as it raises it, and starts from all of it (from half, the dam break 80 particles across took 126 s
  // instead of 104 s of wall time, the same machine; Testing/Benchmarks/README.md).
  if (p.pressureConjugateGradient)
  {
    this->warmStart(sim, this->DensityStiffness, dt, 1.0f);
    return this->solveDensityByConjugateGradient(sim, dt);
  }
  this->warmStart(sim, this->DensityStiffness, dt, 0.5f);
  int iterations = 0;
  while (iterations < p.maxPressureIterations)
  {
    this->computeDensityRate(sim);
    double error = 0.0;
    const float scale = 1.0f / (dt * dt);
#pragma omp parallel for schedule(static) reduction(+ : error) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      // Only compression is corrected: a free surface is allowed to be below rest density.
      const float excess = std::max(s.density[i] + dt * this->DensityRate[i] - rho0, 0.0f);
      error += excess;
      this->Stiffness[i] = excess * scale * this->Factor[i] / s.density[i];
    }
    const double meanError = n > 0 ? error / (static_cast<double>(n) * rho0) : 0.0;
    if (meanError <= p.densityTolerance && iterations >= 2)
    {
      break;
    }
    this->applyPressureImpulse(sim, dt);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      this->DensityStiffness[i] += this->Stiffness[i];
    }
    ++iterations;
  }
  return iterations;
}

int DFSPHSolver::solveDivergence(SimulationParts& sim, float dt)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const auto n = static_cast<std::int64_t>(s.size());
  const int threads = threadCount(p);
  const float rho0 = p.restDensity;
  this->warmStart(sim, this->DivergenceStiffness, dt, 0.5f);
  int iterations = 0;
  while (iterations < p.maxPressureIterations)
  {
    this->computeDensityRate(sim);
    double error = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : error) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      const float rate = this->NeighbourCount[i] < kSurfaceNeighbours ? 0.0f : std::max(this->DensityRate[i], 0.0f);
      error += rate;
      this->Stiffness[i] = rate / dt * this->Factor[i] / s.density[i];
    }
    const double meanError = n > 0 ? error * dt / (static_cast<double>(n) * rho0) : 0.0;
    if (meanError <= p.divergenceTolerance && iterations >= 1)
    {
      break;
    }
    this->applyPressureImpulse(sim, dt);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      this->DivergenceStiffness[i] += this->Stiffness[i];
    }
    ++iterations;
  }
  return iterations;
}

double DFSPHSolver::step(SimulationParts& sim, double remaining)
{
  ParticleState& s = sim.state();
  // Non-pressure accelerations at the current state decide the step and predict the velocities.
  sim.computeAccelerations(false);
  const double dt = sim.chooseTimeStep(remaining);
  const auto h = static_cast<float>(dt);
  sim.kick(h);
  sim.statistics().viscosityIterations = this->solveViscosity(sim, h);
  sim.applyWallFriction(h);
  sim.statistics().densityIterations = this->solveDensity(sim, h);
  sim.drift(h);
  sim.sortByCell();
  this->computeDensityAndFactor(sim);
  sim.statistics().divergenceIterations = this->solveDivergence(sim, h);
  const auto n = static_cast<std::int64_t>(s.size());
#pragma omp parallel for schedule(static) num_threads(threadCount(sim.parameters()))
  for (std::int64_t i = 0; i < n; ++i)
  {
    // Both solves' impulses over the step amount to the pressure p_i = rho_i^2 k_i.
    s.pressure[i] = s.density[i] * s.density[i] * (this->DensityStiffness[i] + this->DivergenceStiffness[i]);
  }
  sim.statistics().timeStep = dt;
  sim.advanceTime(dt);
  return dt;
}
} // namespace parafluid::sph
