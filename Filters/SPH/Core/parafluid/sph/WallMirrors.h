#pragma once
// Mirror images of the fluid across the walls of an axis-aligned box. A particle within h of a wall
// sees, besides its neighbours, their reflections (and reflections across two or three walls in
// edges and corners). A lattice at rest mirrors into a perfect lattice, so water rests on a floor
// at exactly rest density, and the particle's own image pushes it off the wall.
//
// What an image's velocity is depends on the wall's condition (only the viscous term sees it):
//  - free-slip: the mirrored velocity, normal component reversed; no tangential stress;
//  - no-slip: the reversed velocity -v (Morris et al. 1997 ghost particles), so the velocity
//    interpolated between a particle and its image is zero on the wall and viscosity drags the
//    fluid there, as a real floor does. The normal component is reversed either way, so the wall
//    is equally impermeable.
//
// No extra neighbour search is needed: for i and j on the same side of a plane,
// |x_i − R x_j| >= |x_i − x_j|, so every image within h of i belongs to an ordinary neighbour.
#include "parafluid/common/HostDevice.h"
#include "parafluid/sph/SPHParameters.h"

#include <array>

namespace parafluid::sph
{
struct WallMirrors
{
  /// Image k of a point p is scale[k] * p + offset[k], component-wise; the image of a velocity v
  /// is velocityScale[k] * v (equal to scale[k] when every wall crossed is free-slip).
  int count = 0;
  float scale[7][3];
  float offset[7][3];
  float velocityScale[7][3];

  /// The position of image k of point p.
  PARAFLUID_HOST_DEVICE void image(int k, const float p[3], float out[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      out[a] = scale[k][a] * p[a] + offset[k][a];
    }
  }

  /// Whether image k crosses a no-slip wall (its velocity is not simply mirrored).
  PARAFLUID_HOST_DEVICE bool noSlip(int k) const
  {
    return velocityScale[k][0] != scale[k][0] || velocityScale[k][1] != scale[k][1] ||
           velocityScale[k][2] != scale[k][2];
  }

  /// The images a particle at `position` needs: one per subset of the walls within h, taking on
  /// each axis only the nearer wall. noSlip flags the walls xmin, xmax, ymin, ymax, zmin, zmax;
  /// a periodic axis has no walls.
  PARAFLUID_HOST_DEVICE static WallMirrors around(const float position[3], const std::array<float, 6>& bounds, float h,
                                                  const std::array<bool, 6>& noSlip = {},
                                                  const std::array<bool, 3>& periodic = {})
  {
    WallMirrors m;
    int axes[3];
    float planes[3];
    bool sticky[3];
    int walls = 0;
    for (int a = 0; a < 3; ++a)
    {
      const float toLow = position[a] - bounds[2 * a];
      const float toHigh = bounds[2 * a + 1] - position[a];
      if (!periodic[a] && (toLow < h || toHigh < h))
      {
        axes[walls] = a;
        planes[walls] = toLow <= toHigh ? bounds[2 * a] : bounds[2 * a + 1];
        sticky[walls] = noSlip[toLow <= toHigh ? 2 * a : 2 * a + 1];
        ++walls;
      }
    }
    for (int subset = 1; subset < (1 << walls); ++subset)
    {
      float* s = m.scale[m.count];
      float* o = m.offset[m.count];
      float* v = m.velocityScale[m.count];
      s[0] = s[1] = s[2] = 1.0f;
      o[0] = o[1] = o[2] = 0.0f;
      v[0] = v[1] = v[2] = 1.0f;
      for (int b = 0; b < walls; ++b)
      {
        if (subset & (1 << b))
        {
          s[axes[b]] = -1.0f;
          o[axes[b]] = 2.0f * planes[b];
          // Images across several walls compose: free-slip reverses the normal, no-slip all.
          if (sticky[b])
          {
            v[0] = -v[0];
            v[1] = -v[1];
            v[2] = -v[2];
          }
          else
          {
            v[axes[b]] = -v[axes[b]];
          }
        }
      }
      ++m.count;
    }
    return m;
  }

  /// The images of the simulation's box walls (no-slip ones only when withNoSlip: the terms that
  /// see velocities).
  static WallMirrors around(const float position[3], const SPHParameters& p, bool withNoSlip = false)
  {
    return around(position, p.domainBounds, p.smoothingLength, withNoSlip ? p.noSlipWalls() : std::array<bool, 6>{},
                  p.periodic);
  }
};
} // namespace parafluid::sph
