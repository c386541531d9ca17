// The Gerstner ocean model: crest speeds from the dispersion relation, shoaling and refraction over
// a sloping floor, no folds for any preset, breaking only in shallow water, analytic normals and
// Jacobian against finite differences, bad parameters.
#include "parafluid/ocean/GerstnerOcean.h"
#include "parafluid/common/MathConstants.h"
#include "parafluid/ocean/Bathymetry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

namespace
{
using namespace parafluid::ocean;
using parafluid::kPi;

GerstnerWave wave(double amplitude, double wavelength, double direction, double steepness)
{
  GerstnerWave w;
  w.amplitude = amplitude;
  w.wavelength = wavelength;
  w.direction = direction;
  w.steepness = steepness;
  return w;
}

/// Positions of the crests (height maxima of the displaced surface) along the x axis between x0
/// and x1 at `time`, located to a fraction of the sampling step by a parabola through the top three.
std::vector<double> crests(const GerstnerOcean& ocean, double x0, double x1, double time, int samples = 20000)
{
  std::vector<float> x(samples), y(samples, 0.0f), d(3 * samples);
  for (int i = 0; i < samples; ++i)
  {
    x[i] = static_cast<float>(x0 + (x1 - x0) * i / (samples - 1));
  }
  ocean.evaluate(x.data(), y.data(), x.size(), time, d.data(), nullptr, nullptr, nullptr, nullptr);
  std::vector<double> found;
  for (int i = 1; i + 1 < samples; ++i)
  {
    const double a = d[3 * (i - 1) + 2], b = d[3 * i + 2], c = d[3 * (i + 1) + 2];
    if (b > a && b >= c)
    {
      // Crest at the displaced position: interpolate the displaced x of the three samples too.
      const double denominator = a - 2.0 * b + c;
      const double f = denominator != 0.0 ? 0.5 * (a - c) / denominator : 0.0; // in [-1/2, 1/2]
      const double xa = x[i - 1] + d[3 * (i - 1)], xb = x[i] + d[3 * i], xc = x[i + 1] + d[3 * (i + 1)];
      found.push_back(f >= 0.0 ? xb + f * (xc - xb) : xb + f * (xb - xa));
    }
  }
  return found;
}

TEST(GerstnerOcean, DeepWaterCrestTravelsAtSqrtGOverK)
{
  OceanParameters p;
  p.waves = { wave(0.4, 20.0, 0.0, 0.6) };
  const GerstnerOcean ocean(p);
  const double k = 2.0 * kPi / 20.0, expected = std::sqrt(kStandardGravity / k);
  const double dt = 1.0;
  const auto before = crests(ocean, 0.0, 30.0, 0.0), after = crests(ocean, 0.0, 30.0, dt);
  ASSERT_FALSE(before.empty());
  ASSERT_FALSE(after.empty());
  // The crest that was at before[0] is now expected * dt further on; find the nearest one.
  double best = 1e9;
  for (double c : after)
  {
    best = std::min(best, std::fabs((c - before[0]) / dt - expected));
  }
  EXPECT_LT(best / expected, 0.005) << "crest speed off by " << best << " m/s of " << expected;
}

TEST(GerstnerOcean, FiniteDepthCrestSpeedAndWavelengthFollowDispersion)
{
  OceanParameters p;
  p.waves = { wave(0.2, 30.0, 0.0, 0.5) };
  p.depth = 2.5; // k_deep h = 0.52: well inside intermediate depth
  const GerstnerOcean ocean(p);
  const auto a = crests(ocean, 0.0, 60.0, 0.0), b = crests(ocean, 0.0, 60.0, 0.5);
  ASSERT_GE(a.size(), 3u);
  const double wavelength = a[1] - a[0];
  const double k = 2.0 * kPi / wavelength;
  EXPECT_NEAR(k, shoalingWavenumber(2.0 * kPi / 30.0, 2.5), 0.002 * k) << "shorter than in deep water";
  double best = 1e9;
  const double expected = std::sqrt(kStandardGravity / k * std::tanh(k * 2.5));
  for (double c : b)
  {
    best = std::min(best, std::fabs((c - a[0]) / 0.5 - expected));
  }
  EXPECT_LT(best / expected, 0.005);
  EXPECT_LT(expected, std::sqrt(kStandardGravity * 30.0 / (2.0 * kPi))) << "slower than in deep water";
}

/// A beach: the floor rises along +x from 12 m deep at x = 0 to dry land past x = 300.
std::shared_ptr<Bathymetry> beach()
{
  const int nx = 121, ny = 41;
  std::vector<float> elevation;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const double x = 2.5 * i;
      elevation.push_back(static_cast<float>(-12.0 + 12.5 * x / 300.0));
    }
  }
  return std::make_shared<Bathymetry>(elevation, nx, ny, 0.0, -50.0, 2.5, 2.5, 0.0);
}

TEST(GerstnerOcean, WavelengthShrinksTowardsTheShoreAsDispersionSays)
{
  OceanParameters p;
  p.waves = { wave(0.1, 40.0, 0.0, 0.3) };
  const auto floor = beach();
  const double region[4] = { 0.0, 300.0, -50.0, 50.0 };
  const GerstnerOcean ocean(p, floor, region);
  const auto c = crests(ocean, 0.0, 280.0, 0.0, 40000);
  ASSERT_GE(c.size(), 6u);
  double previous = 1e9;
  for (std::size_t i = 0; i + 1 < c.size(); ++i)
  {
    const double wavelength = c[i + 1] - c[i];
    const double middle = 0.5 * (c[i] + c[i + 1]);
    const double h = floor->depth(middle, 0.0);
    if (h < 0.5)
    {
      break;
    }
    const double expected = 2.0 * kPi / shoalingWavenumber(2.0 * kPi / 40.0, h);
    EXPECT_NEAR(wavelength, expected, 0.03 * expected) << "between crests at " << c[i] << " and " << c[i + 1];
    EXPECT_LT(wavelength, previous) << "shorter at every crest towards the shore";
    previous = wavelength;
  }
}

TEST(GerstnerOcean, CrestsTurnTowardsTheShore)
{
  // A wave coming in at 45 degrees to the shore normal (+x): its local direction turns to face the
  // beach as the water shallows.
  OceanParameters p;
  p.waves = { wave(0.1, 40.0, 45.0, 0.3) };
  const double region[4] = { 0.0, 300.0, -50.0, 50.0 };
  const GerstnerOcean ocean(p, beach(), region);
  // The local wave direction is where the displacement points at phase 0; measure it as the
  // horizontal displacement direction at a crest-free phase: use the normal's tilt instead.
  double previousAngle = 90.0;
  for (double x : { 20.0, 100.0, 180.0, 240.0, 270.0 })
  {
    // Sample the horizontal displacement over a full period at (x, 0): it oscillates along D.
    std::vector<float> xs(1, static_cast<float>(x)), ys(1, 0.0f), d(3);
    double sxx = 0, sxy = 0, syy = 0;
    for (int k = 0; k < 64; ++k)
    {
      ocean.evaluate(xs.data(), ys.data(), 1, 0.1 * k, d.data(), nullptr, nullptr, nullptr, nullptr);
      sxx += d[0] * d[0], sxy += d[0] * d[1], syy += d[1] * d[1];
    }
    // Principal axis of the horizontal motion.
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy) * 180.0 / kPi;
    EXPECT_LT(angle, previousAngle) << "at x = " << x;
    EXPECT_GT(angle, 0.0);
    previousAngle = angle;
  }
  EXPECT_LT(previousAngle, 30.0) << "near the shore the crests run nearly parallel to it";
}

TEST(GerstnerOcean, NoPresetEverFolds)
{
  for (SeaState state : { SeaState::Calm, SeaState::Swell, SeaState::Storm })
  {
    OceanParameters p;
    p.waves = seaStatePreset(state, 30.0);
    p.windDirection = 30.0;
    p.windLean = 0.3;
    const GerstnerOcean ocean(p);
    const int n = 200;
    std::vector<float> x, y;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        x.push_back(1.3f * i), y.push_back(1.7f * j);
      }
    }
    std::vector<float> J(x.size());
    for (double t : { 0.0, 3.7, 11.2 })
    {
      ocean.evaluate(x.data(), y.data(), x.size(), t, nullptr, nullptr, J.data(), nullptr, nullptr);
      EXPECT_GT(*std::min_element(J.begin(), J.end()), 0.0f) << "preset " << static_cast<int>(state);
    }
  }
}

TEST(GerstnerOcean, OverSteepWavesAreClampedSoTheyDoNotFold)
{
  OceanParameters p;
  p.waves = { wave(2.0, 10.0, 0.0, 1.0), wave(1.5, 12.0, 40.0, 1.0), wave(1.0, 7.0, -30.0, 1.0) };
  p.maxSteepness = 0.95;
  const GerstnerOcean ocean(p);
  double total = 0.0;
  for (const auto& w : ocean.effectiveWaves())
  {
    total += w.steepness * w.deepWavenumber() * w.amplitude;
  }
  EXPECT_NEAR(total, 0.95, 1e-9);
  std::vector<float> x, y;
  for (int i = 0; i < 100000; ++i)
  {
    x.push_back(0.037f * (i % 400)), y.push_back(0.041f * (i / 400));
  }
  std::vector<float> J(x.size());
  ocean.evaluate(x.data(), y.data(), x.size(), 2.0, nullptr, nullptr, J.data(), nullptr, nullptr);
  EXPECT_GT(*std::min_element(J.begin(), J.end()), 0.0f);
}

TEST(GerstnerOcean, BreaksOnlyWhereTheWaterIsShallow)
{
  OceanParameters p;
  p.waves = { wave(0.5, 40.0, 0.0, 0.5) };
  const auto floor = beach();
  const double region[4] = { 0.0, 300.0, -50.0, 50.0 };
  const GerstnerOcean ocean(p, floor, region);
  std::vector<float> x, y;
  for (int i = 0; i < 3000; ++i)
  {
    x.push_back(0.1f * i), y.push_back(0.0f);
  }
  std::vector<float> foam(x.size()), depth(x.size());
  double deepestFoam = 0.0;
  bool breaking = false;
  for (int k = 0; k < 40; ++k)
  {
    ocean.evaluate(x.data(), y.data(), x.size(), 0.17 * k, nullptr, nullptr, nullptr, foam.data(), depth.data());
    for (std::size_t i = 0; i < x.size(); ++i)
    {
      if (foam[i] > 0.0f)
      {
        deepestFoam = std::max(deepestFoam, static_cast<double>(depth[i]));
        breaking = true;
      }
    }
  }
  EXPECT_TRUE(breaking) << "a 1 m wave must break on this beach";
  // Breaking starts where the height 2 A Sz reaches 0.7 x 0.78 of the depth: under 2 m here.
  EXPECT_LT(deepestFoam, 2.0);
  EXPECT_GT(deepestFoam, 0.3);
}

TEST(GerstnerOcean, NormalsAndJacobianMatchFiniteDifferences)
{
  OceanParameters p;
  p.waves = seaStatePreset(SeaState::Storm, 10.0);
  p.windLean = 0.4;
  p.windDirection = 10.0;
  const GerstnerOcean ocean(p);
  const float e = 1e-3f;
  for (int s = 0; s < 50; ++s)
  {
    const float x0 = 3.1f * s, y0 = 1.9f * s;
    const float xs[5] = { x0, x0 + e, x0 - e, x0, x0 }, ys[5] = { y0, y0, y0, y0 + e, y0 - e };
    float d[15], n[15], J[5];
    ocean.evaluate(xs, ys, 5, 4.2, d, n, J, nullptr, nullptr);
    double tx[3], ty[3];
    for (int c = 0; c < 3; ++c)
    {
      tx[c] = (d[3 + c] - d[6 + c]) / (2.0 * e) + (c == 0 ? 1.0 : 0.0);
      ty[c] = (d[9 + c] - d[12 + c]) / (2.0 * e) + (c == 1 ? 1.0 : 0.0);
    }
    const double fdJ = tx[0] * ty[1] - tx[1] * ty[0];
    EXPECT_NEAR(J[0], fdJ, 2e-2) << "sample " << s;
    double fn[3] = { tx[1] * ty[2] - tx[2] * ty[1], tx[2] * ty[0] - tx[0] * ty[2], fdJ };
    const double length = std::sqrt(fn[0] * fn[0] + fn[1] * fn[1] + fn[2] * fn[2]);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(n[c], fn[c] / length, 2e-2) << "sample " << s << " component " << c;
    }
  }
}

TEST(GerstnerOcean, SameResultForAnyThreadCount)
{
  OceanParameters p;
  p.waves = seaStatePreset(SeaState::Swell, 0.0);
  const GerstnerOcean ocean(p, beach());
  std::vector<float> x, y;
  for (int i = 0; i < 5000; ++i)
  {
    x.push_back(0.06f * i), y.push_back(0.01f * (i % 97));
  }
  std::vector<float> a(3 * x.size()), b(3 * x.size());
  ocean.evaluate(x.data(), y.data(), x.size(), 1.5, a.data(), nullptr, nullptr, nullptr, nullptr, 1);
  ocean.evaluate(x.data(), y.data(), x.size(), 1.5, b.data(), nullptr, nullptr, nullptr, nullptr, 2);
  EXPECT_EQ(a, b);
}

TEST(GerstnerOcean, RejectsBadParameters)
{
  OceanParameters p;
  p.waves = { wave(-1.0, 10.0, 0.0, 0.5) };
  EXPECT_THROW(GerstnerOcean{ p }, std::invalid_argument);
  p.waves = { wave(1.0, 0.0, 0.0, 0.5) };
  EXPECT_THROW(GerstnerOcean{ p }, std::invalid_argument);
  p.waves = { wave(1.0, 10.0, 0.0, 1.5) };
  EXPECT_THROW(GerstnerOcean{ p }, std::invalid_argument);
  p.waves = { wave(1.0, 10.0, 0.0, 0.5) };
  p.depth = 0.0;
  EXPECT_THROW(GerstnerOcean{ p }, std::invalid_argument);
  p.depth = kDeepWater;
  p.windLean = 2.0;
  EXPECT_THROW(GerstnerOcean{ p }, std::invalid_argument);
  EXPECT_THROW(Bathymetry({ 0.0f, 1.0f }, 2, 1, 0, 0, 1, 1, 0), std::invalid_argument);
  EXPECT_THROW(Bathymetry({ 0.0f, 1.0f, NAN, 0.0f }, 2, 2, 0, 0, 1, 1, 0), std::invalid_argument);
}

TEST(Bathymetry, RasterisesATerrainSurface)
{
  // Two triangles making the plane z = 0.1 x - 5 over [0, 100]^2.
  const std::vector<float> points = { 0, 0, -5, 100, 0, 5, 100, 100, 5, 0, 100, -5 };
  const std::vector<std::uint32_t> triangles = { 0, 1, 2, 0, 2, 3 };
  const Bathymetry b = Bathymetry::fromTriangles(points, triangles, 51, 51, 0.0);
  for (double x : { 0.0, 13.0, 50.0, 77.7, 100.0 })
  {
    EXPECT_NEAR(b.depth(x, 42.0), 5.0 - 0.1 * x, 1e-4) << "x = " << x;
  }
  double g[2];
  b.depthGradient(30.0, 30.0, g);
  EXPECT_NEAR(g[0], -0.1, 1e-5);
  EXPECT_NEAR(g[1], 0.0, 1e-5);
}
} // namespace
