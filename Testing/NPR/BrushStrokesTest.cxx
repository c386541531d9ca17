// Brush strokes over a block of water whose left half streams along +x and whose right half is
// still: the moving half gets strokes along its flow, the still half fixed strokes that fill it.
#include "parafluid/npr/BrushStrokes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

using namespace parafluid::npr;

namespace
{
constexpr double kSpacing = 0.02; // d [m]
constexpr double kStream = 1.0;   // [m/s] speed of the left half

struct Block
{
  std::vector<float> xyz, velocity, density;
  std::size_t size() const { return xyz.size() / 3; }
  bool moving(std::uint32_t i) const { return velocity[3 * i] > 0.0f; }
};

// 40 x 20 x 10 particles over [0, 0.8) x [0, 0.4) x [0, 0.2); x < 0.4 streams, with density rising
// along y so a stroke's value tells where its seed was.
Block block(double restSpeed = 0.0)
{
  Block b;
  for (int k = 0; k < 10; ++k)
  {
    for (int j = 0; j < 20; ++j)
    {
      for (int i = 0; i < 40; ++i)
      {
        const float x = static_cast<float>((i + 0.5) * kSpacing), y = static_cast<float>((j + 0.5) * kSpacing);
        b.xyz.insert(b.xyz.end(), { x, y, static_cast<float>((k + 0.5) * kSpacing) });
        const float u = static_cast<float>(i < 20 ? kStream : restSpeed);
        b.velocity.insert(b.velocity.end(), { u, static_cast<float>(i < 20 ? 0.0 : 0.5 * restSpeed), 0.0f });
        b.density.push_back(1000.0f + j);
      }
    }
  }
  return b;
}

BrushStrokeParameters parameters()
{
  BrushStrokeParameters p;
  p.flow.kernelRadius = 2.0 * kSpacing;
  p.flow.seedStride = 7;
  p.flow.pointsPerLine = 8;
  p.flow.lineDuration = 0.1; // a streaming line is 0.1 m long where the field stays defined
  p.strokeLength = 0.06;
  p.fillSpacing = 0.08;
  return p;
}

double strokeLength(const BrushStrokeSet& s, std::size_t k)
{
  double length = 0.0;
  for (std::uint32_t q = s.offsets[k] + 1; q < s.offsets[k + 1]; ++q)
  {
    length += std::sqrt(std::pow(s.points[3 * q] - s.points[3 * q - 3], 2) +
                        std::pow(s.points[3 * q + 1] - s.points[3 * q - 2], 2) +
                        std::pow(s.points[3 * q + 2] - s.points[3 * q - 1], 2));
  }
  return length;
}
} // namespace

TEST(BrushStrokes, MovingWaterGetsFlowStrokesStillWaterFixedOnes)
{
  const Block b = block();
  const BrushStrokeParameters p = parameters();
  const BrushStrokeSet s = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), b.density.data(), b.size(), p);
  ASSERT_GT(s.strokeCount(), 0u);
  std::size_t flow = 0, fixed = 0;
  for (std::size_t k = 0; k < s.strokeCount(); ++k)
  {
    const std::uint32_t seed = s.seed[k];
    EXPECT_EQ(s.value[k], b.density[seed]) << "stroke " << k << " carries its seed's value";
    if (s.fixed[k])
    {
      ++fixed;
      EXPECT_FALSE(b.moving(seed)) << "a fixed stroke sits on still water";
      EXPECT_NEAR(strokeLength(s, k), p.strokeLength, 1e-6) << "fixed strokes all have the one length";
      // Centred on its seed.
      const std::uint32_t middle = s.offsets[k] + 1;
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_NEAR(s.points[3 * middle + a], b.xyz[3 * seed + a], 1e-6);
      }
    }
    else
    {
      ++flow;
      EXPECT_TRUE(b.moving(seed)) << "a flow stroke starts in the moving water";
      EXPECT_GE(strokeLength(s, k), p.strokeLength - 1e-6) << "flow strokes are at least one stroke long";
      // Along the stream: every step is in +x.
      for (std::uint32_t q = s.offsets[k] + 1; q < s.offsets[k + 1]; ++q)
      {
        EXPECT_GT(s.points[3 * q] - s.points[3 * q - 3], 0.0f);
        EXPECT_NEAR(s.points[3 * q + 1], s.points[3 * q - 2], 1e-4);
      }
    }
  }
  EXPECT_GT(flow, 20u);
  // The still half, 0.4 x 0.4 x 0.2 m, holds 5 x 5 x 3 cubes of 0.08 m (the last layer partly):
  // one fixed stroke in each.
  EXPECT_EQ(fixed, 5u * 5u * 3u);
  // Flow strokes come first.
  const auto firstFixed = std::find(s.fixed.begin(), s.fixed.end(), 1);
  EXPECT_TRUE(std::all_of(firstFixed, s.fixed.end(), [](std::uint8_t f) { return f == 1; }));
}

TEST(BrushStrokes, FixedStrokesFillTheStillWater)
{
  const Block b = block();
  const BrushStrokeParameters p = parameters();
  const BrushStrokeSet s = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p);
  // Every still particle is within one cube's diagonal of a fixed stroke's centre.
  double worst = 0.0;
  for (std::uint32_t i = 0; i < b.size(); ++i)
  {
    if (b.moving(i))
    {
      continue;
    }
    double nearest = 1e9;
    for (std::size_t k = 0; k < s.strokeCount(); ++k)
    {
      if (s.fixed[k])
      {
        const float* c = &s.points[3 * (s.offsets[k] + 1)];
        nearest =
          std::min<double>(nearest, std::hypot(c[0] - b.xyz[3 * i], c[1] - b.xyz[3 * i + 1], c[2] - b.xyz[3 * i + 2]));
      }
    }
    worst = std::max(worst, nearest);
  }
  EXPECT_LT(worst, std::sqrt(3.0) * p.fillSpacing);
  EXPECT_TRUE(std::all_of(s.value.begin(), s.value.end(), [](float v) { return v == 0.0f; }));
}

TEST(BrushStrokesAtRest, PointAlongSlowVelocityOrVaryHorizontally)
{
  const BrushStrokeParameters p = parameters();
  // Slow but moving: the fixed strokes point along (2, 1, 0) / sqrt(5).
  {
    const Block b = block(0.1);
    const BrushStrokeSet s = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p);
    std::size_t fixed = 0;
    for (std::size_t k = 0; k < s.strokeCount(); ++k)
    {
      if (s.fixed[k])
      {
        ++fixed;
        const float* a = &s.points[3 * s.offsets[k]];
        const float* c = &s.points[3 * (s.offsets[k] + 2)];
        EXPECT_NEAR((c[0] - a[0]) / p.strokeLength, 2.0 / std::sqrt(5.0), 1e-5);
        EXPECT_NEAR((c[1] - a[1]) / p.strokeLength, 1.0 / std::sqrt(5.0), 1e-5);
      }
    }
    EXPECT_EQ(fixed, 75u);
  }
  // At rest: horizontal, and not all one way.
  {
    const Block b = block(0.0);
    const BrushStrokeSet s = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p);
    std::set<int> headings;
    for (std::size_t k = 0; k < s.strokeCount(); ++k)
    {
      if (s.fixed[k])
      {
        const float* a = &s.points[3 * s.offsets[k]];
        const float* c = &s.points[3 * (s.offsets[k] + 2)];
        EXPECT_NEAR(c[2], a[2], 1e-6);
        headings.insert(static_cast<int>(std::floor(std::atan2(c[1] - a[1], c[0] - a[0]) / 0.5)));
      }
    }
    EXPECT_GE(headings.size(), 6u) << "rest strokes in many directions (of 13 half-radian sectors)";
  }
}

TEST(BrushStrokes, BudgetKeepsFlowStrokesFirst)
{
  const Block b = block();
  BrushStrokeParameters p = parameters();
  const BrushStrokeSet all = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p);
  const std::size_t flow = std::count(all.fixed.begin(), all.fixed.end(), 0);
  p.maxStrokes = flow + 10;
  const BrushStrokeSet some = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p);
  EXPECT_EQ(some.strokeCount(), flow + 10);
  EXPECT_EQ(static_cast<std::size_t>(std::count(some.fixed.begin(), some.fixed.end(), 0)), flow);
}

TEST(BrushStrokes, SeedsAreThinnedToTheBudget)
{
  const Block b = block();
  BrushStrokeParameters p = parameters();
  p.flow.seedStride = 1;
  p.maxStrokes = 10;
  const BrushStrokeSet s = layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p);
  EXPECT_EQ(s.strokeCount(), 10u);
  // The 4,000 moving particles are thinned to 20 seeds; the first 10 long lines are kept.
  std::set<std::uint32_t> seeds(s.seed.begin(), s.seed.end());
  EXPECT_EQ(seeds.size(), 10u);
  for (std::uint32_t seed : seeds)
  {
    EXPECT_TRUE(b.moving(seed));
  }
}

TEST(BrushStrokes, BadInputIsRefused)
{
  Block b = block();
  BrushStrokeParameters p = parameters();
  const BrushStrokeSet none = layoutBrushStrokes(nullptr, nullptr, nullptr, 0, p);
  EXPECT_EQ(none.strokeCount(), 0u);
  p.strokeLength = 0.0;
  EXPECT_THROW(layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p), std::invalid_argument);
  p = parameters();
  p.fillSpacing = std::nan("");
  EXPECT_THROW(layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p), std::invalid_argument);
  p = parameters();
  b.xyz[5] = std::nanf("");
  EXPECT_THROW(layoutBrushStrokes(b.xyz.data(), b.velocity.data(), nullptr, b.size(), p), std::invalid_argument);
}
