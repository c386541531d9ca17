// The terrain contract's checks, no-data filling, and the shading aids on shapes with known slope
// and curvature.
#include "parafluid/terrain/ElevationGrid.h"
#include "parafluid/terrain/TerrainShading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
using namespace parafluid::terrain;

ElevationGrid grid(int nx, int ny, double d, double (*f)(double, double))
{
  ElevationGrid g;
  g.nx = nx, g.ny = ny, g.dx = g.dy = d;
  g.elevation.resize(g.size());
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      g.elevation[g.index(i, j)] = static_cast<float>(f(i * d, j * d));
    }
  }
  return g;
}

TEST(ElevationGrid, NamesWhatIsWrong)
{
  ElevationGrid g = grid(4, 4, 1.0, [](double, double) { return 0.0; });
  EXPECT_TRUE(g.problem().empty());
  g.elevation[5] = std::nanf("");
  EXPECT_NE(g.problem().find("not finite"), std::string::npos);
  g.nx = 1;
  EXPECT_NE(g.problem().find("2 x 2"), std::string::npos);
}

TEST(ElevationGrid, NoDataHolesAreFilledFromTheirRim)
{
  // A plane with a square hole: filling by neighbour means reproduces a plane's interior closely.
  ElevationGrid g = grid(40, 30, 1.0, [](double x, double y) { return 2.0 + 0.5 * x - 0.25 * y; });
  const std::vector<float> truth = g.elevation;
  std::vector<unsigned char> valid(g.size(), 1);
  for (int j = 10; j < 20; ++j)
  {
    for (int i = 12; i < 22; ++i)
    {
      valid[g.index(i, j)] = 0;
      g.elevation[g.index(i, j)] = -9999.0f;
    }
  }
  EXPECT_EQ(fillNoData(g.elevation, g.nx, g.ny, valid), 100u);
  for (std::size_t k = 0; k < g.size(); ++k)
  {
    EXPECT_NEAR(g.elevation[k], truth[k], 2.0);
    EXPECT_GT(g.elevation[k], -10.0f);
  }
  std::vector<unsigned char> none(g.size(), 0);
  EXPECT_THROW(fillNoData(g.elevation, g.nx, g.ny, none), std::invalid_argument);
}

TEST(TerrainShading, SlopeOfAPlaneAndCurvatureOfAParaboloid)
{
  // z = tan(30 deg) x: a 30 degree slope everywhere (edges included: one-sided differences).
  const ElevationGrid plane = grid(20, 10, 2.0, [](double x, double) { return std::tan(M_PI / 6) * x; });
  for (const float s : terrainSlope(plane))
  {
    EXPECT_NEAR(s, 30.0f, 1e-3f);
  }
  const std::vector<float> n = terrainNormals(plane);
  EXPECT_NEAR(n[0], -0.5f, 1e-5f);
  EXPECT_NEAR(n[2], std::sqrt(3.0f) / 2.0f, 1e-5f);
  // z = 0.1 (x^2 + y^2): Laplacian 0.4 1/m inside (a hollow: positive).
  const ElevationGrid bowl =
    grid(21, 21, 0.5, [](double x, double y) { return 0.1 * ((x - 5) * (x - 5) + (y - 5) * (y - 5)); });
  const std::vector<float> c = terrainCurvature(bowl);
  for (int j = 1; j < 20; ++j)
  {
    for (int i = 1; i < 20; ++i)
    {
      EXPECT_NEAR(c[bowl.index(i, j)], 0.4f, 1e-3f);
    }
  }
}
} // namespace
