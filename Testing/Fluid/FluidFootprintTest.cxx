// Where the screen-space fluid lands on screen (FluidFootprint, pure CPU): against hand-computed
// projections of a ball in front of a perspective camera, and the cases that skip drawing.
#include "FluidFootprint.h"

#include <gtest/gtest.h>

#include <cmath>

using parafluid::computeFluidFootprint;
using parafluid::FluidFootprintQuery;

namespace
{
constexpr int kWidth = 800, kHeight = 600, kMargin = 14;
constexpr double kNear = 0.1, kFar = 100.0;
const double kF = 1.0 / std::tan(0.5 * 30.0 * 3.14159265358979 / 180.0); // 30 degree view angle
const double kAspect = double(kWidth) / kHeight;

/// Camera at the origin looking down -z; VTK stores key matrices transposed: m[4 r + c] = P(c, r).
FluidFootprintQuery query(double cx, double cy, double cz, double halfWidth, double radius, bool parallel = false)
{
  FluidFootprintQuery q;
  const double centre[3] = { cx, cy, cz };
  for (int k = 0; k < 3; ++k)
  {
    q.Bounds[2 * k] = centre[k] - halfWidth;
    q.Bounds[2 * k + 1] = centre[k] + halfWidth;
  }
  q.MaxRadius = radius;
  for (int k = 0; k < 4; ++k)
  {
    q.ModelView[5 * k] = 1.0;
  }
  double p[4][4] = {};
  if (parallel)
  {
    const double scale = 5.0; // half height of the view [world units]
    p[0][0] = 1.0 / (scale * kAspect);
    p[1][1] = 1.0 / scale;
    p[2][2] = -2.0 / (kFar - kNear);
    p[2][3] = -(kFar + kNear) / (kFar - kNear);
    p[3][3] = 1.0;
  }
  else
  {
    p[0][0] = kF / kAspect;
    p[1][1] = kF;
    p[2][2] = (kFar + kNear) / (kNear - kFar);
    p[2][3] = 2.0 * kFar * kNear / (kNear - kFar);
    p[3][2] = -1.0;
  }
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      q.Projection[4 * r + c] = p[c][r];
    }
  }
  q.Parallel = parallel;
  q.NearDistance = kNear;
  q.Size[0] = kWidth;
  q.Size[1] = kHeight;
  q.Margin = kMargin;
  q.MaxPointSize = 256.0;
  return q;
}

/// Pixel column of a camera-space point under the perspective camera.
double column(double x, double z)
{
  return (0.5 * (kF / kAspect) * x / -z + 0.5) * kWidth;
}
} // namespace

TEST(FluidFootprint, BallInFrontCoversItsProjectionPlusTheMargin)
{
  const auto f = computeFluidFootprint(query(0.0, 0.0, -10.0, 1.0, 0.1));
  ASSERT_TRUE(f.Visible);
  EXPECT_NEAR(f.Nearest, 8.9, 1e-12);
  EXPECT_NEAR(f.Farthest, 11.1, 1e-12);
  // The widest column of the grown bounds is their near corner: x = 1.1 at z = -8.9.
  const double right = column(1.1, -8.9) + kMargin, left = column(-1.1, -8.9) - kMargin;
  EXPECT_EQ(f.Rect[2], static_cast<int>(std::ceil(right)));
  EXPECT_EQ(f.Rect[0], static_cast<int>(std::floor(left)));
  EXPECT_NEAR(f.Rect[0] + f.Rect[2], kWidth, 1); // centred
  EXPECT_NEAR(f.Rect[1] + f.Rect[3], kHeight, 1);
  EXPECT_TRUE(f.PointSprites) << "small spheres all on screen are point sprites";
}

TEST(FluidFootprint, NothingBehindTheCameraOrOffScreen)
{
  EXPECT_FALSE(computeFluidFootprint(query(0.0, 0.0, 10.0, 1.0, 0.1)).Visible);
  EXPECT_FALSE(computeFluidFootprint(query(100.0, 0.0, -10.0, 1.0, 0.1)).Visible);
  EXPECT_FALSE(computeFluidFootprint(query(0.0, -100.0, -10.0, 1.0, 0.1)).Visible);
}

TEST(FluidFootprint, BoundsThroughTheEyeTakeTheWholeViewportAsQuads)
{
  const auto f = computeFluidFootprint(query(0.0, 0.0, -1.0, 2.0, 0.1));
  ASSERT_TRUE(f.Visible);
  EXPECT_EQ(f.Rect[0], 0);
  EXPECT_EQ(f.Rect[1], 0);
  EXPECT_EQ(f.Rect[2], kWidth);
  EXPECT_EQ(f.Rect[3], kHeight);
  EXPECT_FALSE(f.PointSprites) << "a centre behind the near plane would be clipped whole";
}

TEST(FluidFootprint, PastTheEdgeIsClippedAndDrawnAsQuads)
{
  const auto f = computeFluidFootprint(query(3.0, 0.0, -10.0, 1.0, 0.1));
  ASSERT_TRUE(f.Visible);
  EXPECT_EQ(f.Rect[2], kWidth);
  EXPECT_GT(f.Rect[0], kWidth / 2);
  EXPECT_FALSE(f.PointSprites);
}

TEST(FluidFootprint, SpheresLargerThanTheLargestPointAreQuads)
{
  // A sphere of radius 0.5 at 5 m spans about 0.5 / 5 * f * 300 = 112 pixels across.
  auto q = query(0.0, 0.0, -5.0, 0.2, 0.5);
  EXPECT_TRUE(computeFluidFootprint(q).PointSprites);
  q.MaxPointSize = 64.0;
  EXPECT_FALSE(computeFluidFootprint(q).PointSprites);
}

TEST(FluidFootprint, ParallelProjection)
{
  const auto f = computeFluidFootprint(query(0.0, 0.0, -10.0, 1.0, 0.1, true));
  ASSERT_TRUE(f.Visible);
  // Half-width 1.1 of a 5 x aspect half-view: 1.1 / 6.667 of the half-width, on both sides.
  const double half = 0.5 * kWidth * 1.1 / (5.0 * kAspect);
  EXPECT_EQ(f.Rect[2], static_cast<int>(std::ceil(0.5 * kWidth + half + kMargin)));
  EXPECT_EQ(f.Rect[0], static_cast<int>(std::floor(0.5 * kWidth - half - kMargin)));
  EXPECT_TRUE(f.PointSprites);
}
