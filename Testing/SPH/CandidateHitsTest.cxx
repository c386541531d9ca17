// The neighbour search's inner loop against a plain loop, on every compiled copy (ctest runs this
// suite again with PARAFLUID_SIMD=avx2 and =baseline): the same squared distances, bit for bit, and
// the same hits in the same order, for buffers of every length around the vector widths.
#include "private/NeighbourCandidates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace
{
/// `size` points with coordinates drawn from `coordinate`, x, y and z of each point in turn.
void randomPoints(std::mt19937& random, std::uniform_real_distribution<float>& coordinate, std::uint32_t size,
                  std::vector<float>& x, std::vector<float>& y, std::vector<float>& z)
{
  x.resize(size);
  y.resize(size);
  z.resize(size);
  for (std::uint32_t j = 0; j < size; ++j)
  {
    x[j] = coordinate(random);
    y[j] = coordinate(random);
    z[j] = coordinate(random);
  }
}
} // namespace

TEST(CandidateHits, SameDistancesAndHitsInOrderAsAPlainLoop)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  const float q[3] = { 0.1f, -0.2f, 0.05f };
  const float h2 = 0.36f; // about 11 % of the candidates inside
  for (std::uint32_t size : { 0u, 1u, 7u, 15u, 16u, 17u, 31u, 33u, 250u, 1003u })
  {
    std::vector<float> x, y, z;
    randomPoints(random, coordinate, size, x, y, z);
    std::vector<float> r2(size, -1.0f);
    std::vector<std::uint32_t> hits(size + 16, 0xFFFFFFFFu);
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

// The copy of a cell's candidates against a plain loop, on every compiled copy: the same particles
// (those closer to the cell's box than the reach), shifted, in the same order, with their channels.
TEST(CandidateHits, CopyKeepsTheParticlesNearTheBoxInOrder)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<float> coordinate(-1.0f, 2.0f);
  const float lo[3] = { 0.0f, 0.0f, 0.0f }, hi[3] = { 1.0f, 1.0f, 1.0f };
  const float shift[3] = { 0.5f, 0.0f, -0.25f };
  const float reach2 = 0.3f * 0.3f;
  for (std::uint32_t count : { 0u, 1u, 15u, 16u, 17u, 40u, 1003u })
  {
    std::vector<float> px(count), py(count), pz(count), a(count), b(count);
    for (std::uint32_t j = 0; j < count; ++j)
    {
      px[j] = coordinate(random);
      py[j] = coordinate(random);
      pz[j] = coordinate(random);
      a[j] = static_cast<float>(j);
      b[j] = -static_cast<float>(j);
    }
    // Appended after 3 values already there, from particle 2 on.
    const std::uint32_t first = count > 2 ? 2 : 0, before = 3;
    std::vector<float> x(before + count + 16, -7.0f), y = x, z = x, ca = x, cb = x;
    const float* sources[2] = { a.data(), b.data() };
    float* channels[2] = { ca.data(), cb.data() };
    const std::uint32_t size =
      parafluid::sph::detail::appendNearBoxKernel(px.data(), py.data(), pz.data(), first, count, shift, lo, hi, reach2,
                                                  sources, 2, x.data(), y.data(), z.data(), channels, before);
    std::uint32_t expected = before;
    for (std::uint32_t j = first; j < count; ++j)
    {
      const float p[3] = { px[j] + shift[0], py[j] + shift[1], pz[j] + shift[2] };
      float d2 = 0.0f;
      for (int axis = 0; axis < 3; ++axis)
      {
        const float d = std::max({ lo[axis] - p[axis], 0.0f, p[axis] - hi[axis] });
        d2 += d * d;
      }
      if (d2 >= reach2)
      {
        continue;
      }
      ASSERT_LT(expected, size) << "count " << count;
      EXPECT_EQ(x[expected], p[0]);
      EXPECT_EQ(y[expected], p[1]);
      EXPECT_EQ(z[expected], p[2]);
      EXPECT_EQ(ca[expected], a[j]);
      EXPECT_EQ(cb[expected], b[j]);
      ++expected;
    }
    EXPECT_EQ(size, expected) << "count " << count;
    EXPECT_EQ(x[0], -7.0f) << "what was there stays";
    if (count > 100)
    {
      EXPECT_GT(size - before, count / 10) << "the test should keep some";
      EXPECT_LT(size - before, count / 2) << "and drop some";
    }
  }
}

// The search among a list of candidates (a wall image's, among its particle's hits) against a plain
// loop, on every compiled copy: the listed candidates inside the radius, in the list's order.
TEST(CandidateHits, SearchAmongAListKeepsItsOrder)
{
  std::mt19937 random(17);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  const std::uint32_t size = 500;
  std::vector<float> x, y, z;
  randomPoints(random, coordinate, size, x, y, z);
  const float q[3] = { -0.3f, 0.2f, 0.1f };
  const float h2 = 0.5f;
  for (std::uint32_t listed : { 0u, 1u, 15u, 16u, 17u, 33u, 250u })
  {
    std::vector<std::uint32_t> among(listed);
    for (std::uint32_t k = 0; k < listed; ++k)
    {
      among[k] = (k * 37u + 11u) % size; // not ascending, with gaps
    }
    std::vector<std::uint32_t> out(listed + 16, 0xFFFFFFFFu);
    const std::uint32_t count = parafluid::sph::detail::findHitsAmongKernel(x.data(), y.data(), z.data(), among.data(),
                                                                            listed, q, h2, out.data());
    std::vector<std::uint32_t> expected;
    for (std::uint32_t j : among)
    {
      const float dx = q[0] - x[j], dy = q[1] - y[j], dz = q[2] - z[j];
      if (dx * dx + dy * dy + dz * dz < h2)
      {
        expected.push_back(j);
      }
    }
    ASSERT_EQ(count, expected.size()) << "listed " << listed;
    for (std::uint32_t n = 0; n < count; ++n)
    {
      EXPECT_EQ(out[n], expected[n]) << "listed " << listed << ", hit " << n;
    }
    if (listed > 100)
    {
      EXPECT_GT(count, listed / 10) << "the test should have hits";
      EXPECT_LT(count, listed / 2) << "and misses";
    }
  }
}
