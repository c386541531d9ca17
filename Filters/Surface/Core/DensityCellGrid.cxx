#include "parafluid/surface/DensityCellGrid.h"

#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace parafluid::surface
{
namespace
{
// Distance from v to the interval [lo, hi] along one axis.
inline double outside(double v, double lo, double hi)
{
  return v < lo ? lo - v : (v > hi ? v - hi : 0.0);
}
} // namespace

void DensityCellGrid::build(const float* xyz, std::size_t n, double spacing, double kernelRadius, double isoValue,
                            std::size_t maxCells)
{
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !(kernelRadius > 0.0) || !std::isfinite(kernelRadius) ||
      !(isoValue > 0.0) || !std::isfinite(isoValue) || maxCells < 1)
  {
    throw std::invalid_argument("DensityCellGrid: spacing, kernel radius and iso value must be positive and finite");
  }
  if (n >= OccupiedBit)
  {
    throw std::invalid_argument("DensityCellGrid: at most 2^31 - 1 particles");
  }
  this->KernelRadius = kernelRadius;
  this->IsoValue = isoValue;
  // poly6: W(s) = 315 / (64 pi r^9) (r^2 - s^2)^3, times the particle volume d^3.
  this->Scale = spacing * spacing * spacing * 315.0 / (64.0 * parafluid::kPi * std::pow(kernelRadius, 9));
  this->Sorted.clear();
  this->SplatCells.clear();
  this->Order.clear();
  this->Skipped = 0;
  this->OccupiedCells = 0;
  this->SplashParticles = this->UnsplattedParticles = 0;

  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  std::vector<std::uint32_t> finite;
  finite.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const float* p = xyz + 3 * i;
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      ++this->Skipped;
      continue;
    }
    finite.push_back(static_cast<std::uint32_t>(i));
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], static_cast<double>(p[a]));
      hi[a] = std::max(hi[a], static_cast<double>(p[a]));
    }
  }
  if (finite.empty())
  {
    std::fill(this->Dims, this->Dims + 3, 0);
    std::fill(this->BlockDims, this->BlockDims + 3, 0);
    this->CellStart.assign(1, 0);
    this->BlockOccupied.clear();
    return;
  }
  // One kernel radius of margin on each side holds every point where phi > 0.
  double extent[3];
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = hi[a] - lo[a] + 2.0 * kernelRadius;
  }
  double cell = std::max(kernelRadius, std::cbrt(extent[0] * extent[1] * extent[2] / static_cast<double>(maxCells)));
  for (;;)
  {
    double total = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      total *= std::max(1.0, std::ceil(extent[a] / cell));
    }
    if (total <= static_cast<double>(maxCells))
    {
      break;
    }
    cell *= 1.02; // widen until the table fits (rounding up per axis can overshoot the volume bound)
  }
  this->CellSize = cell;
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = lo[a] - kernelRadius;
    this->Dims[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / cell)));
    this->BlockDims[a] = (this->Dims[a] + BlockCells - 1) / BlockCells;
  }
  const std::size_t cells = static_cast<std::size_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2];

  // Counting sort by cell.
  std::vector<std::uint32_t> cellOf(finite.size());
  std::vector<std::uint32_t> count(cells + 1, 0);
  for (std::size_t k = 0; k < finite.size(); ++k)
  {
    const float* p = xyz + 3 * finite[k];
    int c[3];
    for (int a = 0; a < 3; ++a)
    {
      c[a] = std::clamp(static_cast<int>((p[a] - this->Origin[a]) / cell), 0, this->Dims[a] - 1);
    }
    cellOf[k] =
      static_cast<std::uint32_t>((static_cast<std::size_t>(c[2]) * this->Dims[1] + c[1]) * this->Dims[0] + c[0]);
    ++count[cellOf[k] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c)
  {
    count[c + 1] += count[c];
  }
  this->CellStart = count;
  this->Sorted.assign(4 * finite.size(), 0.0f);
  this->Order.assign(finite.size(), 0);
  for (std::size_t k = 0; k < finite.size(); ++k)
  {
    const std::uint32_t slot = count[cellOf[k]]++;
    const float* p = xyz + 3 * finite[k];
    std::copy(p, p + 3, &this->Sorted[4 * slot]);
    this->Order[slot] = finite[k];
  }
  this->markOccupancy();
  this->classifySplats(spacing);
}

void DensityCellGrid::classifySplats(double spacing)
{
  const int nx = this->Dims[0], ny = this->Dims[1], nz = this->Dims[2];
  const double perCell = std::pow(this->CellSize / spacing, 3);
  const double splashBelow = 27.0 * perCell / 8.0;
  const long long cells = static_cast<long long>(nx) * ny * nz;
  std::size_t splash = 0, none = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : splash, none)
  for (long long id = 0; id < cells; ++id)
  {
    const std::uint32_t first = this->CellStart[static_cast<std::size_t>(id)] & ~OccupiedBit;
    const std::uint32_t last = this->CellStart[static_cast<std::size_t>(id) + 1] & ~OccupiedBit;
    if (first == last)
    {
      continue;
    }
    const int i = static_cast<int>(id % nx), j = static_cast<int>((id / nx) % ny), k = static_cast<int>(id / nx / ny);
    std::size_t around = 0;
    bool occupied = false;
    for (int z = std::max(k - 1, 0); z <= std::min(k + 1, nz - 1); ++z)
    {
      for (int y = std::max(j - 1, 0); y <= std::min(j + 1, ny - 1); ++y)
      {
        const std::size_t row = (static_cast<std::size_t>(z) * ny + y) * nx;
        for (int x = std::max(i - 1, 0); x <= std::min(i + 1, nx - 1); ++x)
        {
          const std::uint32_t entry = this->CellStart[row + x];
          occupied = occupied || (entry & OccupiedBit) != 0;
        }
        around += (this->CellStart[row + std::min(i + 1, nx - 1) + 1] & ~OccupiedBit) -
                  (this->CellStart[row + std::max(i - 1, 0)] & ~OccupiedBit);
      }
    }
    const float splatClass =
      !occupied ? SplatNone : (static_cast<double>(around) < splashBelow ? SplatSplash : SplatBulk);
    for (std::uint32_t s = first; s < last; ++s)
    {
      this->Sorted[4 * s + 3] = splatClass;
    }
    const std::size_t count = last - first;
    splash += splatClass == SplatSplash ? count : 0;
    none += splatClass == SplatNone ? count : 0;
  }
  this->SplashParticles = splash;
  this->UnsplattedParticles = none;
  this->SplatCells.clear();
  for (long long id = 0; id < cells; ++id)
  {
    const std::uint32_t first = this->CellStart[static_cast<std::size_t>(id)] & ~OccupiedBit;
    const std::uint32_t last = this->CellStart[static_cast<std::size_t>(id) + 1] & ~OccupiedBit;
    if (first == last || this->Sorted[4 * first + 3] == SplatNone)
    {
      continue;
    }
    const int i = static_cast<int>(id % nx), j = static_cast<int>((id / nx) % ny), k = static_cast<int>(id / nx / ny);
    const float corner[4] = { static_cast<float>(this->Origin[0] + i * this->CellSize),
                              static_cast<float>(this->Origin[1] + j * this->CellSize),
                              static_cast<float>(this->Origin[2] + k * this->CellSize), this->Sorted[4 * first + 3] };
    this->SplatCells.insert(this->SplatCells.end(), corner, corner + 4);
  }
}

void DensityCellGrid::markOccupancy()
{
  const int nx = this->Dims[0], ny = this->Dims[1], nz = this->Dims[2];
  const double c = this->CellSize, r2 = this->KernelRadius * this->KernelRadius;
  const double threshold = this->IsoValue / this->Scale;
  const long long cells = static_cast<long long>(nx) * ny * nz;
  std::vector<std::uint8_t> occupied(static_cast<std::size_t>(cells), 0);
  std::size_t total = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : total)
  for (long long id = 0; id < cells; ++id)
  {
    const int i = static_cast<int>(id % nx), j = static_cast<int>((id / nx) % ny), k = static_cast<int>(id / nx / ny);
    const double boxLo[3] = { this->Origin[0] + i * c, this->Origin[1] + j * c, this->Origin[2] + k * c };
    double bound = 0.0;
    for (int z = std::max(k - 1, 0); z <= std::min(k + 1, nz - 1) && bound < threshold; ++z)
    {
      for (int y = std::max(j - 1, 0); y <= std::min(j + 1, ny - 1); ++y)
      {
        const std::size_t row = (static_cast<std::size_t>(z) * ny + y) * nx;
        const std::uint32_t begin = this->CellStart[row + std::max(i - 1, 0)];
        const std::uint32_t end = this->CellStart[row + std::min(i + 1, nx - 1) + 1];
        for (std::uint32_t s = begin; s < end; ++s)
        {
          const float* p = &this->Sorted[4 * s];
          const double dx = outside(p[0], boxLo[0], boxLo[0] + c), dy = outside(p[1], boxLo[1], boxLo[1] + c),
                       dz = outside(p[2], boxLo[2], boxLo[2] + c);
          const double t = r2 - (dx * dx + dy * dy + dz * dz);
          if (t > 0.0)
          {
            bound += t * t * t;
          }
        }
      }
    }
    if (bound >= threshold)
    {
      occupied[static_cast<std::size_t>(id)] = 1;
      ++total;
    }
  }
  this->OccupiedCells = total;
  this->BlockOccupied.assign(static_cast<std::size_t>(this->BlockDims[0]) * this->BlockDims[1] * this->BlockDims[2], 0);
  for (long long id = 0; id < cells; ++id)
  {
    if (occupied[static_cast<std::size_t>(id)])
    {
      this->CellStart[static_cast<std::size_t>(id)] |= OccupiedBit;
      const int i = static_cast<int>(id % nx) / BlockCells, j = static_cast<int>((id / nx) % ny) / BlockCells,
                k = static_cast<int>(id / nx / ny) / BlockCells;
      this->BlockOccupied[(static_cast<std::size_t>(k) * this->BlockDims[1] + j) * this->BlockDims[0] + i] = 1;
    }
  }
}

bool DensityCellGrid::cellOccupied(int i, int j, int k) const
{
  if (i < 0 || j < 0 || k < 0 || i >= this->Dims[0] || j >= this->Dims[1] || k >= this->Dims[2])
  {
    return false;
  }
  return (this->CellStart[(static_cast<std::size_t>(k) * this->Dims[1] + j) * this->Dims[0] + i] & OccupiedBit) != 0;
}

double DensityCellGrid::evaluate(const double p[3], double gradient[3]) const
{
  gradient[0] = gradient[1] = gradient[2] = 0.0;
  if (this->Order.empty())
  {
    return 0.0;
  }
  const double r = this->KernelRadius, r2 = r * r;
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(0, static_cast<int>(std::floor((p[a] - r - this->Origin[a]) / this->CellSize)));
    hi[a] = std::min(this->Dims[a] - 1, static_cast<int>(std::floor((p[a] + r - this->Origin[a]) / this->CellSize)));
    if (lo[a] > hi[a])
    {
      return 0.0; // beyond the grid along this axis: no particle within reach
    }
  }
  double sum = 0.0;
  for (int z = lo[2]; z <= hi[2]; ++z)
  {
    for (int y = lo[1]; y <= hi[1]; ++y)
    {
      const std::size_t row = (static_cast<std::size_t>(z) * this->Dims[1] + y) * this->Dims[0];
      const std::uint32_t begin = this->CellStart[row + lo[0]] & ~OccupiedBit;
      const std::uint32_t end = this->CellStart[row + hi[0] + 1] & ~OccupiedBit;
      for (std::uint32_t s = begin; s < end; ++s)
      {
        const float* q = &this->Sorted[4 * s];
        const double e[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
        const double t = r2 - (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if (t > 0.0)
        {
          sum += t * t * t;
          for (int a = 0; a < 3; ++a)
          {
            gradient[a] += 6.0 * t * t * e[a];
          }
        }
      }
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    gradient[a] *= this->Scale;
  }
  return this->Scale * sum;
}
} // namespace parafluid::surface
