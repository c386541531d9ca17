// The density paths toward the light: exact for uniform density straight up and slanted, a slab's
// shadow below it, light from the side, bad input.
#include "parafluid/clouds/LightPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using parafluid::clouds::densityPathToward;

namespace
{
constexpr int kDims[3] = { 24, 20, 16 };
constexpr double kH = 0.1;
constexpr double kSpacing[3] = { kH, kH, kH };

std::size_t index(int i, int j, int k)
{
  return (static_cast<std::size_t>(k) * kDims[1] + j) * kDims[0] + i;
}
} // namespace

TEST(LightPaths, UniformDensityStraightUpIsTheDistanceToTheTop)
{
  const std::vector<float> density(static_cast<std::size_t>(kDims[0]) * kDims[1] * kDims[2], 2.0f);
  const double up[3] = { 0.0, 0.0, 1.0 };
  const std::vector<float> path = densityPathToward(density, kDims, kSpacing, up);
  for (int k = 0; k < kDims[2]; ++k)
  {
    // From the sample to the top face (half a cell past the last sample), times the density.
    EXPECT_NEAR(path[index(5, 7, k)], 2.0 * (kDims[2] - 1 - k + 0.5) * kH, 1e-5) << "k " << k;
  }
}

TEST(LightPaths, SlantedRaysFollowTheirLengthToTheFaceTheyLeaveBy)
{
  const std::vector<float> density(static_cast<std::size_t>(kDims[0]) * kDims[1] * kDims[2], 1.0f);
  const double toward[3] = { 0.3, -0.2, 1.0 };
  const double stretch = std::sqrt(0.09 + 0.04 + 1.0);
  const std::vector<float> path = densityPathToward(density, kDims, kSpacing, toward);
  for (int k = 0; k < kDims[2]; ++k)
  {
    // A sample whose ray leaves through the top (not the sides): i + 0.3 (rise), j - 0.2 (rise) in.
    const int i = 2, j = 17;
    const double rise = kDims[2] - 1 - k + 0.5;
    ASSERT_LT(i + 0.3 * rise, kDims[0] - 1);
    ASSERT_GT(j - 0.2 * rise, 0);
    EXPECT_NEAR(path[index(i, j, k)], rise * kH * stretch, 1e-4) << "k " << k;
  }
}

TEST(LightPaths, UnequalSpacingFollowsTheRayInMetres)
{
  // Samples twice as far apart in z: the same slanted ray in metres.
  const std::vector<float> density(static_cast<std::size_t>(kDims[0]) * kDims[1] * kDims[2], 1.0f);
  const double spacing[3] = { kH, kH, 2 * kH };
  const double toward[3] = { 0.2, 0.0, 1.0 };
  const std::vector<float> path = densityPathToward(density, kDims, spacing, toward);
  const double stretch = std::sqrt(0.04 + 1.0);
  for (int k = 0; k < kDims[2]; ++k)
  {
    EXPECT_NEAR(path[index(2, 5, k)], (kDims[2] - 1 - k + 0.5) * 2 * kH * stretch, 1e-4) << "k " << k;
  }
}

TEST(LightPaths, ASlabShadowsWhatLiesBelowItByItsThickness)
{
  std::vector<float> density(static_cast<std::size_t>(kDims[0]) * kDims[1] * kDims[2], 0.0f);
  for (int k = 10; k <= 12; ++k)
    for (int j = 0; j < kDims[1]; ++j)
      for (int i = 0; i < kDims[0]; ++i)
        density[index(i, j, k)] = 1.0f;
  const double up[3] = { 0.0, 0.0, 1.0 };
  const std::vector<float> path = densityPathToward(density, kDims, kSpacing, up);
  // Samples below the slab: its three layers, the edges at the midpoints between samples.
  EXPECT_NEAR(path[index(4, 4, 3)], 3 * kH, 1e-6);
  EXPECT_NEAR(path[index(4, 4, 8)], 3 * kH, 1e-6);
  EXPECT_NEAR(path[index(4, 4, 14)], 0.0, 1e-9);
  // From the side (+x): the slab is crossed lengthwise, the air below it is in full light.
  const double side[3] = { 1.0, 0.0, 0.0 };
  const std::vector<float> across = densityPathToward(density, kDims, kSpacing, side);
  EXPECT_NEAR(across[index(0, 4, 11)], (kDims[0] - 1 + 0.5) * kH, 1e-5);
  EXPECT_NEAR(across[index(0, 4, 5)], 0.0, 1e-9);
}

TEST(LightPaths, RejectsAZeroDirectionAndMismatchedData)
{
  const std::vector<float> density(10, 1.0f);
  const int dims[3] = { 10, 1, 1 };
  const double zero[3] = { 0.0, 0.0, 0.0 };
  EXPECT_THROW(densityPathToward(density, dims, kSpacing, zero), std::invalid_argument);
  const double up[3] = { 0.0, 0.0, 1.0 };
  const int wrong[3] = { 5, 1, 1 };
  EXPECT_THROW(densityPathToward(density, wrong, kSpacing, up), std::invalid_argument);
  const double flat[3] = { kH, 0.0, kH };
  EXPECT_THROW(densityPathToward(density, dims, flat, up), std::invalid_argument);
}
