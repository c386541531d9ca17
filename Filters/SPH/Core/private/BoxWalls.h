#pragma once
// Internal to the SPH solver: a particle's move along one axis of the axis-aligned box, as every
// backend's drift makes it.
#include "parafluid/common/HostDevice.h"

#include <cmath>

namespace parafluid::sph::detail
{
/// x += dt v along an axis of the box [lo, hi]. Through a periodic axis's face and back in through
/// the opposite one (fmod keeps a far jump inside too); else a damped reflection: the overshoot is
/// mirrored back inside and the normal velocity reversed and scaled by the restitution, so walls
/// take energy out instead of adding it. Not clamped onto the wall: a particle on the plane would
/// coincide with its own mirror image, which then could not push it.
PARAFLUID_HOST_DEVICE inline void moveAlongAxis(float& x, float& v, float dt, float lo, float hi, bool periodic,
                                                float restitution)
{
  float xa = x + dt * v;
  float va = v;
  if (periodic)
  {
    const float length = hi - lo;
    xa = lo + fmodf(xa - lo, length);
    xa = xa < lo ? xa + length : (xa >= hi ? xa - length : xa);
  }
  else if (xa < lo)
  {
    const float back = lo + restitution * (lo - xa);
    xa = back < hi ? back : hi;
    va = va < 0.0f ? -restitution * va : va;
  }
  else if (xa > hi)
  {
    const float back = hi - restitution * (xa - hi);
    xa = back > lo ? back : lo;
    va = va > 0.0f ? -restitution * va : va;
  }
  x = xa;
  v = va;
}
} // namespace parafluid::sph::detail
