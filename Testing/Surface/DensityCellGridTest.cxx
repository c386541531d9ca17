// The ray-marched fluid's particle grid: the same field as Particle Surface's, and an occupancy
// map that never calls a cell empty where phi reaches the iso value.
#include "parafluid/surface/DensityCellGrid.h"
#include "parafluid/surface/SparseDensityField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace parafluid::surface;

namespace
{
// A jittered lattice block plus a few isolated spray particles far above it.
std::vector<float> blockWithSpray(double d, int nx, int ny, int nz, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2 * d, 0.2 * d);
  std::vector<float> xyz;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        xyz.push_back(static_cast<float>(i * d + u(rng)));
        xyz.push_back(static_cast<float>(j * d + u(rng)));
        xyz.push_back(static_cast<float>(k * d + u(rng)));
      }
  for (int s = 0; s < 20; ++s)
  {
    xyz.push_back(static_cast<float>((s % 5) * 3.0 * d));
    xyz.push_back(static_cast<float>((s / 5) * 3.0 * d));
    xyz.push_back(static_cast<float>((nz + 8) * d));
  }
  return xyz;
}
} // namespace

TEST(DensityCellGrid, FieldEqualsParticleSurfacesField)
{
  const double d = 0.02, r = 2.0 * d;
  const std::vector<float> xyz = blockWithSpray(d, 12, 10, 8, 1);
  DensityCellGrid grid;
  grid.build(xyz.data(), xyz.size() / 3, d, r, 0.5);
  SparseDensityField field;
  field.build(xyz.data(), xyz.size() / 3, 0.5 * d, r, d * d * d, 0.5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 0.35);
  for (int s = 0; s < 2000; ++s)
  {
    const double p[3] = { u(rng), u(rng), u(rng) };
    double g1[3], g2[3];
    const double a = grid.evaluate(p, g1), b = field.evaluate(p, g2);
    // (Particle Surface keeps positions in cells as floats: agreement to float rounding.)
    ASSERT_NEAR(a, b, 1e-7 + 1e-5 * std::abs(b));
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_NEAR(g1[k], g2[k], 1e-4 + 1e-4 * std::abs(g2[k]));
    }
  }
}

TEST(DensityCellGrid, EmptyCellsNeverReachTheIsoValue)
{
  const double d = 0.02, r = 2.0 * d;
  const std::vector<float> xyz = blockWithSpray(d, 12, 10, 8, 2);
  for (double iso : { 0.05, 0.5, 0.9 })
  {
    DensityCellGrid grid;
    grid.build(xyz.data(), xyz.size() / 3, d, r, iso);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.1, 0.4);
    int checked = 0;
    for (int s = 0; s < 40000; ++s)
    {
      const double p[3] = { u(rng), u(rng), u(rng) };
      double g[3];
      if (grid.evaluate(p, g) < iso)
      {
        continue;
      }
      ++checked;
      int c[3];
      for (int a = 0; a < 3; ++a)
      {
        c[a] = static_cast<int>(std::floor((p[a] - grid.origin()[a]) / grid.cellSize()));
      }
      ASSERT_TRUE(grid.cellOccupied(c[0], c[1], c[2])) << "phi >= " << iso << " in an empty cell";
      const int B = DensityCellGrid::BlockCells;
      const int* bd = grid.blockDims();
      ASSERT_TRUE(grid.blockOccupied()[(static_cast<std::size_t>(c[2] / B) * bd[1] + c[1] / B) * bd[0] + c[0] / B]);
    }
    EXPECT_GT(checked, 1000);
    // And the map is useful: the air between the block and the spray is empty.
    const double gap[3] = { 0.1, 0.1, 0.23 }; // 4.5 d from the block's top and from the spray
    int c[3];
    for (int a = 0; a < 3; ++a)
    {
      c[a] = static_cast<int>(std::floor((gap[a] - grid.origin()[a]) / grid.cellSize()));
    }
    EXPECT_FALSE(grid.cellOccupied(c[0], c[1], c[2]));
    const std::size_t cells = static_cast<std::size_t>(grid.dims()[0]) * grid.dims()[1] * grid.dims()[2];
    EXPECT_LT(grid.occupiedCells(), cells);
  }
}

TEST(DensityCellGrid, SortKeepsEveryFiniteParticleOnceAndSkipsNaN)
{
  const double d = 0.02;
  std::vector<float> xyz = blockWithSpray(d, 5, 5, 5, 3);
  const std::size_t n = xyz.size() / 3;
  xyz.push_back(std::numeric_limits<float>::quiet_NaN());
  xyz.push_back(0.0f);
  xyz.push_back(0.0f);
  DensityCellGrid grid;
  grid.build(xyz.data(), n + 1, d, 2 * d, 0.5);
  EXPECT_EQ(grid.skipped(), 1u);
  ASSERT_EQ(grid.particleCount(), n);
  std::vector<int> seen(n, 0);
  for (std::uint32_t i : grid.order())
  {
    ASSERT_LT(i, n);
    ++seen[i];
  }
  for (int s : seen)
  {
    EXPECT_EQ(s, 1);
  }
  // Every sorted particle lies in the cell whose range holds it.
  const int* dims = grid.dims();
  for (std::size_t c = 0; c < static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]; ++c)
  {
    const std::uint32_t b = grid.cellStart()[c] & ~DensityCellGrid::OccupiedBit;
    const std::uint32_t e = grid.cellStart()[c + 1] & ~DensityCellGrid::OccupiedBit;
    const int idx[3] = { static_cast<int>(c % dims[0]), static_cast<int>(c / dims[0] % dims[1]),
                         static_cast<int>(c / dims[0] / dims[1]) };
    for (std::uint32_t s = b; s < e; ++s)
    {
      for (int a = 0; a < 3; ++a)
      {
        const double g = (grid.sortedPositions()[4 * s + a] - grid.origin()[a]) / grid.cellSize();
        EXPECT_GE(g, idx[a] - 1e-6);
        EXPECT_LT(g, idx[a] + 1 + 1e-6);
      }
    }
  }
}

TEST(DensityCellGrid, TablesStayBoundedForFarApartParticles)
{
  const float xyz[] = { 0.0f, 0.0f, 0.0f, 1.0e6f, 1.0e6f, 1.0e6f };
  DensityCellGrid grid;
  grid.build(xyz, 2, 0.01, 0.02, 0.5, 1 << 20);
  const double cells = static_cast<double>(grid.dims()[0]) * grid.dims()[1] * grid.dims()[2];
  EXPECT_LE(cells, static_cast<double>(1 << 20));
  double g[3];
  const double p[3] = { 0.0, 0.0, 0.0 };
  EXPECT_GT(grid.evaluate(p, g), 0.0); // still the exact field, through wider cells
}

TEST(DensityCellGrid, EmptyInputAndBadParametersAreClear)
{
  DensityCellGrid grid;
  grid.build(nullptr, 0, 0.01, 0.02, 0.5);
  EXPECT_EQ(grid.particleCount(), 0u);
  const float nan[] = { std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f };
  grid.build(nan, 1, 0.01, 0.02, 0.5);
  EXPECT_EQ(grid.particleCount(), 0u);
  EXPECT_EQ(grid.skipped(), 1u);
  const float one[] = { 0.0f, 0.0f, 0.0f };
  EXPECT_THROW(grid.build(one, 1, 0.0, 0.02, 0.5), std::invalid_argument);
  EXPECT_THROW(grid.build(one, 1, 0.01, std::nan(""), 0.5), std::invalid_argument);
  EXPECT_THROW(grid.build(one, 1, 0.01, 0.02, -1.0), std::invalid_argument);
}

TEST(DensityCellGrid, EveryParticleNearTheSurfaceIsSplattedAndSprayIsSplash)
{
  // Block, isolated droplets (spaced 3 d: no surface of their own), and a clump of 2 x 2 x 2
  // particles (a splash drop with a surface: phi 0.84 at its centre) far from the block.
  const double d = 0.02, r = 2.0 * d;
  std::vector<float> xyz = blockWithSpray(d, 12, 10, 8, 3);
  const std::size_t blockCount = 12 * 10 * 8;
  const std::size_t clumpFirst = xyz.size() / 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
      {
        xyz.push_back(static_cast<float>(0.5 + i * d));
        xyz.push_back(static_cast<float>(0.1 + j * d));
        xyz.push_back(static_cast<float>(0.1 + k * d));
      }
  DensityCellGrid grid;
  grid.build(xyz.data(), xyz.size() / 3, d, r, 0.5);
  const std::vector<float>& sorted = grid.sortedPositions();
  const std::vector<std::uint32_t>& order = grid.order();
  std::vector<float> classOf(xyz.size() / 3);
  for (std::size_t s = 0; s < order.size(); ++s)
  {
    classOf[order[s]] = sorted[4 * s + 3];
  }
  // The block's core is bulk, the droplets are never splatted, the clump is splash.
  EXPECT_EQ(classOf[(4 * 10 + 5) * 12 + 6], DensityCellGrid::SplatBulk);
  for (std::size_t i = blockCount; i < clumpFirst; ++i)
  {
    EXPECT_EQ(classOf[i], DensityCellGrid::SplatNone) << "droplet " << i;
  }
  for (std::size_t i = clumpFirst; i < classOf.size(); ++i)
  {
    EXPECT_EQ(classOf[i], DensityCellGrid::SplatSplash) << "clump particle " << i;
  }
  EXPECT_EQ(grid.unsplattedParticles(), clumpFirst - blockCount);
  EXPECT_GE(grid.splashParticles(), 8u);
  // The splat cells are the cells of the splatted particles, with their class.
  std::size_t splatted = 0;
  const std::vector<float>& cells = grid.splatCells();
  for (std::size_t s = 0; s < order.size(); ++s)
  {
    if (sorted[4 * s + 3] == DensityCellGrid::SplatNone)
    {
      continue;
    }
    ++splatted;
    bool found = false;
    for (std::size_t c = 0; c < cells.size() / 4 && !found; ++c)
    {
      bool inside = cells[4 * c + 3] == sorted[4 * s + 3];
      for (int a = 0; a < 3; ++a)
      {
        inside = inside && sorted[4 * s + a] >= cells[4 * c + a] - 1e-6 &&
                 sorted[4 * s + a] <= cells[4 * c + a] + grid.cellSize() + 1e-6;
      }
      found = inside;
    }
    ASSERT_TRUE(found) << "splatted particle " << s << " lies in no splat cell of its class";
  }
  EXPECT_EQ(splatted, order.size() - grid.unsplattedParticles());
  EXPECT_LT(cells.size() / 4, splatted / 2) << "fewer splat cells than splatted particles";
  // Conservative: every particle within the kernel of a point where phi >= iso is splatted.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.1, 0.6);
  int checked = 0;
  for (int s = 0; s < 100000 && checked < 3000; ++s)
  {
    const double p[3] = { u(rng), u(rng) * 0.5, u(rng) * 0.5 };
    double g[3];
    if (grid.evaluate(p, g) < 0.5)
    {
      continue;
    }
    ++checked;
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      const double dx = sorted[4 * k] - p[0], dy = sorted[4 * k + 1] - p[1], dz = sorted[4 * k + 2] - p[2];
      if (dx * dx + dy * dy + dz * dz < r * r)
      {
        ASSERT_NE(sorted[4 * k + 3], DensityCellGrid::SplatNone) << "a particle near the surface is not splatted";
      }
    }
  }
  EXPECT_GT(checked, 500);
}
