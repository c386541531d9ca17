#pragma once
// Mirror images of the fluid across the walls of an axis-aligned box. A particle within h of a wall
// sees, besides its neighbours, their reflections (and reflections across two or three walls in
// edges and corners). A lattice at rest mirrors into a perfect lattice, so water rests on a floor
// at exactly rest density, and the particle's own image pushes it off the wall. Mirrored
// velocities have the normal component reversed: walls are free-slip.
//
// No extra neighbour search is needed: for i and j on the same side of a plane,
// |x_i − R x_j| >= |x_i − x_j|, so every image within h of i belongs to an ordinary neighbour.
#include <array>

namespace parafluid::sph
{
struct WallMirrors
{
  /// Image k of a point p is scale[k] * p + offset[k], component-wise.
  int count = 0;
  float scale[7][3];
  float offset[7][3];

  /// The images a particle at `position` needs: one per subset of the walls within h, taking on
  /// each axis only the nearer wall.
  static WallMirrors around(const float position[3], const std::array<float, 6>& bounds, float h)
  {
    WallMirrors m;
    int axes[3];
    float planes[3];
    int walls = 0;
    for (int a = 0; a < 3; ++a)
    {
      const float toLow = position[a] - bounds[2 * a];
      const float toHigh = bounds[2 * a + 1] - position[a];
      if (toLow < h || toHigh < h)
      {
        axes[walls] = a;
        planes[walls] = toLow <= toHigh ? bounds[2 * a] : bounds[2 * a + 1];
        ++walls;
      }
    }
    for (int subset = 1; subset < (1 << walls); ++subset)
    {
      float* s = m.scale[m.count];
      float* o = m.offset[m.count];
      s[0] = s[1] = s[2] = 1.0f;
      o[0] = o[1] = o[2] = 0.0f;
      for (int b = 0; b < walls; ++b)
      {
        if (subset & (1 << b))
        {
          s[axes[b]] = -1.0f;
          o[axes[b]] = 2.0f * planes[b];
        }
      }
      ++m.count;
    }
    return m;
  }
};
} // namespace parafluid::sph
