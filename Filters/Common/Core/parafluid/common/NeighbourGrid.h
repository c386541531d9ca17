#pragma once
// Uniform grid for fixed-radius neighbour search. Particles are bucketed into cubic cells of edge
// `cellSize` (= the kernel radius h) over their bounding box by a counting sort on the linear cell
// index, so all particles of one cell, and of three x-adjacent cells, lie contiguously once the
// caller has permuted its arrays into sorted order. A query then visits 9 contiguous index ranges.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid
{
class NeighbourGrid
{
public:
  /// Buckets n particles. Throws std::invalid_argument for a non-positive cell size, non-finite
  /// coordinates, or a bounding box needing more cells than `maxCells()` allows for n particles.
  void build(const float* x, const float* y, const float* z, std::size_t n, float cellSize);

  /// sortedOrder()[k] is the index (in the arrays given to build) of the particle that goes to
  /// sorted slot k. The sort is stable: particles in one cell keep their relative order.
  const std::vector<std::uint32_t>& sortedOrder() const { return this->Order; }

  /// Particles of linear cell c occupy sorted slots [cellStart()[c], cellStart()[c + 1]).
  const std::vector<std::uint32_t>& cellStart() const { return this->CellStart; }

  int dimension(int axis) const { return this->Dims[axis]; }
  float cellSize() const { return this->CellSize; }
  /// Lower corner of the grid (the particles' bounding-box minimum).
  const float* origin() const { return this->Origin; }
  std::size_t cellCount() const { return this->CellStart.empty() ? 0 : this->CellStart.size() - 1; }
  std::size_t linearIndex(int ix, int iy, int iz) const
  {
    return static_cast<std::size_t>(ix) +
           static_cast<std::size_t>(this->Dims[0]) *
             (static_cast<std::size_t>(iy) + static_cast<std::size_t>(this->Dims[1]) * static_cast<std::size_t>(iz));
  }
  void cellCoordinates(std::size_t c, int& ix, int& iy, int& iz) const
  {
    ix = static_cast<int>(c % static_cast<std::size_t>(this->Dims[0]));
    const std::size_t rest = c / static_cast<std::size_t>(this->Dims[0]);
    iy = static_cast<int>(rest % static_cast<std::size_t>(this->Dims[1]));
    iz = static_cast<int>(rest / static_cast<std::size_t>(this->Dims[1]));
  }

  /// Calls f(begin, end) for each of the (up to 9) contiguous sorted ranges holding the particles of
  /// the 27 cells around cell (ix, iy, iz). Every particle within cellSize of a point in that cell
  /// is in one of these ranges.
  template<class F>
  void forEachNeighbourRange(int ix, int iy, int iz, F&& f) const
  {
    const int x0 = ix > 0 ? ix - 1 : 0;
    const int x1 = ix + 1 < this->Dims[0] ? ix + 1 : this->Dims[0] - 1;
    for (int dz = -1; dz <= 1; ++dz)
    {
      const int z = iz + dz;
      if (z < 0 || z >= this->Dims[2])
      {
        continue;
      }
      for (int dy = -1; dy <= 1; ++dy)
      {
        const int y = iy + dy;
        if (y < 0 || y >= this->Dims[1])
        {
          continue;
        }
        const std::uint32_t begin = this->CellStart[this->linearIndex(x0, y, z)];
        const std::uint32_t end = this->CellStart[this->linearIndex(x1, y, z) + 1];
        if (begin < end)
        {
          f(begin, end);
        }
      }
    }
  }

  /// The grid allows at most this many cells for n particles, so that a few far-flung particles
  /// cannot make it allocate gigabytes: 64 cells per particle plus 2^22.
  /// Bytes held by the grid's arrays.
  std::size_t bytes() const
  {
    return (this->Order.capacity() + this->CellStart.capacity() + this->ParticleCell.capacity()) *
           sizeof(std::uint32_t);
  }

  static std::size_t maxCells(std::size_t n) { return 64 * n + (std::size_t(1) << 22); }

private:
  int Dims[3] = { 0, 0, 0 };
  float Origin[3] = { 0.0f, 0.0f, 0.0f };
  float CellSize = 0.0f;
  std::vector<std::uint32_t> Order;
  std::vector<std::uint32_t> CellStart;
  std::vector<std::uint32_t> ParticleCell;
};
} // namespace parafluid
