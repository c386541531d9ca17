// A periodic block of water under a uniform pressure, without gravity: does its simple cubic
// lattice stay where it starts?
#include "SPHScenes.h"
#include "SceneTimer.h"

#include "parafluid/sph/SPHSolver.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace parafluid::validation
{
using sph::PressureSolverType;
using sph::SPHSolver;

PressurisedLattice pressurisedLattice(PressureSolverType solver, int across, std::ostream* curves)
{
  // The still-water tank's 40-across spacing, sound speed (ten times the free-fall speed over its
  // 0.5 m) and the pressure 0.4 m down, where its lattice gave way (Testing/Benchmarks/README.md).
  const float d = 0.0125f, length = static_cast<float>(across) * d;
  const double soundSpeed = 10.0 * std::sqrt(2.0 * kGravity * 0.5), pressure = kRho0 * kGravity * 0.4;
  const std::array<float, 6> domain = { 0.0f, length, 0.0f, length, 0.0f, length };
  sph::SPHParameters p = water(solver, d, domain);
  p.gravity = { 0.0f, 0.0f, 0.0f };
  p.periodic = { true, true, true };
  p.soundSpeed = static_cast<float>(soundSpeed);
  ParticleState start = lattice({ 0, length, 0, length, 0, length }, d);
  // A seed of 1e-4 spacings of positional noise (fixed, so every run sees the same), and the
  // density of Tait's equation (gamma 7) at the chosen pressure: δ-SPH keeps a given density; the
  // other solvers sum theirs, so their block starts at rest density and feels no pressure.
  std::mt19937 random(1);
  std::normal_distribution<float> noise(0.0f, 1e-4f * d);
  for (std::size_t i = 0; i < start.size(); ++i)
  {
    start.x[i] += noise(random);
    start.y[i] += noise(random);
    start.z[i] += noise(random);
  }
  const double stiffness = kRho0 * soundSpeed * soundSpeed / 7.0;
  start.density.assign(start.size(), static_cast<float>(kRho0 * std::pow(1.0 + pressure / stiffness, 1.0 / 7.0)));
  SPHSolver s(p, std::move(start));
  PressurisedLattice r;
  r.cost.particles = static_cast<long long>(s.state().size());
  const SceneTimer timer;
  const double interval = 0.25, duration = 1.5;
  for (double t = interval; t <= duration + 1e-9; t += interval)
  {
    double largest = 0.0;
    while (s.time() < t - 1e-12)
    {
      s.step(t - s.time());
      ++r.cost.steps;
      const ParticleState& q = s.state();
      for (std::size_t i = 0; i < q.size(); ++i)
      {
        largest = std::max(largest, static_cast<double>(q.vx[i] * q.vx[i] + q.vy[i] * q.vy[i] + q.vz[i] * q.vz[i]));
      }
    }
    const ParticleState& q = s.state();
    double pressureSum = 0.0;
    for (std::size_t i = 0; i < q.size(); ++i)
    {
      pressureSum += q.pressure[i];
    }
    // The solver's kinetic energy is (m / 2) sum v^2.
    r.rmsSpeed = std::sqrt(2.0 * s.kineticEnergy() / (p.particleMass * static_cast<double>(q.size())));
    r.largestSpeed = std::sqrt(largest);
    r.meanPressure = pressureSum / static_cast<double>(q.size());
    if (curves)
    {
      *curves << solverName(solver) << "," << across << "," << s.time() << "," << r.rmsSpeed << "," << r.largestSpeed
              << "\n";
    }
  }
  r.cost.seconds = timer.seconds();
  return r;
}
} // namespace parafluid::validation
