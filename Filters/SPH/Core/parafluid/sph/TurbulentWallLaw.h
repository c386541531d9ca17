#pragma once
// The smooth-wall law of the wall for turbulent flow (von Kármán 1930; the constants of Launder &
// Spalding 1974): with the friction velocity u* = sqrt(tau_w / rho) and y+ = y u* / nu,
//   u / u* = y+                       in the viscous sublayer (y+ below about 11),
//   u / u* = ln(y+) / kappa + B       in the log layer.
// A particle sitting a distance y off a wall with tangential speed u can then be given the shear
// stress the wall exerts on the unresolved boundary layer beneath it, from water's molecular
// viscosity, with no tuned coefficient.
#include "parafluid/common/HostDevice.h"

#include <cmath>

namespace parafluid::sph
{
struct TurbulentWallLaw
{
  static constexpr float kappa = 0.41f;       // von Kármán constant
  static constexpr float logIntercept = 5.2f; // B, hydraulically smooth wall
  /// y+ where the sublayer and log-layer profiles meet (y+ = ln(y+)/kappa + B).
  static float sublayerEdge();

  /// u* [m/s] for a tangential speed u [m/s] measured y [m] off the wall in a fluid of kinematic
  /// viscosity nu [m^2/s]; 0 when u is 0. Requires y > 0, nu > 0.
  static float frictionVelocity(float speed, float distance, float kinematicViscosity)
  {
    return frictionVelocity(speed, distance, kinematicViscosity, sublayerEdge());
  }
  /// The same, given sublayerEdge() (which a GPU thread cannot compute once and keep).
  PARAFLUID_HOST_DEVICE static float frictionVelocity(float speed, float distance, float kinematicViscosity, float edge)
  {
    const double u = std::fabs(static_cast<double>(speed));
    if (u == 0.0)
    {
      return 0.0f;
    }
    const double y = distance, nu = kinematicViscosity;
    // Sublayer: u = u*^2 y / nu.
    const double laminar = std::sqrt(u * nu / y);
    if (laminar * y / nu <= edge)
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
};
} // namespace parafluid::sph
