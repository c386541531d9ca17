#pragma once
// The particles sorted into a uniform grid whose cells are at least the kernel radius wide, for
// evaluating the covered-volume fraction phi (SparseDensityField's field) anywhere by summing over
// the cells around a point, and a conservative map of where phi can reach the iso value.
//
// The ray-marched fluid (Representations/Fluid) uploads these tables to the GPU as they are:
// sorted positions, each cell's first particle, and the two levels of the occupancy map that its
// rays use to skip empty space (Wu et al. 2022, "Fluid rendering with empty-space skipping").
//
// Occupancy bound: for a cell C, phi(x) <= V * sum_j W(dist(x_j, C)) for every x in C, because
// the poly6 kernel falls with distance and dist(x_j, C) <= |x - x_j|. A cell whose bound is
// below the iso value holds no point of the surface and no fluid; a block of BlockCells^3 cells
// is empty when all its cells are.
//
// Splat classes (for start/stop depth maps from splats, Xiao et al. 2017): every point where phi
// reaches the iso value lies in an occupied cell and within kernelRadius of a particle, whose cell
// is one of the 27 around it (cells are at least kernelRadius wide). So a particle with no
// occupied cell among its 27 never bounds the surface (SplatNone: isolated droplets whose field
// stays below the iso value). The others are Splash when their 27 cells hold fewer than an eighth
// of the particles a full lattice of the spacing would put there (spray, thin sheets), else Bulk.
// Separate depth maps for the two let a ray through spray skip the gap down to the bulk. A cell's
// box grown by kernelRadius holds the kernel spheres of all its particles, so splatting those
// boxes (splatCells(): far fewer than particles) bounds the surface as the spheres do.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid::surface
{
class DensityCellGrid
{
public:
  static constexpr int BlockCells = 4;                      // cells per block edge (the coarse level of the occupancy)
  static constexpr std::uint32_t OccupiedBit = 0x80000000u; // in cellStart(): the cell may hold phi >= iso
  /// The fourth float of each sorted particle (sortedPositions()).
  static constexpr float SplatBulk = 0.0f, SplatSplash = 1.0f, SplatNone = -1.0f;

  /// Sorts n particles (x, y, z interleaved) of spacing `spacing` [m] (particle volume spacing^3)
  /// for the poly6 kernel of support `kernelRadius` [m], and marks where phi can reach
  /// `isoValue`. Cells are kernelRadius wide, wider when the bounding box would need more than
  /// `maxCells` cells (the tables stay bounded for any spread of particles). Particles with a
  /// non-finite coordinate are left out (counted by skipped()). Throws std::invalid_argument for
  /// a non-positive or non-finite spacing, kernel radius or iso value, or maxCells < 1.
  void build(const float* xyz, std::size_t n, double spacing, double kernelRadius, double isoValue,
             std::size_t maxCells = std::size_t(1) << 24);

  std::size_t particleCount() const { return this->Order.size(); }
  std::size_t skipped() const { return this->Skipped; }
  const double* origin() const { return this->Origin; }
  double cellSize() const { return this->CellSize; }
  const int* dims() const { return this->Dims; }
  const int* blockDims() const { return this->BlockDims; }
  double kernelRadius() const { return this->KernelRadius; }
  double isoValue() const { return this->IsoValue; }
  /// phi = kernelScale() * sum_j (r^2 - s^2)^3 with s, r in metres (r: kernelRadius()).
  double kernelScale() const { return this->Scale; }

  /// x, y, z [m] and the splat class (SplatBulk, SplatSplash, SplatNone) of each sorted particle
  /// (four floats: one RGBA texel each).
  const std::vector<float>& sortedPositions() const { return this->Sorted; }
  /// Original index of each sorted particle.
  const std::vector<std::uint32_t>& order() const { return this->Order; }
  /// dims[0] * dims[1] * dims[2] + 1 entries, x fastest: the particles of cell c are sorted slots
  /// [cellStart[c] & ~OccupiedBit, cellStart[c + 1] & ~OccupiedBit); bit 31 of entry c is set when
  /// phi may reach the iso value in cell c.
  const std::vector<std::uint32_t>& cellStart() const { return this->CellStart; }
  /// One byte per block (x fastest): 1 when one of its cells is occupied.
  const std::vector<std::uint8_t>& blockOccupied() const { return this->BlockOccupied; }
  bool cellOccupied(int i, int j, int k) const;
  std::size_t occupiedCells() const { return this->OccupiedCells; }
  /// x, y, z of the lower corner [m] and the splat class of each cell that holds particles of
  /// class SplatBulk or SplatSplash (four floats per cell).
  const std::vector<float>& splatCells() const { return this->SplatCells; }
  /// Particles of each splat class.
  std::size_t splashParticles() const { return this->SplashParticles; }
  std::size_t unsplattedParticles() const { return this->UnsplattedParticles; }

  /// phi and its gradient [1/m] at p [m], summed over the particles of the cells around p.
  double evaluate(const double p[3], double gradient[3]) const;

private:
  void markOccupancy();
  void classifySplats(double spacing);

  double Origin[3] = { 0, 0, 0 };
  double CellSize = 1, KernelRadius = 1, IsoValue = 0.5, Scale = 0;
  int Dims[3] = { 0, 0, 0 }, BlockDims[3] = { 0, 0, 0 };
  std::size_t Skipped = 0, OccupiedCells = 0, SplashParticles = 0, UnsplattedParticles = 0;
  std::vector<float> Sorted, SplatCells;
  std::vector<std::uint32_t> Order, CellStart;
  std::vector<std::uint8_t> BlockOccupied;
};
} // namespace parafluid::surface
