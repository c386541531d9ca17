#include "parafluid/ocean/WaveDispersion.h"

#include <cmath>
#include <stdexcept>

namespace parafluid::ocean
{
double angularFrequency(double k, double depth, double gravity)
{
  const double depthFactor = std::isinf(depth) ? 1.0 : std::tanh(k * depth);
  return std::sqrt(gravity * k * depthFactor);
}

double phaseSpeed(double k, double depth, double gravity)
{
  return angularFrequency(k, depth, gravity) / k;
}

double shoalingWavenumberApproximation(double kDeep, double depth)
{
  if (std::isinf(depth))
  {
    return kDeep;
  }
  return kDeep / std::sqrt(std::tanh(kDeep * depth));
}

double shoalingWavenumber(double kDeep, double depth)
{
  if (!(depth > 0.0) || !(kDeep > 0.0))
  {
    throw std::invalid_argument("shoalingWavenumber: depth and wavenumber must be positive");
  }
  if (std::isinf(depth) || kDeep * depth > 20.0)
  {
    return kDeep; // tanh(20) = 1 - 8e-18: deep water to double precision
  }
  // Solve y tanh y = x for y = k h, x = kDeep h. f is increasing and convex for y > 0, so Newton
  // from the closed-form guess converges monotonically after the first step.
  const double x = kDeep * depth;
  double y = shoalingWavenumberApproximation(kDeep, depth) * depth;
  for (int iteration = 0; iteration < 50; ++iteration)
  {
    const double t = std::tanh(y);
    const double f = y * t - x;
    const double slope = t + y * (1.0 - t * t);
    const double next = y - f / slope;
    if (std::fabs(next - y) <= 1e-14 * y)
    {
      y = next;
      break;
    }
    y = next;
  }
  return y / depth;
}
} // namespace parafluid::ocean
