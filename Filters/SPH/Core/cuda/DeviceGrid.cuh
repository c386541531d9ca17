#pragma once
// Internal to the CUDA backend: the uniform grid of cells half a support radius wide that the state
// is sorted by, and the loop over the particles within reach of a position as contiguous ranges of
// the sorted arrays (no stored neighbour lists): the rows of cells within the support, each cut to
// the cells the support spans along x, test half the candidates that cells a support wide would.
#include <cstdint>

namespace parafluid::sph::cuda
{
/// d = q - (x_j + shift), the offset from neighbour j (shifted by forEachNeighbour's periodic
/// shift) to the query q; returns |d|^2.
__device__ inline float offsetFrom(const float* x, const float* y, const float* z, std::uint32_t j, const float* shift,
                                   const float q[3], float d[3])
{
  d[0] = q[0] - (__ldg(x + j) + shift[0]);
  d[1] = q[1] - (__ldg(y + j) + shift[1]);
  d[2] = q[2] - (__ldg(z + j) + shift[2]);
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

struct DeviceGrid
{
  float origin[3];      // the lower corner of cell (0, 0, 0) [m]
  float cell[3];        // the cells' edge [m], at least half the support radius
  float inverseCell[3]; // 1 / cell
  int cells[3];
  bool periodic[3];
  float period[3]; // [m], on a periodic axis
  // First sorted particle of each cell, cells + 1 entries: cell c holds [cellStart[c], cellStart[c + 1]).
  const std::uint32_t* cellStart;

  __host__ __device__ std::uint64_t cellCount() const
  {
    return static_cast<std::uint64_t>(cells[0]) * cells[1] * cells[2];
  }
  float reach; // the support radius h [m]
  /// The cell of coordinate x along axis a, clamped into the grid (whose box is the particles' with
  /// a support's margin, so a particle leaves it only by a far jump, and then lies in its edge cell).
  __device__ int coordinate(int a, float x) const
  {
    const int c = static_cast<int>(floorf((x - origin[a]) * inverseCell[a]));
    return c < 0 ? 0 : (c >= cells[a] ? cells[a] - 1 : c);
  }
  __device__ std::uint32_t index(int ix, int iy, int iz) const
  {
    return static_cast<std::uint32_t>(ix + cells[0] * (iy + cells[1] * iz));
  }
  __device__ std::uint32_t cellOf(float x, float y, float z) const
  {
    return index(coordinate(0, x), coordinate(1, y), coordinate(2, z));
  }

  /// f(j, d, r^2) for each particle j within sqrt(h2) of q (d = q - x_j, periodic images
  /// shifted), among the particles around `around` (forEachNeighbour).
  template<class F>
  __device__ void forEachWithin(const float* x, const float* y, const float* z, const float around[3], const float q[3],
                                float h2, F&& f) const
  {
    this->forEachNeighbour(around,
                           [&](std::uint32_t j, const float* shift)
                           {
                             float d[3];
                             const float rr = offsetFrom(x, y, z, j, shift, q, d);
                             if (rr < h2)
                             {
                               f(j, d, rr);
                             }
                           });
  }

  /// f(j, shift) for every particle j of the cells within the support radius of position p (a
  /// superset of its neighbours), shift [m] the period that j was reached across (added to x_j
  /// gives the nearest periodic image). Cells are at least h / 2 wide, so 5 along each axis hold
  /// every point within h; the rows whose y-z box is farther than h are skipped.
  template<class F>
  __device__ void forEachNeighbour(const float p[3], F&& f) const
  {
    const int c[3] = { coordinate(0, p[0]), coordinate(1, p[1]), coordinate(2, p[2]) };
    const float reach2 = reach * reach;
    for (int dz = -2; dz <= 2; ++dz)
    {
      const float gapZ = gap(2, c[2] + dz, p[2]);
      int iz = c[2] + dz;
      float sz = 0.0f;
      if (!(gapZ * gapZ < reach2) || !wrap(2, iz, sz))
      {
        continue;
      }
      for (int dy = -2; dy <= 2; ++dy)
      {
        const float gapY = gap(1, c[1] + dy, p[1]);
        int iy = c[1] + dy;
        float sy = 0.0f;
        if (!(gapY * gapY + gapZ * gapZ < reach2) || !wrap(1, iy, sy))
        {
          continue;
        }
        if (!periodic[0])
        {
          const int x0 = coordinate(0, p[0] - reach), x1 = coordinate(0, p[0] + reach);
          const float shift[3] = { 0.0f, sy, sz };
          const std::uint32_t end = cellStart[index(x1, iy, iz) + 1];
          for (std::uint32_t j = cellStart[index(x0, iy, iz)]; j < end; ++j)
          {
            f(j, shift);
          }
          continue;
        }
        for (int dx = -2; dx <= 2; ++dx)
        {
          int ix = c[0] + dx;
          float sx = 0.0f;
          wrap(0, ix, sx);
          const float shift[3] = { sx, sy, sz };
          const std::uint32_t cell = index(ix, iy, iz);
          const std::uint32_t end = cellStart[cell + 1];
          for (std::uint32_t j = cellStart[cell]; j < end; ++j)
          {
            f(j, shift);
          }
        }
      }
    }
  }

private:
  /// The distance along axis a from coordinate x to cell i's slab (i before any wrap) [m].
  __device__ float gap(int a, int i, float x) const
  {
    const float lo = origin[a] + static_cast<float>(i) * cell[a];
    const float hi = lo + cell[a];
    return x < lo ? lo - x : (x > hi ? x - hi : 0.0f);
  }
  /// Brings cell coordinate i along axis a into the grid across a periodic axis (shift gets the
  /// period crossed); false when it lies outside a non-periodic axis.
  __device__ bool wrap(int a, int& i, float& shift) const
  {
    if (i >= 0 && i < cells[a])
    {
      return true;
    }
    if (!periodic[a])
    {
      return false;
    }
    shift = i < 0 ? -period[a] : period[a];
    i = i < 0 ? i + cells[a] : i - cells[a];
    return true;
  }
};
} // namespace parafluid::sph::cuda
