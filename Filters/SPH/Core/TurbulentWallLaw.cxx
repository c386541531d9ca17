#include "parafluid/sph/TurbulentWallLaw.h"

#include <cmath>

namespace parafluid::sph
{
float TurbulentWallLaw::sublayerEdge()
{
  // Fixed point of y+ = ln(y+)/kappa + B, converging from above (about 11.0 for these constants).
  static const float edge = []
  {
    double y = 20.0;
    for (int k = 0; k < 60; ++k)
    {
      y = std::log(y) / kappa + logIntercept;
    }
    return static_cast<float>(y);
  }();
  return edge;
}

float TurbulentWallLaw::frictionVelocity(float speed, float distance, float kinematicViscosity)
{
  const double u = std::fabs(static_cast<double>(speed));
  if (u == 0.0)
  {
    return 0.0f;
  }
  const double y = distance, nu = kinematicViscosity;
  // Sublayer: u = u*^2 y / nu.
  const double laminar = std::sqrt(u * nu / y);
  if (laminar * y / nu <= sublayerEdge())
  {
    return static_cast<float>(laminar);
  }
  // Log layer: solve f(u*) = u* (ln(y u*/nu)/kappa + B) - u = 0 by Newton's method. f is increasing
  // and convex wherever it is used (f'' = 1/(kappa u*)), so the first Newton step lands above the
  // root and the following ones descend onto it monotonically.
  double ustar = laminar;
  for (int k = 0; k < 30; ++k)
  {
    const double profile = std::log(y * ustar / nu) / kappa + logIntercept;
    const double f = ustar * profile - u;
    const double slope = profile + 1.0 / kappa;
    const double next = ustar - f / slope;
    if (std::fabs(next - ustar) <= 1e-7 * ustar)
    {
      ustar = next;
      break;
    }
    ustar = next;
  }
  return static_cast<float>(ustar);
}
} // namespace parafluid::sph
