// Fluid at rest: the hydrostatic column and still water in a tank.
#include "SPHScenes.h"
#include "SceneTimer.h"

#include "parafluid/sph/SPHSolver.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace parafluid::validation
{
using sph::PressureSolverType;
using sph::SPHSolver;

namespace
{
/// Relative L2 error of the given per-id pressures against rho0 g (surface - z).
double hydrostaticError(const SPHSolver& s, const std::vector<double>& pressureById, double surface,
                        std::ostream* profile, const char* solver, int across)
{
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < s.state().size(); ++i)
  {
    const auto id = static_cast<std::size_t>(s.state().id[i]);
    const double reference = kRho0 * kGravity * (surface - s.state().z[i]);
    num += (pressureById[id] - reference) * (pressureById[id] - reference);
    den += reference * reference;
    if (profile)
    {
      *profile << solver << "," << across << "," << s.state().z[i] << "," << pressureById[id] << "," << reference
               << "\n";
    }
  }
  return den > 0.0 ? std::sqrt(num / den) : 0.0;
}
} // namespace

Hydrostatic hydrostatic(PressureSolverType solver, int across, std::ostream* profile)
{
  const float width = 0.2f, height = 0.2f;
  const float d = width / static_cast<float>(across);
  const std::array<float, 6> domain = { 0.0f, width, 0.0f, 4 * d, 0.0f, 2.0f * height };
  SPHSolver s(water(solver, d, domain), lattice({ 0, width, 0, 4 * d, 0, height }, d));
  Hydrostatic r;
  r.cost.particles = static_cast<long long>(s.state().size());
  const SceneTimer timer;
  r.cost.steps += s.advance(0.4);
  std::vector<double> sum(s.state().size(), 0.0); // by id: the state is reordered every step
  const int samples = 40;
  for (int k = 0; k < samples; ++k)
  {
    r.cost.steps += s.advance(0.005);
    r.compression += s.lastStep().meanCompression / samples;
    const std::vector<float> pressure = s.smoothedPressure(); // what SPH Step outputs as "pressure"
    for (std::size_t i = 0; i < pressure.size(); ++i)
    {
      sum[static_cast<std::size_t>(s.state().id[i])] += pressure[i] / samples;
    }
  }
  r.cost.seconds = timer.seconds();
  r.error = hydrostaticError(s, sum, height, profile, solverName(solver), across);
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
  r.pressureError = hydrostaticError(s, byId, depth, nullptr, solverName(solver), across);
  return r;
}
} // namespace parafluid::validation
