#pragma once
// Internal to the SPH solver: the law of the wall's braking of one particle near the box walls
// (SPHParameters::wallFriction == LogLaw), as every backend applies it after a step's last kick.
//
// The particles within one spacing s of a wall stand for the fluid layer above its unresolved
// boundary layer. The wall's shear stress tau = rho u*^2, with u* from the law of the wall at the
// particle's tangential speed, acts on the particle's share of the wall, s^2, so it decelerates
// the particle (mass rho s^3) at u*^2 / s against its tangential velocity. Per unit of wall area
// the force does not depend on s, so the braking converges with resolution. The update is implicit
// in the speed, v_t <- v_t / (1 + dt u*^2 / (|v_t| s)): it can stop a particle but never reverse it.
#include "parafluid/common/HostDevice.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/TurbulentWallLaw.h"

#include <cmath>

namespace parafluid::sph::detail
{
/// The walls that brake and how (SPHParameters: domainBounds, periodic, frictionWalls,
/// wallKinematicViscosity; the lattice spacing; TurbulentWallLaw::sublayerEdge()).
struct LogLawWalls
{
  float bounds[6];
  bool periodic[3];
  bool friction[6];
  float spacing, viscosity, sublayerEdge;
};

PARAFLUID_HOST_DEVICE inline void brakeAtWalls(const float position[3], float velocity[3], float dt,
                                               const LogLawWalls& w)
{
  for (int a = 0; a < 3; ++a)
  {
    const float toLow = position[a] - w.bounds[2 * a];
    const float toHigh = w.bounds[2 * a + 1] - position[a];
    const int wall = toLow <= toHigh ? 2 * a : 2 * a + 1;
    const float distance = toLow < toHigh ? toLow : toHigh;
    if (w.periodic[a] || !w.friction[wall] || distance >= w.spacing)
    {
      continue;
    }
    const int t0 = (a + 1) % 3, t1 = (a + 2) % 3;
    const float u0 = velocity[t0], u1 = velocity[t1];
    const float speed = std::sqrt(u0 * u0 + u1 * u1);
    if (speed == 0.0f)
    {
      continue;
    }
    // The particle's velocity is its layer's, centred half a spacing off the wall; one pressed
    // closer is still measured there, so crowding against a wall does not inflate the stress.
    const float y = distance > 0.5f * w.spacing ? distance : 0.5f * w.spacing;
    const float ustar = TurbulentWallLaw::frictionVelocity(speed, y, w.viscosity, w.sublayerEdge);
    const float keep = 1.0f / (1.0f + dt * ustar * ustar / (speed * w.spacing));
    velocity[t0] = keep * u0;
    velocity[t1] = keep * u1;
  }
}

/// The LogLawWalls of parameters p at lattice `spacing`.
inline LogLawWalls logLawWalls(const SPHParameters& p, float spacing)
{
  LogLawWalls w{};
  for (int k = 0; k < 6; ++k)
  {
    w.bounds[k] = p.domainBounds[k];
    w.friction[k] = p.frictionWalls[k];
  }
  for (int a = 0; a < 3; ++a)
  {
    w.periodic[a] = p.periodic[a];
  }
  w.spacing = spacing;
  w.viscosity = p.wallKinematicViscosity;
  w.sublayerEdge = TurbulentWallLaw::sublayerEdge();
  return w;
}
} // namespace parafluid::sph::detail
