// Turbulent wall shear on the box walls (SPHParameters::wallFriction == LogLaw; see
// private/LogLawFriction.h).
#include "parafluid/sph/SPHSolver.h"

#include "private/LogLawFriction.h"
#include "private/NeighbourCandidates.h"

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
  const detail::LogLawWalls walls = detail::logLawWalls(p, this->ParticleSpacing);
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const float position[3] = { s.x[i], s.y[i], s.z[i] };
    float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
    detail::brakeAtWalls(position, velocity, dt, walls);
    s.vx[i] = velocity[0];
    s.vy[i] = velocity[1];
    s.vz[i] = velocity[2];
  }
}
} // namespace parafluid::sph
