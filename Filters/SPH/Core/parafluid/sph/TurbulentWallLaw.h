#pragma once
// The smooth-wall law of the wall for turbulent flow (von Kármán 1930; the constants of Launder &
// Spalding 1974): with the friction velocity u* = sqrt(tau_w / rho) and y+ = y u* / nu,
//   u / u* = y+                       in the viscous sublayer (y+ below about 11),
//   u / u* = ln(y+) / kappa + B       in the log layer.
// A particle sitting a distance y off a wall with tangential speed u can then be given the shear
// stress the wall exerts on the unresolved boundary layer beneath it, from water's molecular
// viscosity, with no tuned coefficient.
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
  static float frictionVelocity(float speed, float distance, float kinematicViscosity);
};
} // namespace parafluid::sph
