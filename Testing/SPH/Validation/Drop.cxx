// A weightless water drop oscillating under its surface tension, against Rayleigh (1879).
#include "SPHScenes.h"
#include "SceneTimer.h"

#include "parafluid/common/MathConstants.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHSolver.h"

#include <cmath>
#include <vector>

namespace parafluid::validation
{
using sph::PressureSolverType;

namespace
{
/// (<x^2> - <y^2>) / (<x^2> + <y^2>) about the centre: the drop's l = 2 deformation along x.
double elongation(const ParticleState& s)
{
  double c[2] = { 0.0, 0.0 };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    c[0] += s.x[i];
    c[1] += s.y[i];
  }
  c[0] /= static_cast<double>(s.size());
  c[1] /= static_cast<double>(s.size());
  double xx = 0.0, yy = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    xx += (s.x[i] - c[0]) * (s.x[i] - c[0]);
    yy += (s.y[i] - c[1]) * (s.y[i] - c[1]);
  }
  return (xx - yy) / (xx + yy);
}
} // namespace

Drop oscillatingDrop(PressureSolverType solver, int across, std::ostream* curves, sph::SurfaceTensionModel model,
                     double stretch, double duration, sph::Backend backend)
{
  const double radius = 2.5e-3, spacing = radius / across;
  const auto box = static_cast<float>(4.0 * radius);
  sph::SPHParameters p = water(solver, static_cast<float>(spacing), { -box, box, -box, box, -box, box });
  p.gravity = { 0.0f, 0.0f, 0.0f };
  p.surfaceTension = kWaterSurfaceTension;
  p.surfaceTensionModel = model;
  // The lattice's sphere, stretched along x and squeezed across with its volume kept.
  auto l = fillBoxWithLattice({ -radius, radius, -radius, radius, -radius, radius }, spacing);
  std::vector<float> x, y, z;
  const double along = 1.0 + stretch, across2 = 1.0 / std::sqrt(along);
  for (std::size_t i = 0; i < l.x.size(); ++i)
  {
    if (l.x[i] * l.x[i] + l.y[i] * l.y[i] + l.z[i] * l.z[i] <= radius * radius)
    {
      x.push_back(static_cast<float>(l.x[i] * along));
      y.push_back(static_cast<float>(l.y[i] * across2));
      z.push_back(static_cast<float>(l.z[i] * across2));
    }
  }
  // Rayleigh's period for the drop's own radius (the lattice's sphere is not exactly 2.5 mm):
  // omega^2 = l (l - 1) (l + 2) sigma / (rho R^3) = 8 sigma / (rho R^3) for l = 2.
  const double volume = static_cast<double>(x.size()) * spacing * spacing * spacing;
  const double r0 = std::cbrt(3.0 * volume / (4.0 * kPi));
  Drop r;
  r.rayleigh = 2.0 * kPi / std::sqrt(8.0 * kWaterSurfaceTension / (kRho0 * r0 * r0 * r0));
  const auto s =
    sph::makeSimulation(p, ParticleState::atRest(std::move(x), std::move(y), std::move(z)), nullptr, backend);
  r.cost.particles = static_cast<long long>(s->particleCount());
  // The period from the zero crossings of the elongation, read every 0.2 ms (1/160 of a period).
  const double dt = 2e-4;
  std::vector<double> crossings;
  double previous = elongation(s->hostState());
  const SceneTimer timer;
  for (int k = 1; k * dt <= duration + 1e-9; ++k)
  {
    r.cost.steps += s->advance(dt);
    r.largestDensity = std::max(r.largestDensity, static_cast<double>(s->lastStep().maxDensityRatio));
    const double now = elongation(s->hostState());
    if (curves)
    {
      *curves << solverName(solver) << "," << across << "," << k * dt << "," << now << "\n";
    }
    if ((previous > 0.0) != (now > 0.0))
    {
      crossings.push_back((k - 1) * dt + dt * previous / (previous - now));
    }
    previous = now;
  }
  r.cost.seconds = timer.seconds();
  r.crossings = static_cast<int>(crossings.size());
  if (crossings.size() >= 3)
  {
    r.period = 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    r.periodError = std::fabs(r.period - r.rayleigh) / r.rayleigh;
    r.sigmaRatio = (r.rayleigh / r.period) * (r.rayleigh / r.period);
  }
  return r;
}
} // namespace parafluid::validation
