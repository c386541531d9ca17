// Perlin's improved noise: zero on the lattice, continuous value and gradient across cell borders
// (the quintic fade), within its theoretical bound, an analytic gradient that matches finite
// differences, and a permutation that follows the seed.
#include "parafluid/terrain/PerlinNoise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
using parafluid::terrain::PerlinNoise;

TEST(PerlinNoise, IsZeroAtLatticePoints)
{
  const PerlinNoise noise(7);
  for (int j = -20; j < 300; j += 7)
  {
    for (int i = -20; i < 300; i += 3)
    {
      EXPECT_EQ(noise.noise(static_cast<float>(i), static_cast<float>(j)), 0.0f);
      EXPECT_EQ(noise.noise(static_cast<float>(i), static_cast<float>(j), static_cast<float>(i - j)), 0.0f);
    }
  }
}

TEST(PerlinNoise, ValueAndGradientAreContinuousAcrossCellBorders)
{
  const PerlinNoise noise(11);
  const float e = 1e-3f;
  float worstValue = 0.0f, worstGradient = 0.0f;
  for (int k = 0; k < 400; ++k)
  {
    // A point on a vertical cell border x = integer, at a varied y; one-sided values and
    // one-sided finite-difference slopes from the left and from the right.
    const float x = static_cast<float>(k % 37), y = 0.013f + 0.37f * static_cast<float>(k);
    const float left = noise.noise(x - e, y), right = noise.noise(x + e, y), centre = noise.noise(x, y);
    worstValue = std::fmax(worstValue, std::fmax(std::fabs(left - centre), std::fabs(right - centre)));
    const float slopeLeft = (centre - noise.noise(x - 2 * e, y)) / (2 * e);
    const float slopeRight = (noise.noise(x + 2 * e, y) - centre) / (2 * e);
    worstGradient = std::fmax(worstGradient, std::fabs(slopeLeft - slopeRight));
    // Horizontal borders y = integer, the y derivative.
    const float yb = static_cast<float>(k % 41), xb = 0.021f + 0.29f * static_cast<float>(k);
    const float c2 = noise.noise(xb, yb);
    const float below = (c2 - noise.noise(xb, yb - 2 * e)) / (2 * e),
                above = (noise.noise(xb, yb + 2 * e) - c2) / (2 * e);
    worstGradient = std::fmax(worstGradient, std::fabs(below - above));
  }
  // A jump of the value would show as ~0.1-1; a kink of the slope as ~1. With the fade's zero
  // first and second derivatives at the border both one-sided slopes agree to O(e).
  EXPECT_LT(worstValue, 5e-3f);
  EXPECT_LT(worstGradient, 2e-2f);
}

TEST(PerlinNoise, ThreeDimensionalNoiseIsContinuousAcrossCellBorders)
{
  const PerlinNoise noise(13);
  const float e = 1e-3f;
  float worstValue = 0.0f, worstSlope = 0.0f;
  for (int k = 0; k < 300; ++k)
  {
    // Borders z = integer (and x = integer): one-sided values and slopes from both sides.
    const float x = 0.117f * static_cast<float>(k) + 0.03f, y = 0.291f * static_cast<float>(k % 53) + 0.05f;
    const float z = static_cast<float>(k % 29);
    const float centre = noise.noise(x, y, z);
    worstValue = std::fmax(worstValue, std::fabs(noise.noise(x, y, z + e) - centre));
    worstValue = std::fmax(worstValue, std::fabs(noise.noise(x, y, z - e) - centre));
    const float below = (centre - noise.noise(x, y, z - 2 * e)) / (2 * e);
    const float above = (noise.noise(x, y, z + 2 * e) - centre) / (2 * e);
    worstSlope = std::fmax(worstSlope, std::fabs(above - below));
    const float xb = static_cast<float>(k % 31), c2 = noise.noise(xb, y, x);
    const float left = (c2 - noise.noise(xb - 2 * e, y, x)) / (2 * e),
                right = (noise.noise(xb + 2 * e, y, x) - c2) / (2 * e);
    worstSlope = std::fmax(worstSlope, std::fabs(right - left));
  }
  EXPECT_LT(worstValue, 5e-3f);
  EXPECT_LT(worstSlope, 2e-2f);
}

TEST(PerlinNoise, AnalyticGradientMatchesFiniteDifferences)
{
  const PerlinNoise noise(3);
  const float e = 1e-3f;
  for (int k = 0; k < 500; ++k)
  {
    const float x = 0.173f * static_cast<float>(k) + 0.05f, y = 0.311f * static_cast<float>(k % 97) + 0.07f;
    float g[2];
    const float value = noise.noise(x, y, g);
    EXPECT_NEAR(value, noise.noise(x, y), 1e-6f);
    EXPECT_NEAR(g[0], (noise.noise(x + e, y) - noise.noise(x - e, y)) / (2 * e), 2e-2f);
    EXPECT_NEAR(g[1], (noise.noise(x, y + e) - noise.noise(x, y - e)) / (2 * e), 2e-2f);
  }
}

TEST(PerlinNoise, StaysWithinItsTheoreticalBoundAndUsesMostOfIt)
{
  const PerlinNoise noise(5);
  float largest2 = 0.0f, largest3 = 0.0f;
  double mean = 0.0;
  const int n = 400;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const float x = 0.0731f * static_cast<float>(i), y = 0.0677f * static_cast<float>(j);
      const float v2 = noise.noise(x, y), v3 = noise.noise(x, y, 0.5f * x - 0.3f * y + 0.41f);
      largest2 = std::fmax(largest2, std::fabs(v2));
      largest3 = std::fmax(largest3, std::fabs(v3));
      mean += v2;
    }
  }
  EXPECT_LE(largest2, PerlinNoise::kBound2D);
  EXPECT_LE(largest3, PerlinNoise::kBound3D);
  // A noise scaled down by a mistake (e.g. gradients halved) would stay far below the bound.
  EXPECT_GT(largest2, 0.6f * PerlinNoise::kBound2D);
  EXPECT_GT(largest3, 0.6f * PerlinNoise::kBound3D);
  EXPECT_LT(std::fabs(mean / (n * n)), 0.05);
}

TEST(PerlinNoise, BatchedEvaluationIsTheScalarNoiseBitForBit)
{
  // accumulate() runs 8 lanes at a time on AVX2 CPUs; it must give noise() exactly, negative
  // coordinates and the tail that does not fill 8 lanes included.
  const PerlinNoise noise(21);
  const int n = 1003;
  std::vector<float> x(n), y(n), plain(n, 0.5f), folded(n, 0.5f);
  for (int i = 0; i < n; ++i)
  {
    x[static_cast<std::size_t>(i)] = -300.0f + 0.61f * static_cast<float>(i);
    y[static_cast<std::size_t>(i)] = 40.0f - 0.37f * static_cast<float>(i % 211);
  }
  noise.accumulate(x.data(), y.data(), n, 0.75f, false, plain.data());
  noise.accumulate(x.data(), y.data(), n, 0.75f, true, folded.data());
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
  {
    const float v = noise.noise(x[i], y[i]);
    ASSERT_EQ(plain[i], 0.5f + 0.75f * v) << "sample " << i;
    ASSERT_EQ(folded[i], 0.5f + 0.75f * std::fabs(v)) << "sample " << i;
  }
  std::printf("PerlinNoise::accumulate runs %s\n", PerlinNoise::vectorised() ? "8-wide (AVX2)" : "scalar");
}

TEST(PerlinNoise, TheSeedPicksThePermutation)
{
  const PerlinNoise a(1), b(1), c(2);
  int differ = 0;
  for (int k = 0; k < 100; ++k)
  {
    const float x = 0.37f * static_cast<float>(k) + 0.1f, y = 0.53f * static_cast<float>(k) + 0.2f;
    EXPECT_EQ(a.noise(x, y), b.noise(x, y));
    differ += a.noise(x, y) != c.noise(x, y) ? 1 : 0;
  }
  EXPECT_GT(differ, 90);
}
} // namespace
