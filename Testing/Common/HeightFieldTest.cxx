// The height field of Common: bilinear elevation (exact on a plane), depth below the water level,
// constant beyond the grid, and a terrain rasterised from triangles.
#include "parafluid/common/HeightField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using parafluid::HeightField;

TEST(HeightField, PlaneIsExactAndDepthIsLevelMinusHeight)
{
  // z = 0.5 x - 0.25 y + 1 on 5 x 4 nodes, spacing 2 x 3, origin (10, 20); water level 4.
  const int nx = 5, ny = 4;
  std::vector<float> z;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      z.push_back(static_cast<float>(0.5 * (10 + 2 * i) - 0.25 * (20 + 3 * j) + 1));
    }
  }
  const HeightField field(z, nx, ny, 10.0, 20.0, 2.0, 3.0, 4.0);
  for (double x : { 10.0, 11.3, 15.9, 18.0 })
  {
    for (double y : { 20.0, 24.2, 29.0 })
    {
      const double plane = 0.5 * x - 0.25 * y + 1;
      EXPECT_NEAR(field.heightAt(x, y), plane, 1e-5) << x << ", " << y;
      EXPECT_NEAR(field.depth(x, y), 4.0 - field.heightAt(x, y), 1e-12);
    }
  }
  // Beyond the edges the border value holds.
  EXPECT_NEAR(field.heightAt(100.0, 20.0), field.heightAt(18.0, 20.0), 1e-12);
  EXPECT_NEAR(field.heightAt(10.0, -50.0), field.heightAt(10.0, 20.0), 1e-12);
}

TEST(HeightField, TerrainFromTrianglesKeepsTheHighestSurface)
{
  // Two stacked squares over [0, 1]^2: z = 1 and z = 3; the raster keeps 3 everywhere.
  const std::vector<float> points = { 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, 0, 3, 1, 0, 3, 1, 1, 3, 0, 1, 3 };
  const std::vector<std::uint32_t> triangles = { 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7 };
  const HeightField field = HeightField::fromTriangles(points, triangles, 8, 8, 5.0);
  EXPECT_NEAR(field.heightAt(0.5, 0.5), 3.0, 1e-6);
  EXPECT_NEAR(field.depth(0.25, 0.75), 2.0, 1e-6);
}

TEST(HeightField, NaNQueriesAnswerNaNAndNaNTerrainsAreRefused)
{
  // A NaN query used to pass std::clamp and be cast to a cell index (a read outside the grid);
  // a terrain with a NaN point used to do the same while it was rasterised.
  const HeightField field(std::vector<float>(16, 1.0f), 4, 4, 0.0, 0.0, 1.0, 1.0, 2.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(field.heightAt(nan, 1.0)));
  EXPECT_TRUE(std::isnan(field.depth(1.0, nan)));
  double gradient[2];
  field.depthGradient(nan, nan, gradient);              // must stay inside the grid
  EXPECT_DOUBLE_EQ(field.heightAt(1e300, -1e300), 1.0); // far away: the edge's height
  const std::vector<float> points = { 0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0 };
  EXPECT_THROW(HeightField::fromTriangles(points, { 0, 1, 2 }, 4, 4, 0.0), std::invalid_argument);
}
