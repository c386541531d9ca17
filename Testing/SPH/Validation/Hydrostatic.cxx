// Fluid at rest: the hydrostatic column and still water in a tank.
#include "SPHScenes.h"
#include "SceneTimer.h"

#include "parafluid/sph/SPHSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace parafluid::validation
{
using sph::PressureSolverType;
using sph::SPHSolver;

namespace
{
/// Relative L2 error of the given per-id pressures against rho0 g (surface - z), split by depth
/// layers one spacing thick (splitErrorByDepth).
ErrorByDepth hydrostaticError(const ParticleState& s, const std::vector<double>& pressureById, double surface,
                              double spacing, std::ostream* profile, const char* solver, int across)
{
  const std::size_t n = s.size();
  std::vector<double> z(n), value(n), reference(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto id = static_cast<std::size_t>(s.id[i]);
    z[i] = s.z[i];
    value[i] = pressureById[id];
    reference[i] = kRho0 * kGravity * (surface - z[i]);
    if (profile)
    {
      *profile << solver << "," << across << "," << z[i] << "," << value[i] << "," << reference[i] << "\n";
    }
  }
  return splitErrorByDepth(z, value, reference, spacing);
}
} // namespace

ErrorByDepth splitErrorByDepth(const std::vector<double>& z, const std::vector<double>& value,
                               const std::vector<double>& reference, double spacing)
{
  // Each particle's layer key; a position that is not finite (a particle gone astray) is a layer of
  // its own, and far positions are clamped so that the index cannot overflow.
  std::vector<long long> key(z.size());
  std::map<long long, std::pair<double, double>> layers; // key -> (count, sum of departures)
  double squares = 0.0, referenceSquares = 0.0;
  for (std::size_t i = 0; i < z.size(); ++i)
  {
    const double e = value[i] - reference[i];
    const double index = std::floor(z[i] / spacing);
    key[i] = std::isfinite(index) ? static_cast<long long>(std::clamp(index, -1e15, 1e15))
                                  : std::numeric_limits<long long>::min();
    auto& layer = layers[key[i]];
    layer.first += 1.0;
    layer.second += e;
    squares += e * e;
    referenceSquares += reference[i] * reference[i];
  }
  double meanPart = 0.0, withinPart = 0.0;
  for (const auto& entry : layers)
  {
    const double mean = entry.second.second / entry.second.first;
    meanPart += entry.second.first * mean * mean;
  }
  for (std::size_t i = 0; i < z.size(); ++i)
  {
    const auto& layer = layers[key[i]];
    const double scatter = value[i] - reference[i] - layer.second / layer.first;
    withinPart += scatter * scatter;
  }
  ErrorByDepth r;
  if (referenceSquares > 0.0)
  {
    r.total = std::sqrt(squares / referenceSquares);
    r.layerMean = std::sqrt(meanPart / referenceSquares);
    r.withinLayer = std::sqrt(withinPart / referenceSquares);
  }
  return r;
}

Hydrostatic hydrostatic(PressureSolverType solver, int across, std::ostream* profile, sph::Backend backend)
{
  const float width = 0.2f, height = 0.2f;
  const float d = width / static_cast<float>(across);
  const std::array<float, 6> domain = { 0.0f, width, 0.0f, 4 * d, 0.0f, 2.0f * height };
  const auto s =
    sph::makeSimulation(water(solver, d, domain), lattice({ 0, width, 0, 4 * d, 0, height }, d), nullptr, backend);
  Hydrostatic r;
  r.cost.particles = static_cast<long long>(s->particleCount());
  const SceneTimer timer;
  r.cost.steps += s->advance(0.4);
  std::vector<double> sum(s->particleCount(), 0.0); // by id: the state is reordered every step
  const int samples = 40;
  for (int k = 0; k < samples; ++k)
  {
    r.cost.steps += s->advance(0.005);
    r.compression += s->lastStep().meanCompression / samples;
    const std::vector<float> pressure = s->smoothedPressure(); // what SPH Step outputs as "pressure"
    for (std::size_t i = 0; i < pressure.size(); ++i)
    {
      sum[static_cast<std::size_t>(s->hostState().id[i])] += pressure[i] / samples;
    }
  }
  r.cost.seconds = timer.seconds();
  const ErrorByDepth error = hydrostaticError(s->hostState(), sum, height, d, profile, solverName(solver), across);
  r.error = error.total;
  r.layerMeanError = error.layerMean;
  r.withinLayerError = error.withinLayer;
  return r;
}

StillWater stillWater(PressureSolverType solver, int across, double duration)
{
  const float depth = 0.5f, length = 0.5f;
  const float d = depth / static_cast<float>(across);
  const std::array<float, 6> domain = { 0.0f, length, 0.0f, 4 * d, 0.0f, 2.0f * depth };
  SPHSolver s(water(solver, d, domain), lattice({ 0, length, 0, 4 * d, 0, depth }, d));
  StillWater r;
  r.cost.particles = static_cast<long long>(s.state().size());
  std::vector<float> x0(s.state().size()), z0(s.state().size());
  for (std::size_t i = 0; i < s.state().size(); ++i)
  {
    x0[static_cast<std::size_t>(s.state().id[i])] = s.state().x[i];
    z0[static_cast<std::size_t>(s.state().id[i])] = s.state().z[i];
  }
  const SceneTimer timer;
  const double interval = 0.05;
  const auto outputs = static_cast<int>(std::lround(duration / interval));
  const double reference = std::sqrt(kGravity * depth);
  double closest = 1e30;
  for (int k = 0; k < outputs; ++k)
  {
    r.cost.steps += s.advance(interval);
    const auto& st = s.state();
    for (std::size_t i = 0; i < st.size(); ++i)
    {
      closest = std::min(
        { closest, static_cast<double>(st.x[i]), static_cast<double>(length - st.x[i]), static_cast<double>(st.z[i]) });
      if (s.time() > duration - 1.0 - 1e-9)
      {
        const double speed =
          std::sqrt(double(st.vx[i]) * st.vx[i] + double(st.vy[i]) * st.vy[i] + double(st.vz[i]) * st.vz[i]);
        r.largestSpeed = std::max(r.largestSpeed, speed / reference);
      }
    }
  }
  r.cost.seconds = timer.seconds();
  r.closestToWall = closest / d;
  const auto& st = s.state();
  for (std::size_t i = 0; i < st.size(); ++i)
  {
    const auto id = static_cast<std::size_t>(st.id[i]);
    r.highestDrift = std::max(r.highestDrift, std::hypot(double(st.x[i]) - x0[id], double(st.z[i]) - z0[id]) / d);
  }
  const std::vector<float> pressure = s.smoothedPressure();
  std::vector<double> byId(st.size());
  for (std::size_t i = 0; i < st.size(); ++i)
  {
    byId[static_cast<std::size_t>(st.id[i])] = pressure[i];
  }
  r.pressureError = hydrostaticError(s.state(), byId, depth, d, nullptr, solverName(solver), across).total;
  return r;
}
} // namespace parafluid::validation
