// Procedural terrain: the same seed gives the same terrain on 1 and 2 threads (every method),
// different seeds different terrains; heights follow HeightScale and BaseHeight; settings out of
// range are refused by name.
#include "parafluid/terrain/TerrainGenerator.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <stdexcept>

namespace
{
using namespace parafluid::terrain;

ElevationGrid makeGrid(const TerrainSettings& s, int threads, int n = 200)
{
  ElevationGrid grid;
  grid.nx = n;
  grid.ny = n + 17;
  grid.x0 = 1000.0;
  grid.y0 = -300.0;
  grid.dx = grid.dy = 5.0;
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  generateTerrain(s, grid);
  omp_set_num_threads(before);
  return grid;
}

std::vector<TerrainSettings> everyMethod()
{
  std::vector<TerrainSettings> all;
  for (const FractalType type : { FractalType::FBm, FractalType::Turbulence, FractalType::Ridged })
  {
    TerrainSettings s;
    s.fractal.type = type;
    all.push_back(s);
  }
  TerrainSettings warped;
  warped.warpStrength = 150.0;
  all.push_back(warped);
  TerrainSettings square;
  square.method = TerrainMethod::DiamondSquare;
  all.push_back(square);
  return all;
}

TEST(TerrainGenerator, SameSeedSameTerrainOnAnyThreadCount)
{
  for (TerrainSettings s : everyMethod())
  {
    s.seed = 1234;
    const ElevationGrid one = makeGrid(s, 1), two = makeGrid(s, 2), four = makeGrid(s, 4);
    EXPECT_EQ(one.elevation, two.elevation);
    EXPECT_EQ(one.elevation, four.elevation);
  }
}

TEST(TerrainGenerator, DifferentSeedsDifferentTerrains)
{
  for (TerrainSettings s : everyMethod())
  {
    s.seed = 1;
    const ElevationGrid a = makeGrid(s, 2);
    s.seed = 2;
    const ElevationGrid b = makeGrid(s, 2);
    std::size_t differ = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
    {
      differ += a.elevation[k] != b.elevation[k] ? 1 : 0;
    }
    EXPECT_GT(differ, a.size() * 9 / 10);
  }
}

TEST(TerrainGenerator, HeightsFollowScaleAndBase)
{
  TerrainSettings s;
  s.heightScale = 80.0;
  s.baseHeight = 500.0;
  const ElevationGrid g = makeGrid(s, 2);
  float lo = 1e9f, hi = -1e9f;
  for (const float h : g.elevation)
  {
    lo = std::fmin(lo, h), hi = std::fmax(hi, h);
  }
  // fBm in [-1, 1] (normalised by the amplitudes' sum) times 80 m about 500 m, and not flat.
  EXPECT_GE(lo, 420.0f);
  EXPECT_LE(hi, 580.0f);
  EXPECT_GT(hi - lo, 20.0f);
}

TEST(TerrainGenerator, WarpingMovesTheTerrainAndRowsMatchPointSamples)
{
  TerrainSettings plain;
  TerrainSettings warped = plain;
  warped.warpStrength = 200.0;
  const ElevationGrid a = makeGrid(plain, 2), b = makeGrid(warped, 2);
  double difference = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    difference += std::fabs(a.elevation[k] - b.elevation[k]);
  }
  EXPECT_GT(difference / a.size(), 1.0);
  // The row evaluation (octave by octave, 8 points at a time) gives fractal() point by point.
  const PerlinNoise noise(plain.seed);
  for (const FractalType type : { FractalType::FBm, FractalType::Turbulence, FractalType::Ridged })
  {
    FractalSettings settings = plain.fractal;
    settings.type = type;
    std::vector<float> row(67);
    fractalRow(noise, settings, 3.7f, 0.05f, 1.3f, 67, row.data());
    for (int i = 0; i < 67; ++i)
    {
      EXPECT_NEAR(row[static_cast<std::size_t>(i)], fractal(noise, settings, 3.7f + 0.05f * i, 1.3f), 1e-5f);
    }
  }
}

TEST(TerrainGenerator, RefusesSettingsOutOfRangeByName)
{
  const auto problem = [](TerrainSettings s)
  {
    ElevationGrid g;
    g.nx = g.ny = 16;
    try
    {
      generateTerrain(s, g);
    }
    catch (const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  TerrainSettings s;
  s.fractal.octaves = 0;
  EXPECT_NE(problem(s).find("Octaves"), std::string::npos);
  s = {};
  s.fractal.persistence = std::nanf("");
  EXPECT_NE(problem(s).find("Persistence"), std::string::npos);
  s = {};
  s.featureSize = -1.0;
  EXPECT_NE(problem(s).find("FeatureSize"), std::string::npos);
  s = {};
  s.fractal.octaves = 24;
  s.fractal.lacunarity = 16.0f;
  EXPECT_NE(problem(s).find("Octaves or Lacunarity"), std::string::npos);
  s = {};
  s.roughness = 3.0;
  EXPECT_NE(problem(s).find("Roughness"), std::string::npos);
}
} // namespace
