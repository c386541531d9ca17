// The uniform grid finds exactly the neighbours a brute-force search finds.
#include "parafluid/common/NeighbourGrid.h"
#include "parafluid/common/ParticleNeighbourhood.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

namespace
{
using parafluid::NeighbourGrid;

struct Cloud
{
  std::vector<float> x, y, z;
};

Cloud randomCloud(std::size_t n, unsigned seed, bool clustered)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 2.0f);
  std::normal_distribution<float> g(0.3f, 0.05f);
  Cloud c;
  for (std::size_t i = 0; i < n; ++i)
  {
    const bool inCluster = clustered && i % 2 == 0;
    c.x.push_back(inCluster ? g(rng) : u(rng));
    c.y.push_back(inCluster ? g(rng) : u(rng));
    c.z.push_back(inCluster ? g(rng) : u(rng) * 0.2f);
  }
  return c;
}

void expectGridEqualsBruteForce(const Cloud& c, float radius)
{
  const std::size_t n = c.x.size();
  NeighbourGrid grid;
  grid.build(c.x.data(), c.y.data(), c.z.data(), n, radius);
  const auto& order = grid.sortedOrder();
  ASSERT_EQ(order.size(), n);
  // order is a permutation
  std::vector<std::uint32_t> sortedCopy(order);
  std::sort(sortedCopy.begin(), sortedCopy.end());
  for (std::size_t i = 0; i < n; ++i)
  {
    ASSERT_EQ(sortedCopy[i], i);
  }
  // positions in sorted order, as the solver keeps them
  Cloud s;
  for (std::uint32_t k : order)
  {
    s.x.push_back(c.x[k]);
    s.y.push_back(c.y[k]);
    s.z.push_back(c.z[k]);
  }
  const float r2 = radius * radius;
  std::size_t pairs = 0;
  for (std::size_t cell = 0; cell < grid.cellCount(); ++cell)
  {
    int ix, iy, iz;
    grid.cellCoordinates(cell, ix, iy, iz);
    for (std::uint32_t i = grid.cellStart()[cell]; i < grid.cellStart()[cell + 1]; ++i)
    {
      std::set<std::uint32_t> found;
      grid.forEachNeighbourRange(ix, iy, iz,
                                 [&](std::uint32_t b, std::uint32_t e)
                                 {
                                   for (std::uint32_t j = b; j < e; ++j)
                                   {
                                     const float dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
                                     if (dx * dx + dy * dy + dz * dz < r2)
                                     {
                                       EXPECT_TRUE(found.insert(order[j]).second) << "a neighbour was visited twice";
                                     }
                                   }
                                 });
      std::set<std::uint32_t> expected;
      const std::uint32_t oi = order[i];
      for (std::uint32_t j = 0; j < n; ++j)
      {
        const float dx = c.x[oi] - c.x[j], dy = c.y[oi] - c.y[j], dz = c.z[oi] - c.z[j];
        if (dx * dx + dy * dy + dz * dz < r2)
        {
          expected.insert(j);
        }
      }
      ASSERT_EQ(found, expected) << "particle " << oi;
      pairs += expected.size();
    }
  }
  EXPECT_GT(pairs, n); // more than the self pairs: the test saw real neighbourhoods
}

TEST(NeighbourGrid, EqualsBruteForceOnUniformRandomPoints)
{
  expectGridEqualsBruteForce(randomCloud(3000, 1, false), 0.15f);
}

TEST(NeighbourGrid, EqualsBruteForceOnClusteredPoints)
{
  expectGridEqualsBruteForce(randomCloud(3000, 2, true), 0.07f);
}

TEST(NeighbourGrid, EqualsBruteForceWhenTheRadiusExceedsTheCloud)
{
  expectGridEqualsBruteForce(randomCloud(200, 3, false), 10.0f);
}

TEST(NeighbourGrid, CellsHoldParticlesInStableOrder)
{
  const Cloud c = randomCloud(2000, 4, false);
  NeighbourGrid grid;
  grid.build(c.x.data(), c.y.data(), c.z.data(), c.x.size(), 0.2f);
  for (std::size_t cell = 0; cell < grid.cellCount(); ++cell)
  {
    for (std::uint32_t k = grid.cellStart()[cell] + 1; k < grid.cellStart()[cell + 1]; ++k)
    {
      EXPECT_LT(grid.sortedOrder()[k - 1], grid.sortedOrder()[k]);
    }
  }
}

TEST(NeighbourGrid, EmptyInputGivesAnEmptyGrid)
{
  NeighbourGrid grid;
  grid.build(nullptr, nullptr, nullptr, 0, 0.1f);
  EXPECT_TRUE(grid.sortedOrder().empty());
  int calls = 0;
  grid.forEachNeighbourRange(0, 0, 0, [&](std::uint32_t, std::uint32_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(NeighbourGrid, RejectsBadInputWithAClearError)
{
  NeighbourGrid grid;
  std::vector<float> x = { 0.0f, std::numeric_limits<float>::quiet_NaN() }, y = { 0.0f, 0.0f }, z = { 0.0f, 0.0f };
  EXPECT_THROW(grid.build(x.data(), y.data(), z.data(), 2, 0.1f), std::invalid_argument);
  x[1] = 1e9f; // two particles a billion cells apart
  EXPECT_THROW(grid.build(x.data(), y.data(), z.data(), 2, 1e-3f), std::invalid_argument);
  x[1] = 1.0f;
  EXPECT_THROW(grid.build(x.data(), y.data(), z.data(), 2, 0.0f), std::invalid_argument);
  EXPECT_THROW(grid.build(x.data(), y.data(), z.data(), 2, -1.0f), std::invalid_argument);
}
} // namespace

TEST(ParticleNeighbourhood, NaNAndInfiniteQueryPointsFindNothingAndStayInTheGrid)
{
  // A NaN coordinate used to survive the clamp to the grid and be cast to a cell index (undefined
  // behaviour, then a read outside the cell table). Now it finds nothing; infinite points clamp to
  // the edge cells and, being far from every particle, also find nothing.
  std::vector<float> xyz;
  for (int i = 0; i < 8; ++i)
  {
    xyz.insert(xyz.end(), { 0.1f * i, 0.05f * i, 0.0f });
  }
  parafluid::ParticleNeighbourhood near;
  near.build(xyz.data(), xyz.size() / 3, 0.15f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float queries[][3] = { { nan, 0.0f, 0.0f }, { 0.2f, nan, 0.1f },  { 0.0f, 0.0f, nan },
                               { inf, 0.0f, 0.0f }, { -inf, -inf, 0.0f }, { 1e30f, 0.0f, -1e30f } };
  for (const auto& q : queries)
  {
    int visits = 0;
    near.forEachNear(q, [&](std::uint32_t, float, float, float, float) { ++visits; });
    EXPECT_EQ(visits, 0);
  }
  int visits = 0;
  const float inside[3] = { 0.2f, 0.1f, 0.0f };
  near.forEachNear(inside, [&](std::uint32_t, float, float, float, float) { ++visits; });
  EXPECT_GE(visits, 1); // the lookup still works where it should
}
