#pragma once
// The particles' covered-volume fraction, sampled on a grid only where it can be non-zero.
//
//   phi(x) = V * sum_j W(|x - x_j|, r),  W = poly6 with support radius r, V = particle volume d^3,
//
// so phi is about 1 inside a uniformly filled region and falls to 0 at distance r beyond its last
// particles; phi = 1/2 sits on the edge of the volume the particles stand for (N * d^3 in all).
// The grid is cut into blocks of 8^3 points. A block holds values only when one of its points is
// within r + sqrt(3) * cell of some particle, so cells further than that from every particle are
// never allocated or visited, and a point of a missing block and all its neighbours have phi = 0.
// Blocks are found through a hash table; all loops run over blocks in a fixed order, so the values
// are the same for any number of threads. Values are kept only where marching cubes reads them:
// blocks the iso surface passes through and the blocks around them. Every other block keeps just
// its smallest and largest value (it lies wholly inside or wholly outside).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace parafluid::surface
{
class SparseDensityField
{
public:
  static constexpr int BlockPoints = 8; // grid points per block edge
  static constexpr int BlockSize = BlockPoints * BlockPoints * BlockPoints;

  /// Samples phi for n particles (x, y, z interleaved) on a grid of spacing `cellSize` [m] with
  /// kernel support `kernelRadius` [m] and particle volume `particleVolume` [m^3]. Throws
  /// std::invalid_argument for non-positive sizes, non-finite coordinates, or a bounding box too
  /// large to index (more than 2^21 blocks along an axis).
  void build(const float* xyz, std::size_t n, double cellSize, double kernelRadius, double particleVolume,
             double isoValue);

  std::size_t blockCount() const { return this->Keys.size(); }
  /// Block coordinates (in blocks) of block b; its point (i, j, k) is at
  /// origin + cellSize * (8 * block + (i, j, k)).
  void blockCoordinates(std::size_t b, int c[3]) const;
  /// Index of the block at block coordinates c, or -1 when it holds no values (phi = 0 there).
  std::int64_t findBlock(int bx, int by, int bz) const;
  /// The block's 512 values, x fastest; null for a block that lies wholly on one side of the iso
  /// value and borders no block the surface passes through.
  const float* values(std::size_t b) const { return this->Stored[b]; }
  /// Whether the iso surface can pass through block b's cells (its own points are on both sides,
  /// or a block above it, whose points its upper cells use, is on another side). Marching cubes
  /// polygonises exactly these blocks; they and their neighbours hold values.
  bool surfaceBlock(std::size_t b) const { return this->SurfaceBlock[b] != 0; }
  /// The iso value the field was built for.
  double isoValue() const { return this->IsoValue; }
  /// Smallest and largest value in block b.
  float minimum(std::size_t b) const { return this->Minimum[b]; }
  float maximum(std::size_t b) const { return this->Maximum[b]; }

  const double* origin() const { return this->Origin; }
  double cellSize() const { return this->CellSize; }
  double kernelRadius() const { return this->KernelRadius; }
  double particleVolume() const { return this->ParticleVolume; }

  /// Particles sorted by block: original index and position (in cells from the origin, x, y, z)
  /// of sorted slot k; the particles of
  /// block b are slots [particleBegin(b), particleEnd(b)).
  const std::vector<std::uint32_t>& sortedIndex() const { return this->SortedIndex; }
  const std::vector<float>& sortedPositions() const { return this->SortedXYZ; }
  std::uint32_t particleBegin(std::size_t b) const { return this->ParticleBegin[b]; }
  std::uint32_t particleEnd(std::size_t b) const { return this->ParticleBegin[b + 1]; }
  /// How far (in blocks) a particle's kernel reaches: blocks within this many of a point's block
  /// hold every particle that can contribute to it.
  int blockReach() const { return this->BlockReach; }

  /// Calls visit(k, ex, ey, ez, s2) for each sorted slot k whose particle lies within the kernel
  /// radius of the point x (in cells from the origin), with (ex, ey, ez) = particle - x and s2 its
  /// squared length, both in cells.
  template<typename Visit>
  void forEachParticleNear(const double x[3], Visit&& visit) const;

  /// phi and its gradient [1/m] at world point p, summed exactly over the particles (not read
  /// from the grid): the field marching cubes approximates.
  double evaluate(const double p[3], double gradient[3]) const;

  /// Frees the sampled values (values() is null for every block afterwards) but keeps the block
  /// tables and sorted particles that evaluate() and forEachParticleNear() read.
  void releaseValues();

  /// Bytes held (values, block tables, sorted particles), and the most held at once while the
  /// particles were being sorted.
  std::size_t bytes() const;
  std::size_t sortPeakBytes() const { return this->SortPeakBytes; }

  /// phi's normalisation: phi = scale * sum_j (rho^2 - s^2)^3 with s, rho in cells.
  static double kernelScale(double cellSize, double kernelRadius, double particleVolume);

private:
  void sortParticles(const float* xyz, std::size_t n);
  void allocateBlocks();
  void sampleBlocks(float iso);
  void splatBlock(std::size_t b, float* values) const;
  /// Calls visit(block index) for each allocated block within blockReach() of block coordinates bc.
  template<typename Visit>
  void forEachBlockAround(const int bc[3], Visit&& visit) const;
  void buildHash();
  std::uint64_t key(int bx, int by, int bz) const
  {
    return (static_cast<std::uint64_t>(bz) << 42) | (static_cast<std::uint64_t>(by) << 21) |
           static_cast<std::uint64_t>(bx);
  }

  double Origin[3] = { 0, 0, 0 };
  double CellSize = 1, KernelRadius = 1, ParticleVolume = 1;
  int BlockReach = 1;
  std::size_t SortPeakBytes = 0;
  double IsoValue = 0.5;
  std::vector<char> SurfaceBlock;
  std::vector<std::uint64_t> Keys;               // sorted block keys of the allocated blocks
  std::vector<std::uint32_t> ParticleBegin;      // Keys.size() + 1 entries
  std::vector<const float*> Stored;              // per block: its values or null
  std::vector<std::unique_ptr<float[]>> Storage; // the kept blocks' values
  std::vector<float> Minimum, Maximum;
  std::vector<std::uint64_t> HashKeys;
  std::vector<std::uint32_t> HashSlots;
  std::vector<std::uint32_t> SortedIndex;
  std::vector<float> SortedXYZ; // in cells from the origin
};
template<typename Visit>
void SparseDensityField::forEachBlockAround(const int bc[3], Visit&& visit) const
{
  const int reach = this->BlockReach;
  for (int dz = -reach; dz <= reach; ++dz)
  {
    for (int dy = -reach; dy <= reach; ++dy)
    {
      for (int dx = -reach; dx <= reach; ++dx)
      {
        const std::int64_t nb = this->findBlock(bc[0] + dx, bc[1] + dy, bc[2] + dz);
        if (nb >= 0)
        {
          visit(nb);
        }
      }
    }
  }
}

template<typename Visit>
void SparseDensityField::forEachParticleNear(const double x[3], Visit&& visit) const
{
  const double rho = this->KernelRadius / this->CellSize;
  const double rho2 = rho * rho;
  int bc[3];
  for (int a = 0; a < 3; ++a)
  {
    bc[a] = static_cast<int>(std::floor(x[a] / BlockPoints));
  }
  this->forEachBlockAround(bc,
                           [&](std::int64_t nb)
                           {
                             for (std::uint32_t k = this->particleBegin(nb); k < this->particleEnd(nb); ++k)
                             {
                               const double ex = this->SortedXYZ[3 * k] - x[0], ey = this->SortedXYZ[3 * k + 1] - x[1],
                                            ez = this->SortedXYZ[3 * k + 2] - x[2];
                               const double s2 = ex * ex + ey * ey + ez * ez;
                               if (s2 < rho2)
                               {
                                 visit(k, ex, ey, ez, s2);
                               }
                             }
                           });
}
} // namespace parafluid::surface
