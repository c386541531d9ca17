// Rain streaks rasterised on the CPU (the Rain representation's path for a software OpenGL): the
// streak's place, size and profile, its colour, the depth test, the blending order and the
// independence from the thread count.
#include "parafluid/rain/StreakRaster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace parafluid::rain;

namespace
{
constexpr int kSize = 64;

/// A camera at the origin looking down -z (view = world), 90 degrees high, near 0.1 m, far 100 m.
StreakCamera camera()
{
  StreakCamera c;
  c.worldToView = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const float n = 0.1f, f = 100.0f;
  c.viewToClip = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, (f + n) / (n - f), 2 * f * n / (n - f), 0, 0, -1, 0 };
  c.width = c.height = kSize;
  c.eye = { 0, 0, 0 };
  return c;
}

/// One radiance for every view direction.
struct UniformRadiance
{
  std::vector<float> texels;
  RadianceTable table;
  UniformRadiance(float r, float g, float b)
  {
    for (int k = 0; k < 8 * 4; ++k)
    {
      texels.insert(texels.end(), { r, g, b, 1.0f });
    }
    table = { texels.data(), 8, 4 };
  }
};

/// A drop 5 m ahead falling down the screen: its axis on the centres of pixel column 32, its head
/// 3.2 pixels above the centre, 3.2 pixels wide (diameter 0.5 m at 5 m), 6.4 pixels long (1 m).
std::vector<float> fallingDrop(float x = 0.078125f)
{
  return { x, 0.5f, -5.0f, 0.5f, 0.0f, -6.0f, 0.0f, 1.0f };
}

float alphaAt(const std::vector<float>& rgba, int column, int row)
{
  return rgba[4 * (static_cast<std::size_t>(row) * kSize + column) + 3];
}
} // namespace

TEST(StreakRaster, AStreakCoversItsCapsuleWithTheProfileOfTheGpuPass)
{
  StreakRaster raster;
  UniformRadiance white(1, 1, 1);
  StreakLook look;
  std::vector<float> rgba;
  const auto drop = fallingDrop();
  ASSERT_EQ(raster.draw(drop.data(), 1, camera(), look, white.table, nullptr, rgba, 1), 1u);
  // Pixel centres at k + 0.5 - 32: the axis is column 32; the streak runs from y = 3.2 - 1.6 to
  // 9.6 + 1.6 pixels, i.e. rows 34..42, and is 3.2 pixels wide: columns 31..33.
  float peak = 0.0f;
  for (int row = 0; row < kSize; ++row)
  {
    for (int column = 0; column < kSize; ++column)
    {
      const float a = alphaAt(rgba, column, row);
      const bool inside = row >= 34 && row <= 42 && column >= 31 && column <= 33;
      if (!inside)
      {
        EXPECT_EQ(a, 0.0f) << "column " << column << " row " << row;
      }
      peak = std::max(peak, a);
    }
  }
  // At the middle of the axis (across 0, ends 1) the opacity itself; a pixel off the axis by one
  // (across: 1 / 1.6 half-widths) exp(-2 y^2) of it.
  EXPECT_NEAR(peak, look.opacity, 1e-5f);
  EXPECT_NEAR(alphaAt(rgba, 32, 38), look.opacity, 1e-5f);
  const float y = 1.0f / 1.6f;
  EXPECT_NEAR(alphaAt(rgba, 33, 38), look.opacity * std::exp(-2.0f * y * y), 1e-4f);
  EXPECT_NEAR(alphaAt(rgba, 31, 38), alphaAt(rgba, 33, 38), 1e-6f);
  // The ends fade: the tail's and head's last rows are fainter than the middle.
  EXPECT_LT(alphaAt(rgba, 32, 34), 0.5f * look.opacity);
  EXPECT_LT(alphaAt(rgba, 32, 42), 0.5f * look.opacity);
  // White radiance: premultiplied colour equals coverage.
  const std::size_t middle = 4 * (38 * kSize + 32);
  EXPECT_NEAR(rgba[middle], rgba[middle + 3], 1e-6f);
}

TEST(StreakRaster, ColourIsTheRadianceTowardTheEyeTimesBrightness)
{
  StreakRaster raster;
  UniformRadiance tinted(0.2f, 0.4f, 0.8f);
  StreakLook look;
  look.brightness = 2.0f;
  std::vector<float> rgba;
  const auto drop = fallingDrop();
  raster.draw(drop.data(), 1, camera(), look, tinted.table, nullptr, rgba, 1);
  const std::size_t middle = 4 * (38 * kSize + 32);
  const float a = rgba[middle + 3];
  ASSERT_GT(a, 0.0f);
  EXPECT_NEAR(rgba[middle] / a, 0.4f, 1e-5f);
  EXPECT_NEAR(rgba[middle + 1] / a, 0.8f, 1e-5f);
  EXPECT_NEAR(rgba[middle + 2] / a, 1.0f, 1e-5f); // 1.6, clamped as a fixed-point framebuffer does
}

TEST(StreakRaster, TheSceneInFrontHidesAStreakAndTheOneBehindDoesNot)
{
  StreakRaster raster;
  UniformRadiance white(1, 1, 1);
  std::vector<float> rgba;
  const auto drop = fallingDrop();
  std::vector<float> depth(kSize * kSize, 1.0f);
  EXPECT_EQ(raster.draw(drop.data(), 1, camera(), StreakLook(), white.table, depth.data(), rgba, 1), 1u);
  EXPECT_GT(alphaAt(rgba, 32, 38), 0.0f);
  // A wall at 1 m (window depth of view z = -1) in front of the drop at 5 m.
  const StreakCamera c = camera();
  const float clipZ = c.viewToClip[10] * -1.0f + c.viewToClip[11], clipW = 1.0f;
  std::fill(depth.begin(), depth.end(), 0.5f * clipZ / clipW + 0.5f);
  raster.draw(drop.data(), 1, c, StreakLook(), white.table, depth.data(), rgba, 1);
  EXPECT_EQ(*std::max_element(rgba.begin(), rgba.end()), 0.0f);
}

TEST(StreakRaster, StreaksBlendInTheDropsOrder)
{
  // Radiance by azimuth in 1-degree columns: red below 80 degrees, blue from 80 on. Two drops on
  // the same pixels, seen at 81.1 (blue) and 79.0 degrees (red).
  std::vector<float> texels;
  for (int k = 0; k < 360; ++k)
  {
    texels.insert(texels.end(), { k < 80 ? 1.0f : 0.0f, 0.0f, k < 80 ? 0.0f : 1.0f, 1.0f });
  }
  const RadianceTable table{ texels.data(), 360, 1 };
  const auto blue = fallingDrop(0.078125f), red = fallingDrop(0.098125f);
  StreakLook look;
  look.opacity = 0.5f;
  StreakRaster raster;
  std::vector<float> blueAlone, redAlone, blueThenRed, redThenBlue;
  raster.draw(blue.data(), 1, camera(), look, table, nullptr, blueAlone, 1);
  raster.draw(red.data(), 1, camera(), look, table, nullptr, redAlone, 1);
  std::vector<float> pair = blue;
  pair.insert(pair.end(), red.begin(), red.end());
  raster.draw(pair.data(), 2, camera(), look, table, nullptr, blueThenRed, 2);
  std::swap_ranges(pair.begin(), pair.begin() + 8, pair.begin() + 8);
  raster.draw(pair.data(), 2, camera(), look, table, nullptr, redThenBlue, 2);
  const std::size_t middle = 4 * (38 * kSize + 32);
  ASSERT_GT(blueAlone[middle + 2], 0.0f);
  ASSERT_GT(redAlone[middle], 0.0f);
  // GL's over, in the drops' order: the later drop on top.
  for (int c = 0; c < 4; ++c)
  {
    EXPECT_NEAR(blueThenRed[middle + c], redAlone[middle + c] + (1.0f - redAlone[middle + 3]) * blueAlone[middle + c],
                1e-6f);
    EXPECT_NEAR(redThenBlue[middle + c], blueAlone[middle + c] + (1.0f - blueAlone[middle + 3]) * redAlone[middle + c],
                1e-6f);
  }
  EXPECT_GT(blueThenRed[middle], redThenBlue[middle]); // red on top
  EXPECT_LT(blueThenRed[middle + 2], redThenBlue[middle + 2]);
}

TEST(StreakRaster, DropsBehindTheEyeBeyondTheFarPlaneOrOffScreenAreNotDrawn)
{
  StreakRaster raster;
  UniformRadiance white(1, 1, 1);
  std::vector<float> rgba;
  auto behind = fallingDrop();
  behind[2] = 5.0f;
  EXPECT_EQ(raster.draw(behind.data(), 1, camera(), StreakLook(), white.table, nullptr, rgba, 1), 0u);
  auto far = fallingDrop();
  far[2] = -500.0f;
  EXPECT_EQ(raster.draw(far.data(), 1, camera(), StreakLook(), white.table, nullptr, rgba, 1), 0u);
  auto aside = fallingDrop(50.0f);
  EXPECT_EQ(raster.draw(aside.data(), 1, camera(), StreakLook(), white.table, nullptr, rgba, 1), 0u);
  EXPECT_EQ(*std::max_element(rgba.begin(), rgba.end()), 0.0f);
}

TEST(StreakRaster, TheImageDoesNotDependOnTheThreadCount)
{
  // Many overlapping drops of different colours (their radiance varies with direction).
  std::vector<float> texels;
  for (int k = 0; k < 16 * 8; ++k)
  {
    texels.insert(texels.end(), { (k % 7) / 7.0f, (k % 5) / 5.0f, (k % 3) / 3.0f, 1.0f });
  }
  const RadianceTable table{ texels.data(), 16, 8 };
  std::vector<float> drops;
  for (int k = 0; k < 3000; ++k)
  {
    const float u = static_cast<float>((k * 7919) % 1000) / 1000.0f,
                v = static_cast<float>((k * 104729) % 997) / 997.0f;
    drops.insert(drops.end(), { 8.0f * u - 4.0f, 8.0f * v - 4.0f, -3.0f - 5.0f * u * v, 0.02f + 0.2f * v, 1.0f * u,
                                -6.0f, 0.5f * v, 0.3f + u });
  }
  StreakRaster raster;
  std::vector<float> one, three;
  const std::size_t drawnOne =
    raster.draw(drops.data(), drops.size() / 8, camera(), StreakLook(), table, nullptr, one, 1);
  const std::size_t drawnThree =
    raster.draw(drops.data(), drops.size() / 8, camera(), StreakLook(), table, nullptr, three, 3);
  EXPECT_GT(drawnOne, 1000u);
  EXPECT_EQ(drawnOne, drawnThree);
  EXPECT_EQ(one, three);
}

TEST(StreakRaster, AWideStreakKeepsToItsShareOfTheFramesPixels)
{
  // The limit itself: a capped streak's rectangle covers its share exactly, one under it is kept.
  for (const float length : { 0.0f, 3.0f, 40.0f, 500.0f })
  {
    for (const float area : { 2.0f, 50.0f, 4000.0f })
    {
      const float w = limitedHalfWidth(1e6f, length, area);
      EXPECT_NEAR((length + 2.0f * w) * 2.0f * w, std::max(area, (length + 1.0f) * 1.0f), 1e-3f * area + 1e-3f)
        << "length " << length << " area " << area;
      EXPECT_EQ(limitedHalfWidth(0.7f, length, 1e9f), 0.7f);
    }
  }
  EXPECT_FLOAT_EQ(streakAreaLimit(64.0 * 64.0, 16), kStreakScreens * 64.0f * 64.0f / 16.0f);
  // A drop 1e6 times its width covers its share of the frame, not the whole of it.
  StreakRaster raster;
  UniformRadiance white(1, 1, 1);
  StreakLook look;
  look.widthScale = 1e6f;
  look.maxArea = 100.0f;
  std::vector<float> rgba;
  const auto drop = fallingDrop();
  ASSERT_EQ(raster.draw(drop.data(), 1, camera(), look, white.table, nullptr, rgba, 1), 1u);
  int covered = 0;
  for (int row = 0; row < kSize; ++row)
  {
    for (int column = 0; column < kSize; ++column)
    {
      covered += alphaAt(rgba, column, row) > 0.0f ? 1 : 0;
    }
  }
  EXPECT_GT(covered, 20);
  EXPECT_LE(covered, 100 + 4 * 10); // the rectangle's pixels, and a rim of partly covered ones
}
