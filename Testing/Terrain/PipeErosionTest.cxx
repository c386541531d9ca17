// Virtual-pipe erosion: water and sediment budgets close, flat ground does not change, a valley
// erodes along its floor, extreme settings stay finite.
#include "parafluid/terrain/PipeErosion.h"

#include "ErosionScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace
{
using namespace parafluid::terrain;
using namespace parafluid::terrain::test;

double sum(const std::vector<float>& v)
{
  double s = 0.0;
  for (const float x : v)
  {
    s += x;
  }
  return s;
}

TEST(PipeErosion, WaterAndSedimentBudgetsClose)
{
  const ElevationGrid g = hills(128, 1.0);
  PipeSettings s;
  s.evaporation = 0.0f;
  s.rainRate = 0.01f;
  PipeErosion erosion(g, s);
  for (int k = 0; k < 300; ++k)
  {
    erosion.step();
  }
  // Closed edges, no evaporation: all the rain is still there.
  const double rain = s.rainRate * s.timeStep * 300.0 * g.size();
  EXPECT_NEAR(sum(erosion.water()), rain, 1e-3 * rain);
  const SedimentBudget b = erosion.budget();
  ASSERT_GT(b.eroded, 0.0);
  std::printf("pipes: water %.6g m^3 of %.6g rained; eroded %.6g m^3, deposited %.6g, suspended %.6g: residual %.2g\n",
              sum(erosion.water()), rain, b.eroded, b.deposited, b.carried,
              std::fabs(b.eroded - b.deposited - b.carried) / b.eroded);
  EXPECT_NEAR(b.eroded, b.deposited + b.carried, 1e-4 * b.eroded);
  EXPECT_NEAR(sum(g.elevation) - sum(erosion.elevation()), b.carried, 1e-3 * b.eroded);
}

TEST(PipeErosion, FlatGroundDoesNotChange)
{
  const ElevationGrid g = flat(32, 5.0f);
  PipeErosion erosion(g, PipeSettings{});
  for (int k = 0; k < 100; ++k)
  {
    erosion.step();
  }
  for (const float h : erosion.elevation())
  {
    ASSERT_EQ(h, 5.0f);
  }
  EXPECT_EQ(erosion.budget().eroded, 0.0);
}

TEST(PipeErosion, ValleyErodesAlongItsFloor)
{
  const int n = 96, foot = 24;
  const ElevationGrid g = valley(n, foot);
  PipeSettings s;
  s.rainRate = 0.02f;
  PipeErosion erosion(g, s);
  for (int k = 0; k < 400; ++k)
  {
    erosion.step();
  }
  const ErosionMaps maps = erosion.maps();
  const double floorErosion = meanOver(g, maps.erodedDepth, n / 2 - 1, n / 2 + 2, foot + 8, n - 8);
  const double flankErosion = meanOver(g, maps.erodedDepth, n / 2 + 15, n / 2 + 30, foot + 8, n - 8);
  EXPECT_GT(floorErosion, 2.0 * flankErosion);
  const double floorFlow = meanOver(g, maps.waterFlow, n / 2 - 1, n / 2 + 2, foot + 8, n - 8);
  const double flankFlow = meanOver(g, maps.waterFlow, n / 2 + 15, n / 2 + 30, foot + 8, n - 8);
  EXPECT_GT(floorFlow, 3.0 * flankFlow);
}

TEST(PipeErosion, ExtremeSettingsStayFinite)
{
  std::vector<PipeSettings> cases(4);
  cases[0].timeStep = 10.0f;
  cases[1].capacity = 1e6f;
  cases[1].dissolveRate = 1e6f;
  cases[2].evaporation = 1e6f;
  cases[3].rainRate = 10.0f;
  cases[3].capacity = 0.0f;
  for (const PipeSettings& s : cases)
  {
    PipeErosion erosion(hills(48, 1.0), s);
    for (int k = 0; k < 50; ++k)
    {
      erosion.step();
    }
    for (const float h : erosion.elevation())
    {
      ASSERT_TRUE(std::isfinite(h));
    }
    for (const float d : erosion.water())
    {
      ASSERT_TRUE(std::isfinite(d) && d >= 0.0f);
    }
  }
  PipeSettings bad;
  bad.timeStep = -1.0f;
  EXPECT_THROW(PipeErosion(flat(8, 0.0f), bad), std::invalid_argument);
}
} // namespace
