// δ-SPH's start: the automatic sound speed, the initial density (hydrostatic unless given) and the
// first pressures and accelerations.
#include "parafluid/sph/DeltaSPHSolver.h"

#include "private/DeltaSPHPairs.h"
#include "private/MeshWall.h"
#include "private/SimulationParts.h"

#include <unordered_map>

namespace parafluid::sph
{
using namespace delta;

double DeltaSPHSolver::automaticSoundSpeed(const SPHParameters& p, const ParticleState& s)
{
  return automaticSoundSpeed(p, fluidHeight(p, s), fastestSpeed(s));
}

double DeltaSPHSolver::automaticSoundSpeed(const SPHParameters& p, double height, double fastest)
{
  if (p.soundSpeed > 0.0f)
  {
    return p.soundSpeed;
  }
  const double g = gravityMagnitude(p);
  double speed = std::max(std::sqrt(2.0 * g * height), fastest);
  if (p.surfaceTension > 0.0f)
  {
    // Cohesion holds the fluid under a pressure of about 10 sigma / h (Akinci's force at water's
    // 0.0728 N/m and h = 1 mm: 800 Pa); the sound speed keeps that pressure's compression at ~1 %.
    speed = std::max(speed, std::sqrt(10.0 * p.surfaceTension / (p.restDensity * p.smoothingLength)));
  }
  return 10.0 * std::max(speed, 0.1); // at least 1 m/s, for a scene at rest without gravity
}

void DeltaSPHSolver::start(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  // Over every process of a distributed run (a ghost is some process's particle, so counting it
  // changes no extreme): each takes the same sound speed.
  const std::array<double, 2> range = heightRange(sim.parameters(), s);
  const double height = fluidHeight(sim.parameters(), { -sim.globalMax(-range[0]), sim.globalMax(range[1]) });
  this->SoundSpeed = automaticSoundSpeed(sim.parameters(), height, sim.globalMax(fastestSpeed(s)));
  this->SlowDepartureTime = slowDepartureTime(sim.parameters(), height);
  this->PressureCorrection =
    latticeGradientCorrection(sim.particleSpacing(), sim.parameters().smoothingLength, DensityKernel::WendlandC2);
  // Density is state here: a given one (a prepared initial condition) is kept; otherwise the
  // fluid starts in hydrostatic equilibrium, so a resting column does not ring acoustically.
  const bool given = !s.density.empty() && std::all_of(s.density.begin(), s.density.end(),
                                                       [](float rho) { return std::isfinite(rho) && rho > 0.0f; });
  if (!given)
  {
    hydrostaticDensity(sim.parameters(), this->SoundSpeed, sim.particleSpacing(), s);
  }
  this->DensityRate.assign(s.size(), 0.0f);
  this->startSlowDeparture(sim);
  // The wall's sum where each particle starts: its density counts from there.
  this->WallSum.assign(s.size(), 0.0f);
  if (sim.wall())
  {
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      this->WallSum[i] = sim.wall()->table.at(sim.wall()->contacts.distance[i]).sum;
    }
  }
  // A ghost's column may reach past what this process holds: its owner's density counts.
  sim.refreshGhosts({ s.density.data() });
  this->updatePressure(sim);
  this->computeAccelerations(sim);
}

double DeltaSPHSolver::slowDepartureTime(const SPHParameters& p, const ParticleState& s)
{
  // The slow part of the density's departure follows it over the fluid's free-fall time over its
  // own height: ten sqrt(2) times the time sound crosses that height at the automatic c0, and 3.5
  // times the slowest acoustic period (4 H / c0), so acoustic noise stays in the fast part; a
  // departure held longer than that (a truncated kernel's at a free surface at rest) counts as slow.
  // Without gravity nothing holds the surface off hydrostatic, and the whole departure diffuses.
  return slowDepartureTime(p, fluidHeight(p, s));
}

double DeltaSPHSolver::slowDepartureTime(const SPHParameters& p, double height)
{
  const double g = gravityMagnitude(p);
  return g > 0.0 ? std::sqrt(height / g) : 0.0;
}

void DeltaSPHSolver::hydrostaticDensity(const SPHParameters& p, double soundSpeed, float spacing, ParticleState& s)
{
  std::fill(s.density.begin(), s.density.end(), p.restDensity);
  // Gravity along one axis only (the usual case); otherwise rest density, which settles acoustically.
  int down = -1;
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    if (p.gravity[a] != 0.0f && p.gravity[b] == 0.0f && p.gravity[c] == 0.0f)
    {
      down = a;
    }
  }
  if (down < 0 || s.size() == 0 || p.periodic[down])
  {
    return; // no gravity, gravity off an axis, or along a periodic axis (a body force without a top)
  }
  // Depth of each particle below the top of its column (columns one spacing wide across gravity),
  // plus half a spacing: the free surface lies half a spacing above the top particle.
  const int b = (down + 1) % 3, c = (down + 2) % 3;
  const float* position[3] = { s.x.data(), s.y.data(), s.z.data() };
  const float sign = p.gravity[down] < 0.0f ? 1.0f : -1.0f; // height grows against gravity
  const float d = spacing;
  std::unordered_map<std::int64_t, float> top;
  auto key = [&](std::size_t i)
  {
    const auto u = static_cast<std::int64_t>(std::floor(position[b][i] / d));
    const auto v = static_cast<std::int64_t>(std::floor(position[c][i] / d));
    return u * 2000003LL + v;
  };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const float height = sign * position[down][i];
    auto [it, inserted] = top.emplace(key(i), height);
    if (!inserted)
    {
      it->second = std::max(it->second, height);
    }
  }
  const double g = std::fabs(p.gravity[down]);
  const double bulk = soundSpeed * soundSpeed * p.restDensity / kGamma;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const double depth = top[key(i)] - sign * position[down][i] + 0.5 * d;
    s.density[i] = static_cast<float>(p.restDensity * std::pow(1.0 + p.restDensity * g * depth / bulk, 1.0 / kGamma));
  }
}
} // namespace parafluid::sph
