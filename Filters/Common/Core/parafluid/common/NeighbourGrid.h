#pragma once
// Uniform grid for fixed-radius neighbour search. Particles are bucketed into cubic cells of edge
// `cellSize` (= the kernel radius h) over their bounding box by a counting sort on the linear cell
// index, so all particles of one cell, and of three x-adjacent cells, lie contiguously once the
// caller has permuted its arrays into sorted order. A query then visits 9 contiguous index ranges.
// An axis can be made periodic over an interval: the grid then spans exactly that interval on the
// axis (the last cell takes the remainder), and forEachNeighbourCell wraps around it.
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

  /// Makes `axis` periodic over [lo, hi) for the following builds (positions are expected inside;
  /// those outside fall into the first or last cell). The interval must hold at least 3 cells, so
  /// that the 3 cells around any cell are distinct; build throws otherwise.
  void setPeriodic(int axis, float lo, float hi)
  {
    this->Periodic[axis] = true;
    this->PeriodLow[axis] = lo;
    this->PeriodLength[axis] = hi - lo;
  }
  bool periodic(int axis) const { return this->Periodic[axis]; }
  bool anyPeriodic() const { return this->Periodic[0] || this->Periodic[1] || this->Periodic[2]; }
  float periodLength(int axis) const { return this->PeriodLength[axis]; }

  /// Calls f(cell, shift) for each of the 27 cells around (ix, iy, iz) that exist, wrapping around
  /// periodic axes; shift is what to add to a position in that cell to bring it next to (ix, iy, iz)
  /// (zero unless the cell was reached across a periodic boundary).
  template<class F>
  void forEachNeighbourCell(int ix, int iy, int iz, F&& f) const
  {
    const int centre[3] = { ix, iy, iz };
    int cell[3][3];
    float shift[3][3];
    bool exists[3][3];
    for (int a = 0; a < 3; ++a)
    {
      for (int d = 0; d < 3; ++d)
      {
        int c = centre[a] + d - 1;
        shift[a][d] = 0.0f;
        exists[a][d] = c >= 0 && c < this->Dims[a];
        if (!exists[a][d] && this->Periodic[a])
        {
          shift[a][d] = c < 0 ? -this->PeriodLength[a] : this->PeriodLength[a];
          c = c < 0 ? c + this->Dims[a] : c - this->Dims[a];
          exists[a][d] = true;
        }
        cell[a][d] = c;
      }
    }
    for (int dz = 0; dz < 3; ++dz)
    {
      for (int dy = 0; dy < 3; ++dy)
      {
        for (int dx = 0; dx < 3; ++dx)
        {
          if (exists[0][dx] && exists[1][dy] && exists[2][dz])
          {
            const float offset[3] = { shift[0][dx], shift[1][dy], shift[2][dz] };
            f(this->linearIndex(cell[0][dx], cell[1][dy], cell[2][dz]), offset);
          }
        }
      }
    }
  }

  /// The box of cell (ix, iy, iz): lower corner and upper corner (the last cell of a periodic axis
  /// reaches the end of the period).
  void cellBox(int ix, int iy, int iz, float lo[3], float hi[3]) const
  {
    const int c[3] = { ix, iy, iz };
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = this->Origin[a] + static_cast<float>(c[a]) * this->CellSize;
      hi[a] = this->Periodic[a] && c[a] == this->Dims[a] - 1 ? this->Origin[a] + this->PeriodLength[a]
                                                             : lo[a] + this->CellSize;
    }
  }

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
  bool Periodic[3] = { false, false, false };
  float PeriodLow[3] = { 0.0f, 0.0f, 0.0f };
  float PeriodLength[3] = { 0.0f, 0.0f, 0.0f };
  int Dims[3] = { 0, 0, 0 };
  float Origin[3] = { 0.0f, 0.0f, 0.0f };
  float CellSize = 0.0f;
  std::vector<std::uint32_t> Order;
  std::vector<std::uint32_t> CellStart;
  std::vector<std::uint32_t> ParticleCell;
};
} // namespace parafluid
