#pragma once
// Internal to δ-SPH: the formulas of particle shifting (DeltaSPHShifting.cxx) that every backend
// evaluates, one particle at a time (Lind et al. 2012, with δ+-SPH's coefficient, Sun et al. 2017).
#include "parafluid/common/HostDevice.h"
#include "private/DeltaSPHPairs.h"

#include <cmath>

namespace parafluid::sph::delta
{
/// A pair's weight in the concentration gradient: (dW/dr)/r (1 + 0.2 (W_ij / W(dp))^4). (Builtins
/// only, always inlined: the CPU's AVX-512 pair loop calls it.)
PARAFLUID_HOST_DEVICE __attribute__((always_inline)) inline float shiftingWeight(const WendlandPair& pair,
                                                                                 float inverseWSpacing)
{
  const float f = pair.value * inverseWSpacing;
  const float f2 = f * f;
  return pair.gradient * (1.0f + 0.2f * f2 * f2);
}

/// A particle's shift from its kernel sum and concentration gradient g: none at a free surface
/// (volume times the kernel sum below 0.9: the gradient points out of the fluid), else
/// -diffusion g, at most `limit` long.
PARAFLUID_HOST_DEVICE inline void particleShift(float kernelSum, const float g[3], float volume, float diffusion,
                                                float limit, float shift[3])
{
  if (volume * kernelSum < 0.9f)
  {
    shift[0] = shift[1] = shift[2] = 0.0f;
    return;
  }
  const float s[3] = { -diffusion * g[0], -diffusion * g[1], -diffusion * g[2] };
  const float length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  const float scale = length > limit ? limit / length : 1.0f;
  for (int a = 0; a < 3; ++a)
  {
    shift[a] = scale * s[a];
  }
}

/// x + shift along an axis of the box [lo, hi]: through a periodic axis's faces, else kept
/// `margin` inside the walls.
PARAFLUID_HOST_DEVICE inline float shiftedCoordinate(float x, float shift, float lo, float hi, bool periodic,
                                                     float margin)
{
  float y = x + shift;
  if (periodic)
  {
    const float length = hi - lo;
    return y < lo ? y + length : (y >= hi ? y - length : y);
  }
  y = y < lo + margin ? lo + margin : y;
  return y > hi - margin ? hi - margin : y;
}
} // namespace parafluid::sph::delta
