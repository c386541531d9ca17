#pragma once
// δ-SPH's free-surface detection: how full a particle's neighbourhood is (its first moment against
// a full lattice's) and how far inside the fluid it lies, from the sums of the continuity pass.
// The density diffusion, the push's high pass and the gradient correction read them.
#include "private/GradientCorrection.h"

namespace parafluid::sph::delta
{
struct SurfaceMeasure
{
  // 1 inside the fluid, 0 in the first two layers under a free surface (detail::neighbourhoodFullness).
  float fullness;
  // Its fullness times the smallest of its neighbours' (a step old): 1 where no surface is within
  // a kernel of it or of any of them. (A particle two spacings under a surface has a full first
  // moment but a cut kernel, whose G is the surface's push, which the high pass must keep.)
  float interior;
};

/// The measure of a particle whose queries' first moments summed to `moment` (xx, xy, xz, yy, yz,
/// zz) and whose neighbours' smallest fullness was `leastNeighbourFullness`; C is the lattice's
/// gradient correction.
PARAFLUID_HOST_DEVICE inline SurfaceMeasure measureSurface(const float moment[6], float leastNeighbourFullness,
                                                           float pressureCorrection)
{
  SurfaceMeasure m;
  m.fullness = detail::neighbourhoodFullness(moment, pressureCorrection);
  m.interior = m.fullness * leastNeighbourFullness;
  return m;
}
} // namespace parafluid::sph::delta
