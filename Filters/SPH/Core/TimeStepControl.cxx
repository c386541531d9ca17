// The SPH time-step control every backend uses (see TimeStepControl.h).
#include "parafluid/sph/TimeStepControl.h"

#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace parafluid::sph
{
double proposedTimeStep(const SPHParameters& p, const SolverEntry& solver, double signalSpeed, double fastest,
                        double largestAcceleration, float laplacianCorrection)
{
  if (!p.adaptiveTimeStep)
  {
    return p.timeStep;
  }
  const double h = p.smoothingLength;
  double dt = p.maxTimeStep;
  // CFL: information (sound for WCSPH, the flow itself for incompressible DFSPH) may cross only a
  // fraction lambda of the kernel radius per step.
  const double c = signalSpeed;
  const double speed = c + fastest;
  if (speed > 0.0)
  {
    dt = std::min(dt, p.cflNumber * h / speed);
  }
  if (p.viscosity > 0.0f && solver.separateExtraViscosity)
  {
    // Explicit diffusion is stable for dt nu S < 1, S the sum of Müller's Laplacian weights over a
    // neighbourhood: about 15 / h^2, up to twice that beside a wall's mirror images. Kept at 0.75.
    dt = std::min(dt, h * h * p.restDensity / (40.0 * p.viscosity));
  }
  // A solver without a term of its own for Müller's extra viscosity folds it into its laminar term.
  const double nu = p.kinematicViscosity + (solver.separateExtraViscosity ? 0.0 : p.viscosity / p.restDensity);
  if (nu > 0.0 && solver.explicitLaminarViscosity)
  {
    // The explicit laminar term: nu dt / (h/2)^2 <= 0.125 (Morris et al. 1997), with nu scaled by
    // the operator's lattice correction and halved again beside no-slip walls, whose images double
    // the term; an implicit one has no such limit.
    dt = std::min(dt, 0.015 * h * h / (nu * laplacianCorrection));
  }
  const double a = largestAcceleration;
  if (a > 0.0) // a particle may not move more than ~h/16 from its acceleration alone
  {
    dt = std::min(dt, 0.25 * std::sqrt(h / a));
  }
  if (p.surfaceTension > 0.0f) // capillary waves (Brackbill et al. 1992)
  {
    dt = std::min(dt, std::sqrt(p.restDensity * h * h * h / (2.0 * kPiF * p.surfaceTension)));
  }
  return dt;
}

double timeStepFor(const SPHParameters& p, double proposed, double remaining)
{
  const double dt = proposed;
  if (!p.adaptiveTimeStep)
  {
    // Fixed steps: equal steps that fit the remaining time exactly (TimeStep 2e-4 over 4e-3 s is
    // 20 steps of exactly 2e-4, whatever the float rounding of 2e-4).
    const double steps = std::max(1.0, std::ceil(remaining / dt - 1e-6));
    return remaining / steps;
  }
  // Land exactly on the end time without a sliver of a last step: split the last two evenly.
  if (remaining <= dt)
  {
    return remaining;
  }
  if (remaining < 2.0 * dt)
  {
    return 0.5 * remaining;
  }
  return dt;
}

void checkAdvanceDuration(double duration)
{
  if (!(duration >= 0.0) || !std::isfinite(duration))
  {
    throw std::invalid_argument("SPH: the time to advance must be a non-negative number of seconds");
  }
}

std::int64_t advanceInSteps(const SPHParameters& p, double& time, double duration,
                            const std::function<double(double)>& step, const std::function<bool(double)>& progress,
                            const std::function<std::string()>& advice)
{
  const double end = time + duration;
  std::int64_t taken = 0;
  // A step this much shorter than the longest allowed one means forces have blown up; stop rather
  // than crawl forever.
  const double smallest = 1e-7 * std::min(p.maxTimeStep, p.timeStep);
  while (time < end)
  {
    const double remaining = end - time;
    const double dt = step(remaining);
    ++taken;
    if (dt >= remaining)
    {
      time = end; // exactly, whatever the rounding of the sum
    }
    if (dt < smallest && dt < remaining)
    {
      throw std::runtime_error("SPH became unstable at t = " + std::to_string(time) +
                               " s: the adaptive time step fell to " + std::to_string(dt) + " s; " + advice());
    }
    if (progress && taken % 8 == 0 && !progress(duration > 0.0 ? 1.0 - (end - time) / duration : 1.0))
    {
      break;
    }
  }
  return taken;
}
} // namespace parafluid::sph
