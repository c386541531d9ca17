// Turbulent wall shear on the box walls (SPHParameters::wallFriction == LogLaw).
//
// The particles within one spacing s of a wall stand for the fluid layer above its unresolved
// boundary layer. The wall's shear stress tau = rho u*^2, with u* from the law of the wall at the
// particle's tangential speed, acts on the particle's share of the wall, s^2, so it decelerates
// the particle (mass rho s^3) at u*^2 / s against its tangential velocity. Per unit of wall area
// the force does not depend on s, so the braking converges with resolution.
//
// The update is implicit in the speed, v_t <- v_t / (1 + dt u*^2 / (|v_t| s)): it can stop a
// particle but never reverse it, whatever the step.
#include "parafluid/sph/SPHSolver.h"

#include "parafluid/sph/TurbulentWallLaw.h"
#include "private/NeighbourCandidates.h"

#include <algorithm>
#include <cmath>

namespace parafluid::sph
{
using detail::threadCount;

void SPHSolver::applyWallFriction(float dt)
{
  const SPHParameters& p = this->Parameters;
  if (p.wallFriction != WallFriction::LogLaw || dt <= 0.0f)
  {
    return;
  }
  ParticleState& s = this->State;
  const auto n = static_cast<std::int64_t>(s.size());
  const float spacing = this->ParticleSpacing;
  const float nu = p.wallKinematicViscosity;
  const auto& b = p.domainBounds;
  float* position[3] = { s.x.data(), s.y.data(), s.z.data() };
  float* velocity[3] = { s.vx.data(), s.vy.data(), s.vz.data() };
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < n; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      const float toLow = position[a][i] - b[2 * a];
      const float toHigh = b[2 * a + 1] - position[a][i];
      const int wall = toLow <= toHigh ? 2 * a : 2 * a + 1;
      const float distance = std::min(toLow, toHigh);
      if (p.periodic[a] || !p.frictionWalls[wall] || distance >= spacing)
      {
        continue;
      }
      const int t0 = (a + 1) % 3, t1 = (a + 2) % 3;
      const float u0 = velocity[t0][i], u1 = velocity[t1][i];
      const float speed = std::sqrt(u0 * u0 + u1 * u1);
      if (speed == 0.0f)
      {
        continue;
      }
      // The particle's velocity is its layer's, centred half a spacing off the wall; one pressed
      // closer is still measured there, so crowding against a wall does not inflate the stress.
      const float y = std::max(distance, 0.5f * spacing);
      const float ustar = TurbulentWallLaw::frictionVelocity(speed, y, nu);
      const float keep = 1.0f / (1.0f + dt * ustar * ustar / (speed * spacing));
      velocity[t0][i] = keep * u0;
      velocity[t1][i] = keep * u1;
    }
  }
}
} // namespace parafluid::sph
