#pragma once
// Fixed-radius neighbour queries at arbitrary points (not only at the particles): a NeighbourGrid
// with cells of the search radius over the particles, plus their positions in sorted order so a
// query reads contiguous memory. Used to interpolate particle fields along flow lines and to sum
// over a particle's neighbours when classifying foam.
#include "parafluid/common/NeighbourGrid.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid
{
class ParticleNeighbourhood
{
public:
  /// Indexes n particles (x, y, z interleaved) for queries of radius `radius` [m]. Throws
  /// std::invalid_argument (from NeighbourGrid) for a bad radius or NaN/infinite positions.
  void build(const float* xyz, std::size_t n, float radius);

  std::size_t size() const { return this->Sorted.size() / 3; }
  float radius() const { return this->Radius; }

  /// Calls visit(j, ex, ey, ez, r2) for every particle j (its index in the array given to build)
  /// within the radius of p, with (ex, ey, ez) = x_j - p and r2 its squared length [m^2].
  template<class Visit>
  void forEachNear(const float p[3], Visit&& visit) const
  {
    // A NaN or infinite query point has no neighbours (and must not reach the float-to-int cast
    // below: NaN survives min/max and its conversion is undefined).
    if (this->Sorted.empty() || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return;
    }
    int c[3];
    for (int a = 0; a < 3; ++a)
    {
      // Clamped to the grid: a point outside it within the radius of a particle still finds it in
      // the edge cell's neighbourhood, and one further out finds nothing.
      const float cell = std::floor((p[a] - this->Grid.origin()[a]) / this->Radius);
      c[a] = static_cast<int>(std::min(std::max(cell, 0.0f), static_cast<float>(this->Grid.dimension(a) - 1)));
    }
    const float r2max = this->Radius * this->Radius;
    const std::vector<std::uint32_t>& order = this->Grid.sortedOrder();
    this->Grid.forEachNeighbourRange(c[0], c[1], c[2],
                                     [&](std::uint32_t begin, std::uint32_t end)
                                     {
                                       for (std::uint32_t k = begin; k < end; ++k)
                                       {
                                         const float ex = this->Sorted[3 * k] - p[0],
                                                     ey = this->Sorted[3 * k + 1] - p[1],
                                                     ez = this->Sorted[3 * k + 2] - p[2];
                                         const float r2 = ex * ex + ey * ey + ez * ez;
                                         if (r2 < r2max)
                                         {
                                           visit(order[k], ex, ey, ez, r2);
                                         }
                                       }
                                     });
  }

private:
  NeighbourGrid Grid;
  std::vector<float> Sorted;
  float Radius = 1.0f;
};
} // namespace parafluid
