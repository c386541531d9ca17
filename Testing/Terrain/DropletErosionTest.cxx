// Droplet erosion: the sediment budget closes, a valley erodes along its floor and fills at its
// foot, flat ground does not change, extreme settings stay finite, and the result is the same on
// any thread count.
#include "parafluid/terrain/DropletErosion.h"

#include "ErosionScenes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace
{
using namespace parafluid::terrain;
using namespace parafluid::terrain::test;

TEST(DropletErosion, ErodedEqualsDepositedPlusCarried)
{
  ElevationGrid g = hills(256, 2.0);
  const std::vector<float> before = g.elevation;
  DropletSettings s;
  s.drops = 20000;
  ErosionMaps maps;
  const SedimentBudget budget = erodeWithDroplets(s, g, maps);
  ASSERT_GT(budget.eroded, 0.0);
  EXPECT_GT(budget.deposited, 0.0);
  std::printf("droplets: eroded %.6g m^3, deposited %.6g, carried %.6g: residual %.2g of the eroded\n", budget.eroded,
              budget.deposited, budget.carried,
              std::fabs(budget.eroded - budget.deposited - budget.carried) / budget.eroded);
  EXPECT_NEAR(budget.eroded, budget.deposited + budget.carried, 1e-5 * budget.eroded);
  // The ground's net loss is what the water still carries.
  double change = 0.0, erodedMap = 0.0, depositedMap = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k)
  {
    change += (static_cast<double>(g.elevation[k]) - before[k]) * g.dx * g.dy;
    erodedMap += maps.erodedDepth[k] * g.dx * g.dy;
    depositedMap += maps.sedimentDeposited[k] * g.dx * g.dy;
  }
  EXPECT_NEAR(-change, budget.carried, 1e-3 * budget.eroded);
  EXPECT_NEAR(erodedMap, budget.eroded, 1e-4 * budget.eroded);
  EXPECT_NEAR(depositedMap, budget.deposited, 1e-4 * budget.eroded);
}

TEST(DropletErosion, ValleyErodesAlongItsFloorAndDepositsAtItsFoot)
{
  const int n = 128, foot = 32;
  ElevationGrid g = valley(n, foot);
  DropletSettings s;
  s.drops = 8000; // half a drop per sample
  ErosionMaps maps;
  erodeWithDroplets(s, g, maps);
  const double floorErosion = meanOver(g, maps.erodedDepth, n / 2 - 2, n / 2 + 3, foot + 10, n - 10);
  const double flankErosion = meanOver(g, maps.erodedDepth, n / 2 + 20, n / 2 + 40, foot + 10, n - 10);
  EXPECT_GT(floorErosion, 2.0 * flankErosion); // measured: about 3x
  const double footDeposit = meanOver(g, maps.sedimentDeposited, n / 2 - 15, n / 2 + 15, foot - 12, foot + 2);
  const double flankDeposit = meanOver(g, maps.sedimentDeposited, n / 2 + 20, n / 2 + 40, foot + 10, n - 10);
  EXPECT_GT(footDeposit, 3.0 * flankDeposit);
  // The floor (a band as wide as the erosion brush) went down.
  const ElevationGrid original = valley(n, foot);
  EXPECT_LT(meanOver(g, g.elevation, n / 2 - 3, n / 2 + 4, foot + 10, n - 10),
            meanOver(original, original.elevation, n / 2 - 3, n / 2 + 4, foot + 10, n - 10) - 0.2);
}

TEST(DropletErosion, FlatGroundDoesNotChange)
{
  ElevationGrid g = flat(64, 10.0f);
  DropletSettings s;
  s.drops = 5000;
  ErosionMaps maps;
  const SedimentBudget budget = erodeWithDroplets(s, g, maps);
  for (const float h : g.elevation)
  {
    ASSERT_EQ(h, 10.0f);
  }
  EXPECT_EQ(budget.eroded, 0.0);
}

TEST(DropletErosion, ExtremeSettingsStayFinite)
{
  DropletSettings base;
  base.drops = 3000;
  std::vector<DropletSettings> cases(6, base);
  cases[0].capacity = 0.0f;
  cases[1].capacity = 1e6f;
  cases[1].erodeRate = 1.0f;
  cases[2].drops = 0;
  cases[3].radius = 32.0f;
  cases[3].inertia = 1.0f;
  cases[4].evaporation = 1.0f;
  cases[4].depositRate = 1.0f;
  cases[5].gravity = 1000.0f;
  cases[5].maxSteps = 5000;
  for (const DropletSettings& s : cases)
  {
    ElevationGrid g = hills(64, 1.0);
    const std::vector<float> before = g.elevation;
    ErosionMaps maps;
    const SedimentBudget budget = erodeWithDroplets(s, g, maps);
    for (const float h : g.elevation)
    {
      ASSERT_TRUE(std::isfinite(h));
    }
    EXPECT_TRUE(std::isfinite(budget.eroded) && std::isfinite(budget.carried));
    if (s.capacity == 0.0f || s.drops == 0)
    {
      EXPECT_EQ(g.elevation, before);
    }
  }
  DropletSettings bad;
  bad.inertia = 2.0f;
  ElevationGrid g = flat(8, 0.0f);
  ErosionMaps maps;
  EXPECT_THROW(erodeWithDroplets(bad, g, maps), std::invalid_argument);
}

TEST(DropletErosion, SameResultOnAnyThreadCount)
{
  DropletSettings s;
  s.drops = 5000;
  s.seed = 77;
  const auto run = [&](int threads)
  {
    ElevationGrid g = hills(128, 1.0);
    ErosionMaps maps;
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    erodeWithDroplets(s, g, maps);
    omp_set_num_threads(before);
    return std::make_pair(g.elevation, maps.waterFlow);
  };
  const auto one = run(1), two = run(2), three = run(3);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, three);
  s.seed = 78;
  EXPECT_NE(one.first, run(2).first);
}
} // namespace
