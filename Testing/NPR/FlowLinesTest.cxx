// Flow lines through a solid-body vortex sampled on particles: the lines follow the true circles,
// their length follows the speed, curvature is 1/r, and the budget keeps the longest-curved lines.
#include "parafluid/npr/FlowLines.h"
#include "parafluid/common/MathConstants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace parafluid::npr;
using parafluid::kPi;

namespace
{
constexpr double kSpacing = 0.02; // d [m]
constexpr double kOmega = 2.0;    // [rad/s]

// Lattice particles in a disc of radius 0.5 m, 5 layers thick, turning as a rigid body about z.
void vortex(std::vector<float>& xyz, std::vector<float>& velocity)
{
  const int n = static_cast<int>(0.5 / kSpacing);
  for (int k = 0; k < 5; ++k)
  {
    for (int j = -n; j <= n; ++j)
    {
      for (int i = -n; i <= n; ++i)
      {
        const double x = i * kSpacing, y = j * kSpacing;
        if (x * x + y * y > 0.25)
        {
          continue;
        }
        xyz.insert(xyz.end(), { float(x), float(y), float(k * kSpacing) });
        velocity.insert(velocity.end(), { float(-kOmega * y), float(kOmega * x), 0.0f });
      }
    }
  }
}

// Seeds on the middle layer at radii 0.1 ... 0.4 m, at several angles (off the lattice).
std::vector<float> seedRing()
{
  std::vector<float> seeds;
  for (int r = 0; r < 7; ++r)
  {
    for (int a = 0; a < 5; ++a)
    {
      const double radius = 0.1 + 0.05 * r, angle = 0.3 + 1.1 * a + 0.07 * r;
      seeds.insert(seeds.end(),
                   { float(radius * std::cos(angle)), float(radius * std::sin(angle)), float(2 * kSpacing) });
    }
  }
  return seeds;
}
} // namespace

TEST(FlowLines, FollowASolidBodyVortexWithinOnePercentOfTheCircle)
{
  std::vector<float> xyz, velocity;
  vortex(xyz, velocity);
  const std::vector<float> seeds = seedRing();
  for (FlowIntegrator integrator : { FlowIntegrator::RK4, FlowIntegrator::RK2 })
  {
    FlowLineParameters p;
    p.kernelRadius = 2 * kSpacing;
    p.pointsPerLine = 16;
    p.lineDuration = kPi / (2 * kOmega); // a quarter turn
    p.integrator = integrator;
    const FlowLineSet lines =
      traceFlowLines(xyz.data(), velocity.data(), xyz.size() / 3, p, seeds.data(), seeds.size() / 3);
    ASSERT_EQ(lines.lineCount(), seeds.size() / 3);
    double worst = 0.0;
    for (std::size_t l = 0; l < lines.lineCount(); ++l)
    {
      const float* s = &seeds[3 * lines.seed[l]];
      const double r0 = std::hypot(s[0], s[1]);
      ASSERT_EQ(lines.offsets[l + 1] - lines.offsets[l], 16u) << "a line stopped inside the fluid";
      double meanCurvature = 0.0;
      for (std::uint32_t k = lines.offsets[l]; k < lines.offsets[l + 1]; ++k)
      {
        const double r = std::hypot(lines.points[3 * k], lines.points[3 * k + 1]);
        worst = std::max(worst, std::abs(r - r0) / r0);
        EXPECT_NEAR(lines.speed[k], kOmega * r, 0.01 * kOmega * r);
        // Pointwise curvature is a second difference of interpolated positions: a few per cent.
        EXPECT_NEAR(lines.curvature[k], 1.0 / r0, 0.05 / r0);
        meanCurvature += lines.curvature[k] / 16.0;
      }
      EXPECT_NEAR(meanCurvature, 1.0 / r0, 0.01 / r0);
      // Length follows speed: the polyline of a quarter circle of radius r0 (15 chords).
      const double chords = 15 * 2 * r0 * std::sin(kPi / 4 / 15);
      EXPECT_NEAR(lines.length[l], chords, 0.01 * chords);
      EXPECT_NEAR(lines.turning[l], kPi / 2 * 14 / 15, 0.01);
    }
    std::printf("%s: worst radial deviation %.4f %%\n", integrator == FlowIntegrator::RK4 ? "RK4" : "RK2", 100 * worst);
    EXPECT_LT(worst, 0.01);
  }
}

TEST(FlowLines, BudgetKeepsTheLongestCurvedLines)
{
  std::vector<float> xyz, velocity;
  vortex(xyz, velocity);
  const std::vector<float> seeds = seedRing();
  FlowLineParameters p;
  p.kernelRadius = 2 * kSpacing;
  p.lineDuration = 0.3;
  p.maxLines = 5;
  const FlowLineSet lines =
    traceFlowLines(xyz.data(), velocity.data(), xyz.size() / 3, p, seeds.data(), seeds.size() / 3);
  ASSERT_EQ(lines.lineCount(), 5u);
  // Equal turning everywhere in a rigid vortex, so the outermost seeds (0.4 m) have the longest lines.
  for (std::size_t l = 0; l < 5; ++l)
  {
    const float* s = &seeds[3 * lines.seed[l]];
    EXPECT_NEAR(std::hypot(s[0], s[1]), 0.4, 1e-5);
  }
}

TEST(FlowLines, SeedStrideAndLinesLeavingTheFluid)
{
  // Uniform flow in +x through a block: every line is straight, and lines stop at the block's end.
  std::vector<float> xyz, velocity;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 20; ++i)
      {
        xyz.insert(xyz.end(), { float(i * kSpacing), float(j * kSpacing), float(k * kSpacing) });
        velocity.insert(velocity.end(), { 1.0f, 0.0f, 0.0f });
      }
  FlowLineParameters p;
  p.kernelRadius = 2 * kSpacing;
  p.seedStride = 20; // one seed per row: the row's first particle
  p.pointsPerLine = 11;
  p.lineDuration = 1.0; // would run 1 m, far beyond the 0.4 m block
  const FlowLineSet lines = traceFlowLines(xyz.data(), velocity.data(), xyz.size() / 3, p);
  ASSERT_EQ(lines.lineCount(), 16u);
  for (std::size_t l = 0; l < lines.lineCount(); ++l)
  {
    EXPECT_LT(lines.offsets[l + 1] - lines.offsets[l], 11u);
    EXPECT_NEAR(lines.turning[l], 0.0, 1e-6);
    // The last point is still within the kernel's reach of the block.
    EXPECT_LT(lines.points[3 * (lines.offsets[l + 1] - 1)], 19 * kSpacing + 2 * kSpacing);
  }
}

TEST(FlowLines, EmptyInputAndBadParameters)
{
  FlowLineParameters p;
  p.kernelRadius = 0.04;
  EXPECT_EQ(traceFlowLines(nullptr, nullptr, 0, p).lineCount(), 0u);
  const float one[3] = { 0, 0, 0 }, still[3] = { 0, 0, 0 };
  const FlowLineSet single = traceFlowLines(one, still, 1, p);
  ASSERT_EQ(single.lineCount(), 1u);
  EXPECT_FLOAT_EQ(single.length[0], 0.0f);
  p.pointsPerLine = 1;
  EXPECT_THROW(traceFlowLines(one, still, 1, p), std::invalid_argument);
  p.pointsPerLine = 16;
  p.lineDuration = -1;
  EXPECT_THROW(traceFlowLines(one, still, 1, p), std::invalid_argument);
  p.lineDuration = 0.1;
  const float bad[3] = { NAN, 0, 0 };
  EXPECT_THROW(traceFlowLines(bad, still, 1, p), std::invalid_argument);
}

TEST(FlowLines, NaNAndHugeVelocitiesEndLinesInsteadOfPoisoningThem)
{
  // One particle's velocity is NaN, another's overflows a float step: the lines near them stop
  // (no NaN point is ever emitted) and the query at a NaN point finds no neighbour (it used to
  // cast NaN to a cell index and read outside the grid).
  std::vector<float> xyz, velocity;
  vortex(xyz, velocity);
  velocity[3 * 10] = std::numeric_limits<float>::quiet_NaN();
  velocity[3 * 500 + 1] = 3e38f;
  FlowLineParameters p;
  p.kernelRadius = 2 * kSpacing;
  p.lineDuration = 0.5;
  p.seedStride = 1;
  const FlowLineSet lines = traceFlowLines(xyz.data(), velocity.data(), xyz.size() / 3, p);
  ASSERT_GT(lines.lineCount(), 0u);
  for (float v : lines.points)
  {
    ASSERT_TRUE(std::isfinite(v));
  }
  for (float s : lines.speed)
  {
    ASSERT_TRUE(std::isfinite(s));
  }
}
