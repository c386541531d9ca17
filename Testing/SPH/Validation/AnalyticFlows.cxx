// Flows with analytic solutions: the Taylor-Green vortex, Poiseuille flow and a standing wave.
#include "SPHScenes.h"
#include "SceneTimer.h"

#include "parafluid/common/MathConstants.h"
#include "parafluid/sph/SPHSolver.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace parafluid::validation
{
using sph::PressureSolverType;
using sph::SPHSolver;

TaylorGreen taylorGreen(PressureSolverType solver, int across, std::ostream* curves)
{
  const float L = 1.0f, U = 1.0f, nu = 0.01f; // Re = U L / nu = 100
  const float d = L / static_cast<float>(across);
  // Three smoothing lengths: the least a periodic axis may be.
  const float thickness = std::ceil(3.0f * kernelRatio(solver)) * d;
  sph::SPHParameters p = water(solver, d, { 0.0f, L, 0.0f, thickness, 0.0f, L });
  p.gravity = { 0.0f, 0.0f, 0.0f };
  p.periodic = { true, true, true };
  p.kinematicViscosity = nu;
  p.viscosity = 0.0f; // the flow's viscosity is the physical one, whatever the solver
  ParticleState state = lattice({ 0, L, 0, thickness, 0, L }, d);
  const double k = 2.0 * kPi / L;
  // The pressure of the vortex, p = rho0 U^2 / 4 (cos 2kx + cos 2kz), as a starting density for
  // the weakly compressible solver (c0 = 10 U); the others compute density themselves.
  const double c0 = 10.0 * U, bulk = c0 * c0 * kRho0 / 7.0;
  state.density.resize(state.size());
  for (std::size_t i = 0; i < state.size(); ++i)
  {
    const double x = state.x[i], z = state.z[i];
    state.vx[i] = static_cast<float>(U * std::sin(k * x) * std::cos(k * z));
    state.vz[i] = static_cast<float>(-U * std::cos(k * x) * std::sin(k * z));
    const double pressure = 0.25 * kRho0 * U * U * (std::cos(2 * k * x) + std::cos(2 * k * z));
    state.density[i] = static_cast<float>(kRho0 * std::pow(1.0 + pressure / bulk, 1.0 / 7.0));
  }
  p.soundSpeed = static_cast<float>(c0);
  p.particleShifting = true; // the vortex stretches the particle distribution (see SPHParameters.h)
  SPHSolver s(p, std::move(state));
  TaylorGreen r;
  r.cost.particles = static_cast<long long>(s.state().size());
  const double e0 = s.kineticEnergy();
  const double decayTime = L * L / (16.0 * kPi * kPi * nu); // energy falls by e
  const SceneTimer timer;
  const int samples = 25;
  for (int n = 1; n <= samples; ++n)
  {
    r.cost.steps += s.advance(decayTime / samples);
    const double ratio = s.kineticEnergy() / e0;
    const double exact = std::exp(-16.0 * kPi * kPi * nu * s.time() / (L * L));
    r.decayError = std::max(r.decayError, std::fabs(ratio - exact) / exact);
    if (curves)
    {
      *curves << solverName(solver) << "," << across << "," << s.time() << "," << ratio << "," << exact << "\n";
    }
  }
  r.cost.seconds = timer.seconds();
  return r;
}

Poiseuille poiseuille(PressureSolverType solver, int across, std::ostream* curves)
{
  const float H = 0.1f, nu = 0.01f, peak = 0.01f; // Re = peak H / nu = 0.1
  const float d = H / static_cast<float>(across);
  const float thickness = std::ceil(3.0f * kernelRatio(solver)) * d, length = 2.0f * thickness;
  sph::SPHParameters p = water(solver, d, { 0.0f, length, 0.0f, thickness, 0.0f, H });
  const float force = 8.0f * nu * peak / (H * H); // u(z) = force / (2 nu) z (H - z)
  p.gravity = { force, 0.0f, 0.0f };
  p.periodic = { true, true, false };
  p.kinematicViscosity = nu;
  p.viscosity = 0.0f;
  p.wallFriction = sph::WallFriction::NoSlip;
  p.frictionWalls = { false, false, false, false, true, true };
  SPHSolver s(p, lattice({ 0, length, 0, thickness, 0, H }, d));
  Poiseuille r;
  r.cost.particles = static_cast<long long>(s.state().size());
  const SceneTimer timer;
  // Start-up decays as exp(-pi^2 nu t / H^2): after H^2 / nu it is below 1e-4 of the flow.
  long long iterations = 0;
  const double end = H * H / nu;
  while (s.time() < end - 1e-12)
  {
    s.step(end - s.time());
    ++r.cost.steps;
    iterations += s.lastStep().viscosityIterations;
  }
  r.cost.seconds = timer.seconds();
  r.viscosityIterations = static_cast<int>(iterations / std::max(1LL, r.cost.steps));
  std::vector<double> sum(static_cast<std::size_t>(across), 0.0), height(sum.size(), 0.0);
  std::vector<int> count(sum.size(), 0);
  const auto& st = s.state();
  for (std::size_t i = 0; i < st.size(); ++i)
  {
    const auto layer = std::min(sum.size() - 1, static_cast<std::size_t>(std::max(0.0f, st.z[i] / d)));
    sum[layer] += st.vx[i];
    height[layer] += st.z[i];
    ++count[layer];
  }
  for (std::size_t l = 0; l < sum.size(); ++l)
  {
    if (count[l] == 0)
    {
      continue;
    }
    const double z = height[l] / count[l], u = sum[l] / count[l];
    const double exact = force / (2.0 * nu) * z * (H - z);
    r.profileError = std::max(r.profileError, std::fabs(u - exact) / peak);
    if (curves)
    {
      *curves << solverName(solver) << "," << across << "," << z << "," << u << "," << exact << "\n";
    }
  }
  return r;
}

StandingWave standingWave(PressureSolverType solver, int across, std::ostream* curves, sph::Backend backend)
{
  const float L = 1.0f, h = 0.5f, A = 0.01f;
  const float d = h / static_cast<float>(across);
  const double k = kPi / L;
  const double omega = std::sqrt(kGravity * k * std::tanh(k * h));
  ParticleState state = lattice({ 0, L, 0, 4 * d, 0, h }, d);
  // Linear standing wave eta = A cos(k x) sin(omega t): at t = 0 the surface is flat and the
  // velocity is that of the potential phi = (A omega / k) cosh(k z) / sinh(k h) cos(k x).
  for (std::size_t i = 0; i < state.size(); ++i)
  {
    const double x = state.x[i], z = state.z[i];
    state.vx[i] = static_cast<float>(-A * omega * std::cosh(k * z) / std::sinh(k * h) * std::sin(k * x));
    state.vz[i] = static_cast<float>(A * omega * std::sinh(k * z) / std::sinh(k * h) * std::cos(k * x));
  }
  const auto s =
    sph::makeSimulation(water(solver, d, { 0.0f, L, 0.0f, 4 * d, 0.0f, 2.0f * h }), std::move(state), nullptr, backend);
  StandingWave r;
  r.cost.particles = static_cast<long long>(s->hostState().size());
  r.exact = omega;
  auto centre = [&]()
  {
    double sum = 0.0;
    for (float x : s->hostState().x)
    {
      sum += x;
    }
    return sum / static_cast<double>(s->hostState().size()) - 0.5 * L;
  };
  const SceneTimer timer;
  const double interval = 0.005, end = 2.5 * 2.0 * kPi / omega; // two and a half periods
  std::vector<double> times, centres;
  while (s->time() < end - 1e-12)
  {
    r.cost.steps += s->advance(interval);
    times.push_back(s->time());
    centres.push_back(centre());
    if (curves)
    {
      *curves << solverName(solver) << "," << across << "," << s->time() << "," << centres.back() << "\n";
    }
  }
  // Zero crossings with hysteresis: a crossing counts only after the signal went beyond a third of
  // its amplitude on the other side, so particle-scale jitter around zero adds none.
  double amplitude = 0.0;
  for (double c : centres)
  {
    amplitude = std::max(amplitude, std::fabs(c));
  }
  std::vector<double> crossings;
  int side = 0; // sign of the last excursion beyond the threshold
  for (std::size_t k = 1; k < centres.size(); ++k)
  {
    const double c = centres[k];
    if (std::fabs(c) > amplitude / 3.0)
    {
      const int now = c > 0.0 ? 1 : -1;
      if (side != 0 && now != side)
      {
        // The last sign change before this point is the crossing.
        std::size_t j = k;
        while (j > 1 && (centres[j - 1] > 0.0) == (c > 0.0))
        {
          --j;
        }
        const double a = centres[j - 1], b = centres[j];
        crossings.push_back(times[j - 1] + (times[j] - times[j - 1]) * a / (a - b));
      }
      side = now;
    }
  }
  r.cost.seconds = timer.seconds();
  // The centre of mass crosses its rest position twice a period (x_c ~ sin(omega t)).
  if (crossings.size() >= 2)
  {
    const double halfPeriod = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    r.frequency = kPi / halfPeriod;
    r.frequencyError = std::fabs(r.frequency - omega) / omega;
  }
  else
  {
    r.frequencyError = 1.0;
  }
  return r;
}
} // namespace parafluid::validation
