#include "parafluid/common/NeighbourGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace parafluid
{
void NeighbourGrid::build(const float* x, const float* y, const float* z, std::size_t n, float cellSize)
{
  if (!(cellSize > 0.0f) || !std::isfinite(cellSize))
  {
    throw std::invalid_argument("neighbour grid: cell size must be a positive finite number, got " +
                                std::to_string(cellSize));
  }
  if (n > std::numeric_limits<std::uint32_t>::max() - 1)
  {
    throw std::invalid_argument("neighbour grid: more than 2^32 - 2 particles are not supported");
  }
  this->Order.resize(n);
  this->ParticleCell.resize(n);
  if (n == 0)
  {
    this->Dims[0] = this->Dims[1] = this->Dims[2] = 1;
    this->CellStart.assign(2, 0);
    return;
  }

  float lo[3] = { x[0], y[0], z[0] };
  float hi[3] = { x[0], y[0], z[0] };
  bool finite = true;
  for (std::size_t i = 0; i < n; ++i)
  {
    const float p[3] = { x[i], y[i], z[i] };
    for (int a = 0; a < 3; ++a)
    {
      finite = finite && std::isfinite(p[a]);
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  if (!finite)
  {
    throw std::invalid_argument("neighbour grid: a particle position is NaN or infinite");
  }

  const float inverseCell = 1.0f / cellSize;
  this->CellSize = cellSize;
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = this->Periodic[a] ? this->PeriodLow[a] : lo[a];
    if (this->Periodic[a])
    {
      lo[a] = this->PeriodLow[a];
    }
  }
  double cells = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    // A periodic axis has whole cells of at least cellSize over the period (the last takes the
    // remainder), so that the wrap-around neighbours are the first and last cells.
    const double extent = this->Periodic[a]
                            ? std::floor(static_cast<double>(this->PeriodLength[a]) * inverseCell * (1.0 + 1e-6))
                            : std::floor((static_cast<double>(hi[a]) - lo[a]) * inverseCell) + 1.0;
    if (this->Periodic[a] && extent < 3.0)
    {
      throw std::invalid_argument("neighbour grid: a periodic axis must be at least 3 cells long (axis " +
                                  std::to_string(a) + ": period " + std::to_string(this->PeriodLength[a]) + ", cell " +
                                  std::to_string(cellSize) + ")");
    }
    cells *= extent;
    this->Dims[a] = extent > 2e9 ? std::numeric_limits<int>::max() : static_cast<int>(extent);
  }
  if (cells > static_cast<double>(std::min<std::size_t>(maxCells(n), std::numeric_limits<std::uint32_t>::max() - 1)))
  {
    throw std::invalid_argument(
      "neighbour grid: the particles span " + std::to_string(cells) + " cells of size " + std::to_string(cellSize) +
      ", more than the " + std::to_string(maxCells(n)) + " allowed for " + std::to_string(n) +
      " particles; particles have flown far apart (check the domain bounds and the time step)");
  }
  const std::size_t cellCount = static_cast<std::size_t>(cells);

  // Counting sort on the linear cell index. Serial: it is O(n + cells) and a small part of a step,
  // and a serial scatter keeps the order stable and independent of the thread count.
  this->CellStart.assign(cellCount + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    // Clamped into the grid: only a periodic axis can have positions outside (rounding at its ends).
    const int ix = std::clamp(static_cast<int>((x[i] - lo[0]) * inverseCell), 0, this->Dims[0] - 1);
    const int iy = std::clamp(static_cast<int>((y[i] - lo[1]) * inverseCell), 0, this->Dims[1] - 1);
    const int iz = std::clamp(static_cast<int>((z[i] - lo[2]) * inverseCell), 0, this->Dims[2] - 1);
    const auto c = static_cast<std::uint32_t>(this->linearIndex(ix, iy, iz));
    this->ParticleCell[i] = c;
    ++this->CellStart[c + 1];
  }
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    this->CellStart[c + 1] += this->CellStart[c];
  }
  // Scatter using CellStart[c] as the running insertion point of cell c, then shift back.
  for (std::size_t i = 0; i < n; ++i)
  {
    this->Order[this->CellStart[this->ParticleCell[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (std::size_t c = cellCount; c > 0; --c)
  {
    this->CellStart[c] = this->CellStart[c - 1];
  }
  this->CellStart[0] = 0;
}
} // namespace parafluid
