// The carpet height field: flat under a flat sheet, falling at the stated acceleration once the
// particles leave, and a quadtree that only holds (and visits) the wet part of a large grid.
#include "parafluid/surface/CarpetSurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace parafluid::surface;

namespace
{
// A sheet of particles at height z over [x0, x1] x [y0, y1] with spacing d.
std::vector<float> sheet(double x0, double x1, double y0, double y1, double d, double z)
{
  std::vector<float> xyz;
  const int nx = static_cast<int>(std::lround((x1 - x0) / d)), ny = static_cast<int>(std::lround((y1 - y0) / d));
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      xyz.insert(xyz.end(), { float(x0 + (i + 0.5) * d), float(y0 + (j + 0.5) * d), float(z) });
    }
  }
  return xyz;
}

CarpetSurface flatCarpet(int n, float ground = 0.0f)
{
  CarpetSurface carpet;
  carpet.setGrid(0.0, 0.0, 1.0, 1.0, n, std::vector<float>(static_cast<std::size_t>(n) * n, ground));
  return carpet;
}
} // namespace

TEST(CarpetSurface, FlatSheetGivesAFlatCarpetAtItsHeight)
{
  CarpetSurface carpet = flatCarpet(32, 0.05f);
  const std::vector<float> xyz = sheet(0.25, 0.75, 0.25, 0.75, 0.01, 0.3);
  carpet.advance(xyz.data(), xyz.size() / 3, 0.0, 9.81, 0.001);
  std::vector<float> depth;
  const SurfaceMesh mesh = carpet.mesh(&depth);
  EXPECT_EQ(carpet.wetCells(), 16u * 16u);
  ASSERT_EQ(mesh.triangleCount(), 2u * 16u * 16u);
  EXPECT_EQ(mesh.vertexCount(), 17u * 17u) << "corners are shared";
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
  {
    EXPECT_FLOAT_EQ(mesh.points[3 * v + 2], 0.3f);
    EXPECT_NEAR(depth[v], 0.25f, 1e-6f);
    EXPECT_FLOAT_EQ(mesh.normals[3 * v + 2], 1.0f);
    EXPECT_GE(mesh.points[3 * v], 0.25f - 1e-6f);
    EXPECT_LE(mesh.points[3 * v], 0.75f + 1e-6f);
  }
}

TEST(CarpetSurface, CarpetFallsToTheTerrainInTheTimeTheAccelerationGives)
{
  const double height = 0.3, ground = 0.05, minDepth = 0.001, fall = 4.0, dt = 0.005;
  CarpetSurface carpet = flatCarpet(16, static_cast<float>(ground));
  const std::vector<float> xyz = sheet(0.0, 1.0, 0.0, 1.0, 0.02, height);
  carpet.advance(xyz.data(), xyz.size() / 3, 0.0, fall, minDepth);
  ASSERT_EQ(carpet.wetCells(), 256u);
  // h(t) = H - a t^2 / 2 until it is within minDepth of the ground.
  const double predicted = std::sqrt(2.0 * (height - ground - minDepth) / fall);
  double t = 0.0;
  while (carpet.wetCells() > 0 && t < 10.0)
  {
    carpet.advance(nullptr, 0, dt, fall, minDepth);
    t += dt;
    if (carpet.wetCells() > 0)
    {
      EXPECT_NEAR(carpet.cellHeight(3, 5), height - 0.5 * fall * t * t, 1e-5);
    }
  }
  EXPECT_GE(t, predicted - 1e-9);
  EXPECT_LT(t, predicted + dt);
  EXPECT_EQ(carpet.mesh().triangleCount(), 0u);
}

TEST(CarpetSurface, ParticlesArrivingStopTheFall)
{
  CarpetSurface carpet = flatCarpet(8);
  std::vector<float> xyz = sheet(0.0, 1.0, 0.0, 1.0, 0.05, 0.5);
  carpet.advance(xyz.data(), xyz.size() / 3, 0.0, 9.81, 0.001);
  carpet.advance(nullptr, 0, 0.1, 9.81, 0.001);
  EXPECT_NEAR(carpet.cellHeight(2, 2), 0.5 - 0.5 * 9.81 * 0.01, 1e-5);
  // Particles come back lower over the left half: those cells take their height and stop; the
  // right half goes on falling from where it was, faster.
  xyz = sheet(0.0, 0.5, 0.0, 1.0, 0.05, 0.2);
  carpet.advance(xyz.data(), xyz.size() / 3, 0.05, 9.81, 0.001);
  EXPECT_FLOAT_EQ(static_cast<float>(carpet.cellHeight(1, 2)), 0.2f);
  EXPECT_NEAR(carpet.cellHeight(6, 2), 0.5 - 0.5 * 9.81 * 0.15 * 0.15, 1e-5);
}

TEST(CarpetSurface, QuadtreeHoldsAndVisitsOnlyTheWetCells)
{
  // A 12 x 12-cell puddle in a 1024 x 1024 grid: the tree holds a few hundred nodes, not a million,
  // and the traversal enters each of them once.
  const int n = 1024;
  CarpetSurface carpet = flatCarpet(n);
  const double cell = 1.0 / n;
  const std::vector<float> xyz = sheet(300 * cell, 312 * cell, 600 * cell, 612 * cell, 0.5 * cell, 0.01);
  carpet.advance(xyz.data(), xyz.size() / 3, 0.0, 9.81, 0.001);
  std::size_t visited = 0;
  const SurfaceMesh mesh = carpet.mesh(nullptr, &visited);
  const std::size_t wet = carpet.wetCells();
  EXPECT_EQ(wet, 144u);
  EXPECT_EQ(mesh.triangleCount(), 2 * wet);
  EXPECT_EQ(visited, carpet.quadtreeNodes());
  // Each level holds at most a quarter of the level below plus a border, and there are
  // log2(1024) = 10 levels above the cells.
  EXPECT_LE(visited, 2 * wet + 4 * 10);
  std::printf("wet cells %zu, quadtree nodes visited %zu (grid %d^2)\n", wet, visited, n);
}

TEST(CarpetSurface, ParentsTakeTheMeanOfTheirChildren)
{
  CarpetSurface carpet = flatCarpet(4);
  // Cells (0,0), (1,0), (0,1) at heights 0.1, 0.2, 0.6; (1,1) dry.
  const float xyz[] = { 0.1f, 0.1f, 0.1f, 0.35f, 0.1f, 0.2f, 0.1f, 0.35f, 0.6f };
  carpet.advance(xyz, 3, 0.0, 9.81, 0.001);
  EXPECT_NEAR(carpet.meanHeight(1, 0, 0), 0.3, 1e-6);
  EXPECT_NEAR(carpet.meanHeight(2, 0, 0), 0.3, 1e-6);
  EXPECT_TRUE(std::isnan(carpet.meanHeight(1, 1, 1)));
  EXPECT_TRUE(std::isnan(carpet.cellHeight(1, 1)));
}

TEST(CarpetSurface, FluidUnderTheTerrainIsNotShown)
{
  CarpetSurface carpet = flatCarpet(8, 0.5f);
  const std::vector<float> xyz = sheet(0.0, 1.0, 0.0, 1.0, 0.05, 0.2);
  carpet.advance(xyz.data(), xyz.size() / 3, 0.0, 9.81, 0.001);
  EXPECT_EQ(carpet.wetCells(), 0u);
  EXPECT_EQ(carpet.mesh().triangleCount(), 0u);
}

TEST(CarpetSurface, BadInputIsRefused)
{
  CarpetSurface carpet;
  EXPECT_THROW(carpet.advance(nullptr, 0, 0.0, 9.81, 0.0), std::logic_error);
  EXPECT_THROW(carpet.setGrid(0, 0, 1, 1, 0, {}), std::invalid_argument);
  EXPECT_THROW(carpet.setGrid(0, 0, 0, 1, 2, std::vector<float>(4, 0.0f)), std::invalid_argument);
  EXPECT_THROW(carpet.setGrid(0, 0, 1, 1, 2, std::vector<float>(3, 0.0f)), std::invalid_argument);
  carpet = flatCarpet(4);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float xyz[] = { 0.5f, nan, 0.1f };
  EXPECT_THROW(carpet.advance(xyz, 1, 0.0, 9.81, 0.0), std::invalid_argument);
  EXPECT_THROW(carpet.advance(nullptr, 0, -1.0, 9.81, 0.0), std::invalid_argument);
}
