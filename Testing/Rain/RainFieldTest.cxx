// The stateless drops: analytic paths against integration, impacts on the ground, the rain delivered,
// the drop-size law, determinism and bad input.
#include "parafluid/rain/RainField.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

using parafluid::HeightField;
using parafluid::rain::DropSizeDistribution;
using parafluid::rain::Impact;
using parafluid::rain::RainField;
using parafluid::rain::RainParameters;

namespace
{
std::shared_ptr<HeightField> flatGround(double size, double height = 0.0)
{
  return std::make_shared<HeightField>(std::vector<float>(4, static_cast<float>(height)), 2, 2, 0.0, 0.0, size, size,
                                       0.0);
}

/// Steep sine hills: 1.5 m high, 3 m wavelength, on a 0.1 m grid.
std::shared_ptr<HeightField> hillyGround(double size)
{
  const int n = static_cast<int>(size / 0.1) + 1;
  std::vector<float> z(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      z[static_cast<std::size_t>(j) * n + i] =
        static_cast<float>(0.75 * (1.0 + std::sin(2.0 * M_PI * i * 0.1 / 3.0) * std::cos(2.0 * M_PI * j * 0.1 / 3.0)));
    }
  }
  return std::make_shared<HeightField>(std::move(z), n, n, 0.0, 0.0, 0.1, 0.1, 0.0);
}

RainParameters shower(double size, int cells, double dropsPerRealDrop)
{
  RainParameters p;
  p.bounds = { 0.0, size, 0.0, size };
  p.cells = { cells, cells };
  p.height = 12.0;
  p.rainfallRate = 20.0;
  p.dropsPerRealDrop = dropsPerRealDrop;
  p.seed = 7;
  return p;
}
} // namespace

TEST(RainDrops, AnalyticPathMatchesIntegration)
{
  // Terminal drops (quadratic drag balancing gravity, starting at the terminal speed) and ballistic
  // drops (gravity only): positions at t1 from the state at t0, by RK4, against the formula.
  for (bool terminal : { true, false })
  {
    RainParameters p = shower(6.0, 4, 1e-3);
    p.terminalVelocity = terminal;
    p.wind = { 1.5, -0.5 };
    RainField rain(p, flatGround(6.0));
    const std::size_t n = rain.dropCount();
    ASSERT_GT(n, 10u);
    const double t0 = 3.0, t1 = 3.2;
    int compared = 0;
    for (std::size_t s = 0; s < n; ++s)
    {
      const auto slot = static_cast<std::uint32_t>(s);
      if (rain.dropAt(slot, t0) != rain.dropAt(slot, t1))
      {
        continue; // a new drop was born in between
      }
      double x[3], v[3], end[3], unused[3];
      rain.drop(slot, t0, x, v);
      rain.drop(slot, t1, end, unused);
      const double vt = -v[2];
      const double k = terminal ? p.gravity / (vt * vt) : 0.0; // drag coefficient that balances gravity
      auto accel = [&](const double* vel, double* a)
      {
        a[0] = a[1] = 0.0;
        a[2] = -p.gravity + k * vel[2] * vel[2];
      };
      const int steps = 1000;
      const double h = (t1 - t0) / steps;
      for (int it = 0; it < steps; ++it)
      {
        double a1[3], a2[3], a3[3], a4[3], vv[3];
        accel(v, a1);
        for (int c = 0; c < 3; ++c)
          vv[c] = v[c] + 0.5 * h * a1[c];
        double k2x[3] = { vv[0], vv[1], vv[2] };
        accel(vv, a2);
        for (int c = 0; c < 3; ++c)
          vv[c] = v[c] + 0.5 * h * a2[c];
        double k3x[3] = { vv[0], vv[1], vv[2] };
        accel(vv, a3);
        for (int c = 0; c < 3; ++c)
          vv[c] = v[c] + h * a3[c];
        double k4x[3] = { vv[0], vv[1], vv[2] };
        accel(vv, a4);
        for (int c = 0; c < 3; ++c)
        {
          x[c] += h / 6.0 * (v[c] + 2.0 * k2x[c] + 2.0 * k3x[c] + k4x[c]);
          v[c] += h / 6.0 * (a1[c] + 2.0 * a2[c] + 2.0 * a3[c] + a4[c]);
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(x[c], end[c], 1e-6) << "drop " << s << " axis " << c << (terminal ? " terminal" : " ballistic");
      }
      ++compared;
    }
    EXPECT_GT(compared, static_cast<int>(n / 2));
  }
}

TEST(RainDrops, ImpactsLieOnTheGroundAndNothingTunnels)
{
  // Strong wind over steep hills: drops cross ridges on their way. Every impact is on the ground,
  // and a drop is above the ground all along its path until its impact time.
  const double size = 9.0;
  RainParameters p = shower(size, 6, 2e-4);
  p.wind = { 6.0, 2.0 };
  p.height = 6.0;
  auto ground = hillyGround(size);
  RainField rain(p, ground);
  const std::size_t n = rain.dropCount();
  std::vector<std::int64_t> counted;
  std::vector<Impact> impacts;
  rain.collectImpacts(4.0, nullptr, counted, impacts);
  ASSERT_GT(impacts.size(), 50u);
  double cell[2];
  rain.cellSize(cell);
  for (const Impact& impact : impacts)
  {
    const double g = ground->heightAt(impact.position[0], impact.position[1]);
    EXPECT_NEAR(impact.position[2], g, 1e-4 * cell[0]) << "slot " << impact.slot;
    EXPECT_LE(impact.time, 4.0);
  }
  std::vector<float> x(3 * n);
  int checked = 0, ridges = 0;
  for (double t = 0.05; t < 4.0; t += 0.05)
  {
    rain.evaluate(t, nullptr, x.data(), nullptr, nullptr);
    for (std::size_t s = 0; s < n; ++s)
    {
      const auto slot = static_cast<std::uint32_t>(s);
      const Impact impact = rain.impactOf(slot, rain.dropAt(slot, t), nullptr);
      const double g = ground->heightAt(x[3 * s], x[3 * s + 1]);
      if (t < impact.time)
      {
        EXPECT_GT(x[3 * s + 2], g - 1e-5) << "drop " << s << " under the ground at t = " << t;
        ++checked;
      }
      else
      {
        ++ridges; // met a ridge before reaching its target
      }
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(ridges, 0) << "the wind should carry some drops into a ridge";
}

TEST(RainDrops, DeliveredRainfallMatchesTheRate)
{
  const double size = 10.0;
  RainParameters p = shower(size, 16, 2e-3);
  p.rainfallRate = 25.0;
  RainField rain(p, flatGround(size));
  std::vector<std::int64_t> counted;
  std::vector<Impact> impacts;
  double volume = 0.0;
  for (int step = 1; step <= 600; ++step)
  {
    impacts.clear();
    rain.collectImpacts(0.1 * step, nullptr, counted, impacts);
    for (const Impact& impact : impacts)
    {
      volume += rain.waterPerImpact(impact.slot);
    }
  }
  const double depthMm = volume / (size * size) * 1e3;
  const double expectedMm = p.rainfallRate * 60.0 / 3600.0;
  RecordProperty("delivered_mm", std::to_string(depthMm));
  EXPECT_NEAR(depthMm, expectedMm, 0.01 * expectedMm) << rain.dropCount() << " drops";
}

TEST(RainDrops, MarshallPalmerHistogram)
{
  // A million drawn drops against N(D) = N0 exp(-Lambda D), integrated over 40 bins of equal
  // probability (chi-square, 39 degrees of freedom: 72 is the 0.1 % tail).
  const double size = 20.0;
  RainParameters p = shower(size, 32, 1.0);
  p.rainfallRate = 10.0;
  p.height = 1.0;
  RainField rain(p, flatGround(size, -1.0)); // 2 m of air
  const auto& d = rain.diameters();
  ASSERT_GT(d.size(), 900000u);
  const DropSizeDistribution& law = rain.sizes();
  EXPECT_NEAR(law.slope() * 1e-3, 4.1 * std::pow(10.0, -0.21), 1e-9); // per mm
  const int bins = 40;
  std::vector<double> edges(bins + 1);
  for (int b = 0; b <= bins; ++b)
  {
    edges[b] = law.diameterAt(static_cast<double>(b) / bins);
  }
  edges[bins] = DropSizeDistribution::kMaxDiameter;
  // Expected counts from the law itself, by numerical integration of N(D) over each bin.
  std::vector<double> expected(bins);
  double total = 0.0;
  for (int b = 0; b < bins; ++b)
  {
    const int m = 200;
    double sum = 0.0;
    for (int k = 0; k < m; ++k)
    {
      sum += law.density(edges[b] + (k + 0.5) * (edges[b + 1] - edges[b]) / m);
    }
    expected[b] = sum * (edges[b + 1] - edges[b]) / m;
    total += expected[b];
  }
  std::vector<double> observed(bins, 0.0);
  for (float diameter : d)
  {
    const int b = static_cast<int>(std::upper_bound(edges.begin(), edges.end(), diameter) - edges.begin()) - 1;
    observed[std::clamp(b, 0, bins - 1)] += 1.0;
  }
  double chi2 = 0.0;
  for (int b = 0; b < bins; ++b)
  {
    const double e = expected[b] / total * static_cast<double>(d.size());
    chi2 += (observed[b] - e) * (observed[b] - e) / e;
  }
  RecordProperty("chi2", std::to_string(chi2));
  EXPECT_LT(chi2, 72.0);
  // The number of drops in the air is what the law gives for the air above the area.
  const double air = size * size * 2.0;
  EXPECT_NEAR(static_cast<double>(d.size()), law.dropsPerVolume() * air, 32.0 * 32.0);
}

TEST(RainDrops, SameSeedSameDropsOnAnyThreadCount)
{
  RainParameters p = shower(9.0, 12, 5e-4);
  p.wind = { 3.0, 1.0 };
  auto ground = hillyGround(9.0);
  std::vector<std::vector<float>> positions;
  std::vector<std::vector<Impact>> impacts;
  for (int threads : { 1, 2, 4 })
  {
    omp_set_num_threads(threads);
    RainField rain(p, ground);
    positions.emplace_back(3 * rain.dropCount());
    rain.evaluate(2.5, nullptr, positions.back().data(), nullptr, nullptr);
    std::vector<std::int64_t> counted;
    impacts.emplace_back();
    rain.collectImpacts(2.5, nullptr, counted, impacts.back());
  }
  omp_set_num_threads(2);
  for (std::size_t r = 1; r < positions.size(); ++r)
  {
    EXPECT_EQ(positions[r], positions[0]);
    ASSERT_EQ(impacts[r].size(), impacts[0].size());
    for (std::size_t i = 0; i < impacts[0].size(); ++i)
    {
      EXPECT_EQ(impacts[r][i].slot, impacts[0][i].slot);
      EXPECT_EQ(impacts[r][i].time, impacts[0][i].time);
    }
  }
}

TEST(RainDrops, ConstantNumberInTheAir)
{
  RainParameters p = shower(9.0, 8, 5e-4);
  auto ground = hillyGround(9.0);
  RainField rain(p, ground);
  std::vector<std::uint8_t> air(rain.dropCount());
  for (double t : { 0.0, 1.3, 7.9 })
  {
    rain.evaluate(t, nullptr, nullptr, nullptr, air.data());
    EXPECT_EQ(std::count(air.begin(), air.end(), 1), static_cast<long>(rain.dropCount()));
  }
  // Water standing 0.5 m deep over everything stops the drops that are below its level.
  std::vector<float> water(rain.cellCount(), 2.0f);
  std::vector<float> x(3 * rain.dropCount());
  rain.evaluate(1.3, &water, x.data(), nullptr, air.data());
  for (std::size_t s = 0; s < rain.dropCount(); ++s)
  {
    EXPECT_EQ(air[s] != 0, x[3 * s + 2] > 2.0f) << s;
  }
  std::vector<std::int64_t> counted;
  std::vector<Impact> impacts;
  rain.collectImpacts(3.0, &water, counted, impacts);
  ASSERT_FALSE(impacts.empty());
  for (const Impact& impact : impacts)
  {
    if (impact.onWater)
    {
      EXPECT_NEAR(impact.position[2], 2.0f, 1e-4f);
    }
  }
}

TEST(RainDrops, BadParametersAreRefusedByName)
{
  auto ground = flatGround(4.0);
  auto message = [&](const RainParameters& p)
  {
    try
    {
      RainField rain(p, ground);
    }
    catch (const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  RainParameters p = shower(4.0, 4, 1e-3);
  p.rainfallRate = std::nan("");
  EXPECT_NE(message(p).find("RainfallRate"), std::string::npos);
  p = shower(4.0, 4, 1e-3);
  p.cells = { 0, 4 };
  EXPECT_NE(message(p).find("Cells"), std::string::npos);
  p = shower(4.0, 4, 1e-3);
  p.height = -1.0;
  EXPECT_NE(message(p).find("PrecipitationHeight"), std::string::npos);
  p = shower(4.0, 4, 1e-3);
  p.dropsPerRealDrop = 2.0;
  EXPECT_NE(message(p).find("DropsPerRealDrop"), std::string::npos);
  p = shower(4000.0, 4, 1.0);
  EXPECT_NE(message(p).find("200 million"), std::string::npos);
}
