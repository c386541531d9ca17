// The neighbour search's inner loop against a plain loop, on every compiled copy (ctest runs this
// suite again with PARAFLUID_SIMD=avx2 and =baseline): the same squared distances, bit for bit, and
// the same hits in the same order, for buffers of every length around the vector widths.
#include "private/NeighbourCandidates.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

TEST(CandidateHits, SameDistancesAndHitsInOrderAsAPlainLoop)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  const float q[3] = { 0.1f, -0.2f, 0.05f };
  const float h2 = 0.36f; // about 11 % of the candidates inside
  for (std::uint32_t size : { 0u, 1u, 7u, 15u, 16u, 17u, 31u, 33u, 250u, 1003u })
  {
    std::vector<float> x(size), y(size), z(size);
    for (std::uint32_t j = 0; j < size; ++j)
    {
      x[j] = coordinate(random);
      y[j] = coordinate(random);
      z[j] = coordinate(random);
    }
    std::vector<float> r2(size, -1.0f);
    std::vector<std::uint32_t> hits(size + 1, 0xFFFFFFFFu);
    const std::uint32_t count =
      parafluid::sph::detail::findHitsKernel(x.data(), y.data(), z.data(), size, q, h2, r2.data(), hits.data());
    std::vector<std::uint32_t> expected;
    for (std::uint32_t j = 0; j < size; ++j)
    {
      const float dx = q[0] - x[j], dy = q[1] - y[j], dz = q[2] - z[j];
      const float d = dx * dx + dy * dy + dz * dz;
      ASSERT_EQ(r2[j], d) << "size " << size << ", candidate " << j;
      if (d < h2)
      {
        expected.push_back(j);
      }
    }
    ASSERT_EQ(count, expected.size()) << "size " << size;
    for (std::uint32_t n = 0; n < count; ++n)
    {
      ASSERT_EQ(hits[n], expected[n]) << "size " << size << ", hit " << n;
    }
    if (size > 100)
    {
      EXPECT_GT(count, size / 20) << "the test should have hits";
      EXPECT_LT(count, size / 4) << "and misses";
    }
  }
}
