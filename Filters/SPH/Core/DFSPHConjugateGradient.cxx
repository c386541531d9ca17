// DFSPH's density solve as a preconditioned conjugate gradient (SPHParameters::pressureConjugateGradient).
//
// The impulse of stiffnesses k (k = p / rho^2) changes the velocities by dv = -dt c G k, G the
// symmetric pressure gradient sum_j m (k_i + k_j) grad W_ij (c its lattice correction), and the
// density rate by D dv, D the SPH divergence sum_j m (v_i - v_j) . grad W_ij. With equal masses D
// is exactly the transpose of G, so the density change the impulse takes away over the step,
// B k = -dt D dv = c dt^2 G^T G k, is symmetric and positive semi-definite: a conjugate gradient
// solves it.
// Jacobi iterations (Bender & Koschier's) carry pressure one neighbourhood per iteration, so a
// column N particles deep needs of order N^2 of them to build its hydrostatic pressure; the
// conjugate gradient of order N. The preconditioner is Jacobi's own step, alpha_i / (rho_i dt^2).
// Which particles are under pressure (the inequality of the free surface) is an active set, found
// again after each solve: those with a pressure, or compressed at the end of the step by what has
// been applied so far; the total is clamped to no tension after each solve.
#include "parafluid/sph/DFSPHSolver.h"

#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace parafluid::sph
{
namespace
{
/// Iterations of each solve at least (as the Jacobi form's two), and active-set rounds at most.
constexpr int kMinimumIterations = 2;
constexpr int kRounds = 8;
/// A round's solve is enough when the compression left averages under densityTolerance and
/// nowhere exceeds this many times it: the mean alone let a few particles at the free surface,
/// outside the set solved for, be squeezed by 5-10 % in a resting column 40 particles deep.
constexpr float kLargestErrorOverTolerance = 10.0f;

/// sum_i a_i b_i in double, over the particles in `active`.
double dot(const std::vector<float>& a, const std::vector<float>& b, const std::vector<char>& active, int threads)
{
  const auto n = static_cast<std::int64_t>(a.size());
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i)
  {
    sum += active[i] ? static_cast<double>(a[i]) * b[i] : 0.0;
  }
  return sum;
}
} // namespace

int DFSPHSolver::solveDensityByConjugateGradient(SimulationParts& sim, float dt)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const auto n = static_cast<std::int64_t>(s.size());
  const int threads = detail::threadCount(p);
  const float rho0 = p.restDensity;
  std::vector<float>& error = this->Residual;
  error.resize(s.size());
  this->Active.resize(s.size());
  int iterations = 0;
  for (int round = 0; round < kRounds && iterations < p.maxPressureIterations; ++round)
  {
    this->computeDensityRate(sim);
    double excess = 0.0;
    float largest = 0.0f;
#pragma omp parallel for schedule(static) reduction(+ : excess) reduction(max : largest) num_threads(threads)
    for (std::int64_t i = 0; i < n; ++i)
    {
      error[i] = s.density[i] + dt * this->DensityRate[i] - rho0;
      excess += std::max(error[i], 0.0f);
      largest = std::max(largest, error[i]);
      this->Active[i] = this->Factor[i] > 0.0f && (this->DensityStiffness[i] > 0.0f || error[i] > 0.0f);
    }
    if (excess <= p.densityTolerance * rho0 * static_cast<double>(n) &&
        largest <= kLargestErrorOverTolerance * p.densityTolerance * rho0 && iterations >= kMinimumIterations)
    {
      break;
    }
    this->removeEnclosedMean(sim, error);
    iterations += this->solveConjugateGradient(sim, dt, p.maxPressureIterations - iterations);
  }
  return iterations;
}

void DFSPHSolver::removeEnclosedMean(SimulationParts& sim, std::vector<float>& error) const
{
  // Fluid with no free surface (walls and periodic sides all round) cannot change its volume: the
  // mean of the density error over the particles solved for is out of any pressure's reach (the
  // compatibility condition of a pressure equation with only walls for boundaries), and the
  // conjugate gradient, asked for it, builds a pressure that grows step after step (a periodic
  // channel's reached 20 Pa in 0.17 s against Jacobi's 8 and wrecked the Poiseuille profile).
  const auto n = static_cast<std::int64_t>(error.size());
  const int threads = detail::threadCount(sim.parameters());
  std::int64_t surface = 0, active = 0;
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : surface, active, sum) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i)
  {
    surface += this->NeighbourCount[i] < kSurfaceNeighbours ? 1 : 0;
    if (this->Active[i])
    {
      ++active;
      sum += error[i];
    }
  }
  if (surface > 0 || active == 0)
  {
    return;
  }
  const auto mean = static_cast<float>(sum / static_cast<double>(active));
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i)
  {
    error[i] -= this->Active[i] ? mean : 0.0f;
  }
}

void DFSPHSolver::densityChangeOperator(SimulationParts& sim, float dt, const std::vector<float>& x,
                                        const std::vector<char>& active, std::vector<float>& out)
{
  ParticleState& s = sim.state();
  const std::size_t n = s.size();
  // The impulse alone, from zero velocities: the real ones wait aside.
  std::vector<float>* velocity[3] = { &s.vx, &s.vy, &s.vz };
  for (int a = 0; a < 3; ++a)
  {
    std::swap(*velocity[a], this->SavedVelocity[a]);
    velocity[a]->assign(n, 0.0f);
  }
  this->Stiffness = x;
  this->applyPressureImpulse(sim, dt, false);
  this->computeDensityRate(sim);
  for (int a = 0; a < 3; ++a)
  {
    std::swap(*velocity[a], this->SavedVelocity[a]);
  }
  out.resize(n);
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) num_threads(detail::threadCount(sim.parameters()))
  for (std::int64_t i = 0; i < count; ++i)
  {
    out[i] = active[i] ? -dt * this->DensityRate[i] : 0.0f;
  }
}

int DFSPHSolver::solveConjugateGradient(SimulationParts& sim, float dt, int budget)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const std::size_t n = s.size();
  const auto count = static_cast<std::int64_t>(n);
  const int threads = detail::threadCount(p);
  const double limit = static_cast<double>(p.densityTolerance) * p.restDensity * static_cast<double>(n);
  std::vector<float>& r = this->Residual; // what is left of the predicted density error
  std::vector<float>& accumulated = this->DensityStiffness;
  const std::vector<char>& active = this->Active;
  std::vector<float>&z = this->Preconditioned, &d = this->Direction, &q = this->Product, &x = this->Increment;
  z.resize(n);
  x.assign(n, 0.0f);
  const float inverseStep = 1.0f / (dt * dt);
  auto precondition = [&]()
  {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < count; ++i)
    {
      if (!active[i])
      {
        r[i] = 0.0f;
      }
      z[i] = r[i] * this->Factor[i] / s.density[i] * inverseStep;
    }
  };
  auto residualNorm = [&]()
  {
    double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(threads)
    for (std::int64_t i = 0; i < count; ++i)
    {
      sum += std::fabs(static_cast<double>(r[i]));
    }
    return sum;
  };
  precondition();
  d = z;
  double rz = dot(r, z, active, threads);
  int iterations = 0;
  while (iterations < budget && rz > 0.0 && (iterations < kMinimumIterations || residualNorm() > limit))
  {
    this->densityChangeOperator(sim, dt, d, active, q);
    const double dq = dot(d, q, active, threads);
    if (!(dq > 0.0))
    {
      break; // no curvature left along d: converged to rounding
    }
    const auto step = static_cast<float>(rz / dq);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < count; ++i)
    {
      x[i] += step * d[i];
      r[i] -= step * q[i];
    }
    precondition();
    const double next = dot(r, z, active, threads);
    const auto beta = static_cast<float>(next / rz);
    rz = next;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < count; ++i)
    {
      d[i] = z[i] + beta * d[i];
    }
    ++iterations;
  }
  // The increments, with the total held at no tension, applied and kept as the next warm start.
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < count; ++i)
  {
    const float total = std::max(accumulated[i] + x[i], 0.0f);
    x[i] = total - accumulated[i];
    accumulated[i] = total;
  }
  this->Stiffness = x;
  this->applyPressureImpulse(sim, dt);
  return iterations;
}
} // namespace parafluid::sph
