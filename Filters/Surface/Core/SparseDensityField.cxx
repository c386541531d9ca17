#include "parafluid/surface/SparseDensityField.h"
#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <omp.h>
#include <stdexcept>
#include <string>
#ifdef __GLIBCXX__
#include <parallel/algorithm>
#endif

namespace parafluid::surface
{
namespace
{
constexpr int B = SparseDensityField::BlockPoints;
constexpr std::uint64_t EmptySlot = ~std::uint64_t(0);
constexpr std::uint64_t AxisLimit = std::uint64_t(1) << 21; // blocks along an axis (8 * 2^21 = 2^24 cells)

struct KeyedParticle
{
  std::uint64_t key;
  std::uint32_t index;
  bool operator<(const KeyedParticle& o) const { return key < o.key || (key == o.key && index < o.index); }
};

template<class It>
void sortRange(It first, It last)
{
#ifdef __GLIBCXX__
  // Keys are unique (the particle index breaks ties), so the parallel sort's result is the same
  // for any thread count.
  __gnu_parallel::sort(first, last);
#else
  std::sort(first, last);
#endif
}

std::uint64_t mix(std::uint64_t x)
{
  // splitmix64 finaliser: spreads the packed block coordinates over the hash table.
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

void unpack(std::uint64_t k, int c[3])
{
  c[0] = static_cast<int>(k & (AxisLimit - 1));
  c[1] = static_cast<int>((k >> 21) & (AxisLimit - 1));
  c[2] = static_cast<int>(k >> 42);
}
} // namespace

double SparseDensityField::kernelScale(double cellSize, double kernelRadius, double particleVolume)
{
  // poly6: W(s) = 315 / (64 pi r^9) (r^2 - s^2)^3. With s and r measured in cells (s = c sigma,
  // r = c rho) this is 315 / (64 pi rho^9 c^3) (rho^2 - sigma^2)^3.
  const double rho = kernelRadius / cellSize;
  return particleVolume * 315.0 / (64.0 * parafluid::kPi * std::pow(rho, 9) * cellSize * cellSize * cellSize);
}

double SparseDensityField::evaluate(const double p[3], double gradient[3]) const
{
  const double c = this->CellSize;
  const double x[3] = { (p[0] - this->Origin[0]) / c, (p[1] - this->Origin[1]) / c, (p[2] - this->Origin[2]) / c };
  const double rho = this->KernelRadius / c;
  double sum = 0.0, g[3] = { 0.0, 0.0, 0.0 };
  this->forEachParticleNear(x,
                            [&](std::uint32_t, double ex, double ey, double ez, double s2)
                            {
                              const double t = rho * rho - s2;
                              sum += t * t * t;
                              // d/dx (rho^2 - |x_j - x|^2)^3 = 6 t^2 (x_j - x)
                              g[0] += 6.0 * t * t * ex;
                              g[1] += 6.0 * t * t * ey;
                              g[2] += 6.0 * t * t * ez;
                            });
  const double scale = kernelScale(c, this->KernelRadius, this->ParticleVolume);
  for (int a = 0; a < 3; ++a)
  {
    gradient[a] = scale * g[a] / c;
  }
  return scale * sum;
}

void SparseDensityField::build(const float* xyz, std::size_t n, double cellSize, double kernelRadius,
                               double particleVolume, double isoValue)
{
  if (!(cellSize > 0.0) || !(kernelRadius > 0.0) || !(particleVolume > 0.0) || !std::isfinite(cellSize) ||
      !std::isfinite(kernelRadius) || !std::isfinite(particleVolume))
  {
    throw std::invalid_argument("cell size, kernel radius and particle volume must be positive and finite");
  }
  if (n > std::numeric_limits<std::uint32_t>::max() - 1)
  {
    throw std::invalid_argument("too many particles for one surface (at most 2^32 - 2)");
  }
  this->CellSize = cellSize;
  this->KernelRadius = kernelRadius;
  this->ParticleVolume = particleVolume;
  this->BlockReach = std::max(1, static_cast<int>(std::ceil(kernelRadius / (B * cellSize))));
  this->Keys.clear();
  this->ParticleBegin.assign(1, 0);
  this->Stored.clear();
  this->Storage.clear();
  this->SurfaceBlock.clear();
  this->Minimum.clear();
  this->Maximum.clear();
  this->SortedIndex.clear();
  this->SortedXYZ.clear();
  this->HashKeys.assign(1, EmptySlot);
  this->HashSlots.assign(1, 0);
  if (n == 0)
  {
    return;
  }
  this->sortParticles(xyz, n);
  this->allocateBlocks();
  this->buildHash();
  this->IsoValue = isoValue;
  this->sampleBlocks(static_cast<float>(isoValue));
}

void SparseDensityField::sortParticles(const float* xyz, std::size_t n)
{
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  bool finite = true;
  const long long count = static_cast<long long>(n);
#pragma omp parallel for reduction(min : lo[:3]) reduction(max : hi[:3]) reduction(&& : finite)
  for (long long i = 0; i < count; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double v = xyz[3 * i + a];
      finite = finite && std::isfinite(v);
      lo[a] = std::min(lo[a], v);
      hi[a] = std::max(hi[a], v);
    }
  }
  if (!finite)
  {
    throw std::invalid_argument("particle positions contain NaN or infinite values");
  }
  // The lowest point any particle reaches (r + sqrt(3) cells) must have a non-negative index.
  const double margin = this->KernelRadius + 2.0 * this->CellSize;
  const double blockEdge = B * this->CellSize;
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = lo[a] - margin;
    if ((hi[a] - this->Origin[a] + margin) / blockEdge + 2 >= static_cast<double>(AxisLimit))
    {
      throw std::invalid_argument("the particles span " + std::to_string(hi[a] - lo[a]) + " m, too many cells of " +
                                  std::to_string(this->CellSize) + " m to index; raise the cell size");
    }
  }
  std::vector<KeyedParticle> keyed(n);
#pragma omp parallel for
  for (long long i = 0; i < count; ++i)
  {
    int c[3];
    for (int a = 0; a < 3; ++a)
    {
      c[a] = static_cast<int>(std::floor((xyz[3 * i + a] - this->Origin[a]) / blockEdge));
    }
    keyed[i] = { this->key(c[0], c[1], c[2]), static_cast<std::uint32_t>(i) };
  }
  sortRange(keyed.begin(), keyed.end());
  this->SortPeakBytes = n * (sizeof(KeyedParticle) + sizeof(std::uint32_t) + 3 * sizeof(float));
  this->SortedIndex.resize(n);
  this->SortedXYZ.resize(3 * n);
#pragma omp parallel for
  for (long long k = 0; k < count; ++k)
  {
    const std::uint32_t i = keyed[k].index;
    this->SortedIndex[k] = i;
    for (int a = 0; a < 3; ++a)
    {
      this->SortedXYZ[3 * k + a] =
        static_cast<float>((xyz[3 * static_cast<std::size_t>(i) + a] - this->Origin[a]) / this->CellSize);
    }
  }
  // The occupied blocks, in key order, as (key, first sorted slot); kept in Keys/ParticleBegin
  // until allocateBlocks merges them with the blocks their kernels reach.
  this->Keys.clear();
  this->ParticleBegin.clear();
  for (std::size_t k = 0; k < n; ++k)
  {
    if (k == 0 || keyed[k].key != keyed[k - 1].key)
    {
      this->Keys.push_back(keyed[k].key);
      this->ParticleBegin.push_back(static_cast<std::uint32_t>(k));
    }
  }
  this->ParticleBegin.push_back(static_cast<std::uint32_t>(n));
}

void SparseDensityField::allocateBlocks()
{
  const std::vector<std::uint64_t> occupied = std::move(this->Keys);
  const std::vector<std::uint32_t> occupiedBegin = std::move(this->ParticleBegin);
  const std::size_t nOccupied = occupied.size();
  const double c = this->CellSize;
  const double reach = this->KernelRadius + std::sqrt(3.0) * c;
  // Block b's points span [8 b c, (8 b + 7) c] on each axis (from the origin); it is needed when
  // that span comes within `reach` of the bounding box of some occupied block's particles.
  std::vector<int> range(6 * nOccupied);
  std::vector<std::size_t> offset(nOccupied + 1, 0);
  const long long nOcc = static_cast<long long>(nOccupied);
#pragma omp parallel for
  for (long long o = 0; o < nOcc; ++o)
  {
    float lo[3] = { std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                    std::numeric_limits<float>::max() };
    float hi[3] = { -lo[0], -lo[1], -lo[2] };
    for (std::uint32_t k = occupiedBegin[o]; k < occupiedBegin[o + 1]; ++k)
    {
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], this->SortedXYZ[3 * k + a]);
        hi[a] = std::max(hi[a], this->SortedXYZ[3 * k + a]);
      }
    }
    std::size_t cells = 1;
    for (int a = 0; a < 3; ++a)
    {
      const double low = lo[a] - reach / c;
      const double high = hi[a] + reach / c;
      const int b0 = std::max(0, static_cast<int>(std::ceil((low - (B - 1)) / B)));
      const int b1 = static_cast<int>(std::floor(high / B));
      range[6 * o + 2 * a] = b0;
      range[6 * o + 2 * a + 1] = b1;
      cells *= static_cast<std::size_t>(std::max(0, b1 - b0 + 1));
    }
    offset[o + 1] = cells;
  }
  for (std::size_t o = 0; o < nOccupied; ++o)
  {
    offset[o + 1] += offset[o];
  }
  std::vector<std::uint64_t> candidates(offset[nOccupied]);
#pragma omp parallel for
  for (long long o = 0; o < nOcc; ++o)
  {
    std::size_t w = offset[o];
    const int* r = &range[6 * o];
    for (int z = r[4]; z <= r[5]; ++z)
    {
      for (int y = r[2]; y <= r[3]; ++y)
      {
        for (int x = r[0]; x <= r[1]; ++x)
        {
          candidates[w++] = this->key(x, y, z);
        }
      }
    }
  }
  sortRange(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  candidates.shrink_to_fit();
  this->Keys = std::move(candidates);
  // Merge: every occupied block is among the allocated ones (a particle reaches its own block).
  const std::size_t nBlocks = this->Keys.size();
  this->ParticleBegin.assign(nBlocks + 1, 0);
  std::size_t o = 0;
  for (std::size_t b = 0; b < nBlocks; ++b)
  {
    while (o < nOccupied && occupied[o] < this->Keys[b])
    {
      ++o;
    }
    this->ParticleBegin[b] = (o < nOccupied) ? occupiedBegin[o] : occupiedBegin[nOccupied];
  }
  this->ParticleBegin[nBlocks] = occupiedBegin[nOccupied];
  // Blocks without particles get an empty range: begin = the next occupied block's begin, and the
  // next block's begin is the same; occupied blocks end where the next one starts.
}

void SparseDensityField::buildHash()
{
  std::size_t capacity = 16;
  while (capacity < 2 * this->Keys.size())
  {
    capacity *= 2;
  }
  this->HashKeys.assign(capacity, EmptySlot);
  this->HashSlots.assign(capacity, 0);
  const std::uint64_t mask = capacity - 1;
  for (std::size_t b = 0; b < this->Keys.size(); ++b)
  {
    std::uint64_t h = mix(this->Keys[b]) & mask;
    while (this->HashKeys[h] != EmptySlot)
    {
      h = (h + 1) & mask;
    }
    this->HashKeys[h] = this->Keys[b];
    this->HashSlots[h] = static_cast<std::uint32_t>(b);
  }
}

std::int64_t SparseDensityField::findBlock(int bx, int by, int bz) const
{
  if (bx < 0 || by < 0 || bz < 0 || bx >= static_cast<int>(AxisLimit) || by >= static_cast<int>(AxisLimit) ||
      bz >= static_cast<int>(AxisLimit))
  {
    return -1;
  }
  const std::uint64_t k = this->key(bx, by, bz);
  const std::uint64_t mask = this->HashKeys.size() - 1;
  for (std::uint64_t h = mix(k) & mask;; h = (h + 1) & mask)
  {
    if (this->HashKeys[h] == k)
    {
      return this->HashSlots[h];
    }
    if (this->HashKeys[h] == EmptySlot)
    {
      return -1;
    }
  }
}

void SparseDensityField::blockCoordinates(std::size_t b, int c[3]) const
{
  unpack(this->Keys[b], c);
}

namespace
{
int floorInt(float x)
{
  // x > -1024 here (particles are rejected unless within the kernel radius of the block).
  return static_cast<int>(x + 1024.0f) - 1024;
}

int ceilInt(float x)
{
  return -floorInt(-x);
}

// Four floats processed together (GCC/Clang vector extension: SSE on x86, NEON on ARM).
typedef float Float4 __attribute__((vector_size(16)));

// Adds (rho^2 - s^2)^3 of one particle at local cell coordinates l to the block's values, for
// the points within rho. Whole rows of 8 points as two 4-wide vectors: cheaper than clipping each
// row to the kernel's chord.
inline void splatParticle(float* acc, const float l[3], float rho, float rho2)
{
  const int z0 = std::max(0, ceilInt(l[2] - rho)), z1 = std::min(B - 1, floorInt(l[2] + rho));
  const int y0 = std::max(0, ceilInt(l[1] - rho)), y1 = std::min(B - 1, floorInt(l[1] + rho));
  const Float4 lx = { l[0], l[0], l[0], l[0] };
  const Float4 ex0 = Float4{ 0.0f, 1.0f, 2.0f, 3.0f } - lx, ex1 = Float4{ 4.0f, 5.0f, 6.0f, 7.0f } - lx;
  const Float4 ex20 = ex0 * ex0, ex21 = ex1 * ex1;
  const Float4 zero = { 0.0f, 0.0f, 0.0f, 0.0f };
  for (int iz = z0; iz <= z1; ++iz)
  {
    const float ez = static_cast<float>(iz) - l[2];
    const float rz2 = rho2 - ez * ez;
    for (int iy = y0; iy <= y1; ++iy)
    {
      const float ey = static_cast<float>(iy) - l[1];
      const float ry2 = rz2 - ey * ey;
      if (ry2 <= 0.0f)
      {
        continue;
      }
      float* row = acc + (iz * B + iy) * B;
      const Float4 r = { ry2, ry2, ry2, ry2 };
      Float4 q0 = r - ex20, q1 = r - ex21;
      q0 = q0 > zero ? q0 : zero;
      q1 = q1 > zero ? q1 : zero;
      Float4 a0, a1;
      std::memcpy(&a0, row, sizeof a0);
      std::memcpy(&a1, row + 4, sizeof a1);
      a0 += q0 * q0 * q0;
      a1 += q1 * q1 * q1;
      std::memcpy(row, &a0, sizeof a0);
      std::memcpy(row + 4, &a1, sizeof a1);
    }
  }
}
} // namespace

void SparseDensityField::splatBlock(std::size_t b, float* acc) const
{
  const float rho = static_cast<float>(this->KernelRadius / this->CellSize);
  const float rho2 = rho * rho;
  const float upper = static_cast<float>(B - 1) + rho;
  int bc[3];
  unpack(this->Keys[b], bc);
  std::fill(acc, acc + BlockSize, 0.0f);
  // The block's first point, in cells from the origin.
  const float base[3] = { static_cast<float>(B * bc[0]), static_cast<float>(B * bc[1]), static_cast<float>(B * bc[2]) };
  const float* cells = this->SortedXYZ.data();
  this->forEachBlockAround(
    bc,
    [&](std::int64_t nb)
    {
      const std::uint32_t end = this->ParticleBegin[nb + 1];
      for (std::uint32_t k = this->ParticleBegin[nb]; k < end; ++k)
      {
        const float l[3] = { cells[3 * k] - base[0], cells[3 * k + 1] - base[1], cells[3 * k + 2] - base[2] };
        if (l[0] < -rho || l[1] < -rho || l[2] < -rho || l[0] > upper || l[1] > upper || l[2] > upper)
        {
          continue;
        }
        splatParticle(acc, l, rho, rho2);
      }
    });
  const float scale = static_cast<float>(kernelScale(this->CellSize, this->KernelRadius, this->ParticleVolume));
  for (int p = 0; p < BlockSize; ++p)
  {
    acc[p] *= scale;
  }
}

void SparseDensityField::sampleBlocks(float iso)
{
  const std::size_t nBlocks = this->Keys.size();
  this->Stored.assign(nBlocks, nullptr);
  this->Storage.clear();
  this->Minimum.assign(nBlocks, 0.0f);
  this->Maximum.assign(nBlocks, 0.0f);
  const long long count = static_cast<long long>(nBlocks);
  // Pass 1: every block's range; only blocks the surface passes through keep their values.
  std::vector<std::vector<std::unique_ptr<float[]>>> kept(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    std::unique_ptr<float[]> scratch(new float[BlockSize]);
    auto& mine = kept[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 16)
    for (long long b = 0; b < count; ++b)
    {
      this->splatBlock(static_cast<std::size_t>(b), scratch.get());
      const auto range = std::minmax_element(scratch.get(), scratch.get() + BlockSize);
      this->Minimum[b] = *range.first;
      this->Maximum[b] = *range.second;
      if (*range.first <= iso && *range.second > iso)
      {
        this->Stored[b] = scratch.get();
        mine.push_back(std::move(scratch));
        scratch.reset(new float[BlockSize]);
      }
    }
  }
  for (auto& list : kept)
  {
    for (auto& block : list)
    {
      this->Storage.push_back(std::move(block));
    }
  }
  // Pass 2: mark the blocks marching cubes polygonises; it also reads the blocks around each of
  // them, so recompute and keep those.
  std::vector<char> needed(nBlocks, 0);
  auto side = [&](std::int64_t b)
  { return b < 0 ? 0 : (this->Maximum[b] <= iso ? 0 : (this->Minimum[b] > iso ? 1 : 2)); };
  this->SurfaceBlock.assign(nBlocks, 0);
#pragma omp parallel for schedule(dynamic, 64)
  for (long long b = 0; b < count; ++b)
  {
    // Its own points are mixed, or a block above it (whose points its upper cells use) lies on
    // another side; a missing block is outside.
    int bc[3];
    unpack(this->Keys[b], bc);
    bool crosses = side(b) == 2;
    for (int n = 1; n < 8 && !crosses; ++n)
    {
      crosses = side(this->findBlock(bc[0] + (n & 1), bc[1] + ((n >> 1) & 1), bc[2] + ((n >> 2) & 1))) != side(b);
    }
    this->SurfaceBlock[b] = crosses ? 1 : 0;
    if (!crosses)
    {
      continue;
    }
    for (int dz = -1; dz <= 1; ++dz)
    {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const std::int64_t nb = this->findBlock(bc[0] + dx, bc[1] + dy, bc[2] + dz);
          if (nb >= 0 && !this->Stored[nb])
          {
            needed[nb] = 1; // benign race: every writer writes 1
          }
        }
      }
    }
  }
  std::vector<std::uint32_t> recompute;
  for (std::size_t b = 0; b < nBlocks; ++b)
  {
    if (needed[b])
    {
      recompute.push_back(static_cast<std::uint32_t>(b));
    }
  }
  const std::size_t first = this->Storage.size();
  for (std::size_t k = 0; k < recompute.size(); ++k)
  {
    this->Storage.emplace_back(new float[BlockSize]);
  }
  const long long extra = static_cast<long long>(recompute.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (long long k = 0; k < extra; ++k)
  {
    float* values = this->Storage[first + static_cast<std::size_t>(k)].get();
    this->splatBlock(recompute[k], values);
    this->Stored[recompute[k]] = values;
  }
}

void SparseDensityField::releaseValues()
{
  std::vector<std::unique_ptr<float[]>>().swap(this->Storage);
  std::vector<const float*>(this->Keys.size(), nullptr).swap(this->Stored);
}

std::size_t SparseDensityField::bytes() const
{
  return this->Keys.capacity() * sizeof(std::uint64_t) + this->ParticleBegin.capacity() * sizeof(std::uint32_t) +
         this->Storage.size() * BlockSize * sizeof(float) + this->Storage.capacity() * sizeof(void*) +
         this->Stored.capacity() * sizeof(float*) + this->SurfaceBlock.capacity() +
         (this->Minimum.capacity() + this->Maximum.capacity()) * sizeof(float) +
         this->HashKeys.capacity() * sizeof(std::uint64_t) + this->HashSlots.capacity() * sizeof(std::uint32_t) +
         this->SortedIndex.capacity() * sizeof(std::uint32_t) + this->SortedXYZ.capacity() * sizeof(float);
}
} // namespace parafluid::surface
