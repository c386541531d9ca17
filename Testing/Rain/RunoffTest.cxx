// Rain becoming SPH water: the volume it carries, a basin filled to the level its volume gives,
// water running down a slope and never under it, and infiltration.
#include "parafluid/rain/Runoff.h"
#include "parafluid/rain/GroundSurface.h"
#include "parafluid/sph/CudaBackend.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

using parafluid::HeightField;
using parafluid::rain::RainParameters;
using parafluid::rain::Runoff;
using parafluid::rain::RunoffParameters;
using parafluid::rain::triangulatedHeight;

namespace
{
/// z = f(x, y) on an n x n grid over [0, size]^2.
template<class F>
std::shared_ptr<HeightField> groundOf(double size, int n, F f)
{
  std::vector<float> z(static_cast<std::size_t>(n) * n);
  const double h = size / (n - 1);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      z[static_cast<std::size_t>(j) * n + i] = static_cast<float>(f(i * h, j * h));
    }
  }
  return std::make_shared<HeightField>(std::move(z), n, n, 0.0, 0.0, h, h, 0.0);
}

/// A cloudburst from low over the ground: ballistic drops from 0.3 m, so the SPH's steps stay long.
RainParameters cloudburst(double size, double rate)
{
  RainParameters r;
  r.bounds = { 0.0, size, 0.0, size };
  r.cells = { 4, 4 };
  r.rainfallRate = rate;
  r.dropsPerRealDrop = 2e-3;
  r.terminalVelocity = false;
  r.initialSpeed = 0.5;
  r.seed = 11;
  return r;
}

/// The Rain filter's defaults (DFSPH at the automatic CFL number, 0.2) at `spacing`, with drop
/// steps of 0.02 s.
RunoffParameters water(double spacing)
{
  RunoffParameters p;
  p.particleSpacing = spacing;
  p.rainStep = 0.02;
  return p;
}

/// The lowest clearance of any particle over the triangulated ground [m].
double lowestClearance(const Runoff& runoff, const HeightField& ground)
{
  double lowest = 1e30;
  if (const auto* sph = runoff.water())
  {
    const auto& s = sph->hostState();
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      lowest = std::min(lowest, s.z[i] - triangulatedHeight(ground, s.x[i], s.y[i]));
    }
  }
  return lowest;
}
/// A paraboloid bowl z = a r^2 (a = 1 / m) 0.8 m across (size) and a cloudburst over it from 0.6 m
/// in 3 x 3 cells: what may wait in them (under a particle each) is then under 1 % of the ~940
/// particles' volume of 25 s of it, so the basin's 1 % check holds by the bookkeeping, not by when
/// the rain stopped.
constexpr double kBowlSize = 0.8, kBowlCurvature = 1.0; // [m], [1/m]
std::shared_ptr<HeightField> bowl()
{
  return groundOf(kBowlSize, 41,
                  [](double x, double y) { return kBowlCurvature * ((x - 0.4) * (x - 0.4) + (y - 0.4) * (y - 0.4)); });
}
RainParameters bowlCloudburst()
{
  RainParameters rain = cloudburst(kBowlSize, 1700.0);
  rain.height = 0.6;
  rain.cells = { 3, 3 };
  return rain;
}
} // namespace

TEST(Runoff, BasinKeepsTheRainVolume)
{
  // It rains 25 s into the bowl, then the water settles for 5 s, with the Rain filter's defaults
  // (DFSPH, BoundaryDamping 1, the automatic CFL number). The water inserted equals the rain that
  // fell within one particle per cell. The pond's surface should be where a bowl holding that
  // volume is full: V = pi L^2 / (2 a).
  const double a = kBowlCurvature;
  auto ground = bowl();
  RainParameters rain = bowlCloudburst();
  rain.duration = 25.0;
  const double d = 0.02;
  const RunoffParameters p = water(d);
  ASSERT_EQ(p.sph.pressureSolver, parafluid::sph::PressureSolverType::DFSPH);
  Runoff runoff(rain, p, ground);
  runoff.advance(30.0);
  const double particles = static_cast<double>(runoff.particleCount()) * runoff.particleVolume();
  const double fallen = runoff.fallenVolume();
  RecordProperty("particles", std::to_string(runoff.particleCount()));
  RecordProperty("fallen_m3", std::to_string(fallen));
  RecordProperty("sph_m3", std::to_string(particles));
  ASSERT_GT(runoff.particleCount(), 500u);
  // Bookkeeping is exact; what waits in the cells is under one particle in all.
  EXPECT_NEAR(particles + runoff.waitingVolume(), fallen, 1e-9 * fallen);
  EXPECT_LT(runoff.waitingVolume(), runoff.particleVolume());
  EXPECT_NEAR(particles, fallen, 0.01 * fallen);
  // The surface: the top layer in the middle of the pond (the 90th percentile of the heights there,
  // so a drop's splash above it does not count), plus half a spacing.
  const auto& s = runoff.water()->hostState();
  std::vector<double> heights;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    if (std::hypot(s.x[i] - 0.4, s.y[i] - 0.4) < 0.1)
    {
      heights.push_back(s.z[i]);
    }
  }
  ASSERT_GT(heights.size(), 20u);
  std::sort(heights.begin(), heights.end());
  const double level = heights[heights.size() * 9 / 10] + 0.5 * d;
  const double expected = std::sqrt(2.0 * a * particles / M_PI);
  RecordProperty("level_m", std::to_string(level));
  RecordProperty("expected_level_m", std::to_string(expected));
  // Within one spacing of the level its volume gives. The bottom layers rest at rest density on
  // the ground because the mesh's wall adds to their sums (SPHParameters::meshWallDensity); without
  // it they pack onto it and the pond stood 2 d low.
  EXPECT_NEAR(level, expected, d);
  EXPECT_GT(lowestClearance(runoff, *ground), -1e-6);
}

TEST(Runoff, DeltaSPHCloudburstAtTheTerrainsEdgeKeepsRunning)
{
  // The basin's cloudburst with the Rain filter's defaults of the time (δ-SPH, BoundaryDamping 1) at
  // SPH Step's CFL number, 0.2, which the Rain filter then took too (it now takes DFSPH, and 0.1 for
  // δ-SPH). Each of the 3 x 3 cells gathers several particles' water between impacts and emits
  // them on a spiral around the impact; at the terrain's edge the spiral's points used to lie beyond the SPH's box, and
  // the solver put them back onto its side, millimetres apart: a pair held together there by its
  // tension ran away and the run blew up at 4.0 s. New particles now stay half a spacing inside.
  auto ground = bowl();
  const RainParameters rain = bowlCloudburst();
  RunoffParameters p = water(0.02);
  p.sph.cflNumber = 0.2f;
  p.sph.pressureSolver = parafluid::sph::PressureSolverType::DeltaSPH;
  Runoff runoff(rain, p, ground);
  EXPECT_NO_THROW(runoff.advance(8.0));
  ASSERT_GT(runoff.particleCount(), 250u);
  const auto& s = runoff.water()->hostState();
  float fastest = 0.0f;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    fastest = std::max(fastest, std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]));
    EXPECT_TRUE(s.x[i] > 0.0f && s.x[i] < kBowlSize && s.y[i] > 0.0f && s.y[i] < kBowlSize) << "particle " << i;
  }
  // Nothing faster than the drops arrive (free fall from 0.6 m after a 0.5 m/s start: 3.5 m/s).
  EXPECT_LT(fastest, 4.0f);
  EXPECT_GT(lowestClearance(runoff, *ground), -1e-6);
}

TEST(Runoff, WaterRunsDownATiltedPlaneAndNeverUnderIt)
{
  // A plane falling 0.3 m over 1.2 m in x. Rain on its upper third only, for 1.5 s; the water's
  // centre of mass moves downhill, and no particle is ever under the ground, over 10,000 SPH steps,
  // with the Rain filter's defaults (DFSPH) and with δ-SPH.
  const double size = 1.2;
  auto ground = groundOf(size, 25, [&](double x, double) { return 0.3 * (1.0 - x / size); });
  RainParameters rain = cloudburst(size, 3000.0);
  rain.bounds = { 0.0, 0.4, 0.0, size };
  rain.height = 0.7;
  rain.duration = 1.5;
  for (const auto solver : { parafluid::sph::PressureSolverType::DFSPH, parafluid::sph::PressureSolverType::DeltaSPH })
  {
    const bool dfsph = solver == parafluid::sph::PressureSolverType::DFSPH;
    SCOPED_TRACE(dfsph ? "DFSPH" : "delta-SPH");
    RunoffParameters p = water(0.02);
    p.sph.pressureSolver = solver;
    Runoff runoff(rain, p, ground);
    double firstX = -1.0, lastX = 0.0;
    double lowest = 1e30;
    while (runoff.sphSteps() < 10000)
    {
      runoff.advance(0.02);
      lowest = std::min(lowest, lowestClearance(runoff, *ground));
      if (runoff.particleCount() > 0)
      {
        const auto& s = runoff.water()->hostState();
        double mean = 0.0;
        for (float x : s.x)
        {
          mean += x;
        }
        mean /= static_cast<double>(s.size());
        if (firstX < 0.0 && runoff.time() > 0.5)
        {
          firstX = mean;
        }
        lastX = mean;
      }
    }
    const std::string prefix = dfsph ? "dfsph_" : "delta_sph_";
    RecordProperty(prefix + "time_s", std::to_string(runoff.time()));
    RecordProperty(prefix + "first_x", std::to_string(firstX));
    RecordProperty(prefix + "last_x", std::to_string(lastX));
    EXPECT_GT(runoff.particleCount(), 60u);
    EXPECT_GT(lowest, -1e-6) << "a particle got under the terrain";
    EXPECT_GT(lastX, firstX + 0.2) << "the water should run down the slope (towards +x)";
  }
}

TEST(Runoff, DeltaSPHRunoffOnTheGpuFollowsTheCpu)
{
  // The tilted plane's rain with δ-SPH on both backends for 1 s: the same particles arrive (the
  // drops do not depend on the SPH), none gets under the terrain on the GPU, and the water's
  // centre is where the CPU's is, within a spacing.
  std::string why;
  if (!parafluid::sph::cudaBackendUsable(&why))
  {
    GTEST_SKIP() << "no GPU for the CUDA backend: " << why;
  }
  const double size = 1.2;
  auto ground = groundOf(size, 25, [&](double x, double) { return 0.3 * (1.0 - x / size); });
  RainParameters rain = cloudburst(size, 3000.0);
  rain.bounds = { 0.0, 0.4, 0.0, size };
  rain.height = 0.7;
  RunoffParameters p = water(0.02);
  p.sph.pressureSolver = parafluid::sph::PressureSolverType::DeltaSPH;
  p.backend = parafluid::sph::Backend::CPU;
  Runoff cpu(rain, p, ground);
  p.backend = parafluid::sph::Backend::CUDA;
  Runoff gpu(rain, p, ground);
  double lowest = 1e30;
  auto centre = [](const Runoff& r)
  {
    const auto& s = r.water()->hostState();
    double x = 0.0, z = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      x += s.x[i];
      z += s.z[i];
    }
    return std::array<double, 2>{ x / static_cast<double>(s.size()), z / static_cast<double>(s.size()) };
  };
  for (int frame = 0; frame < 50; ++frame)
  {
    cpu.advance(0.02);
    gpu.advance(0.02);
    lowest = std::min(lowest, lowestClearance(gpu, *ground));
  }
  ASSERT_GT(gpu.particleCount(), 30u);
  ASSERT_STREQ(gpu.water()->backendName(), "CUDA");
  EXPECT_EQ(gpu.particleCount(), cpu.particleCount());
  EXPECT_GT(lowest, -1e-6) << "a particle got under the terrain on the GPU";
  const auto c = centre(cpu), g = centre(gpu);
  EXPECT_NEAR(g[0], c[0], 0.02);
  EXPECT_NEAR(g[1], c[1], 0.02);
  std::cout << gpu.particleCount() << " particles; centre x, z " << c[0] << ", " << c[1] << " m on the CPU, " << g[0]
            << ", " << g[1] << " m on the GPU\n";
}

TEST(Runoff, InfiltrationTakesTheRainUntilTheRainOutpacesIt)
{
  const double size = 0.6;
  auto ground = groundOf(size, 13, [](double, double) { return 0.0; });
  RainParameters rain = cloudburst(size, 2000.0);
  rain.height = 0.4;
  RunoffParameters p = water(0.02);
  p.infiltration = 3000.0; // faster than it rains: nothing runs off
  {
    Runoff runoff(rain, p, ground);
    runoff.advance(5.0);
    EXPECT_EQ(runoff.particleCount(), 0u);
    EXPECT_GT(runoff.fallenVolume(), 10 * runoff.particleVolume());
    EXPECT_NEAR(runoff.infiltratedVolume() + runoff.waitingVolume(), runoff.fallenVolume(), 1e-9);
  }
  p.infiltration = 1000.0; // half the rain soaks in, half becomes water
  Runoff runoff(rain, p, ground);
  runoff.advance(5.0);
  const double inWater = static_cast<double>(runoff.particleCount()) * runoff.particleVolume();
  EXPECT_GT(runoff.particleCount(), 0u);
  EXPECT_NEAR(inWater + runoff.infiltratedVolume() + runoff.waitingVolume(), runoff.fallenVolume(),
              1e-9 * runoff.fallenVolume());
  EXPECT_NEAR(runoff.infiltratedVolume() / runoff.fallenVolume(), 0.5, 0.1);
}

TEST(Runoff, RainArrivesAtAnyRateAndAnyCells)
{
  // A new user's first rain: a flat metre square, rain from 2 m at its terminal speed, 60 s. Each
  // cell gathers far less than a particle at these rates (64 x 64 cells at 1 mm/h: 2e-9 m^3 each a
  // second), yet the water must be the rain that fell within one particle's volume, each cell's
  // account within one particle, and each new particle where the rain fell (on the left half).
  struct Case
  {
    double rate; // [mm/h]
    int cells;
    double spacing; // [m]
  };
  auto ground = groundOf(1.0, 11, [](double, double) { return 0.0; });
  for (const Case c : { Case{ 1.0, 64, 0.01 }, Case{ 1.0, 8, 0.02 }, Case{ 10.0, 64, 0.025 }, Case{ 10.0, 16, 0.04 },
                        Case{ 100.0, 64, 0.05 }, Case{ 100.0, 8, 0.025 } })
  {
    SCOPED_TRACE(std::to_string(c.rate) + " mm/h, " + std::to_string(c.cells) + " cells, spacing " +
                 std::to_string(c.spacing));
    RainParameters rain;
    rain.bounds = { 0.0, 0.5, 0.0, 1.0 };
    rain.height = 2.0;
    rain.cells = { c.cells, c.cells };
    rain.rainfallRate = c.rate;
    rain.seed = 5;
    RunoffParameters p;
    p.particleSpacing = c.spacing;
    p.sph.threads = 1; // a few dozen particles: one thread, and no waiting on a busy machine's other
    Runoff runoff(rain, p, ground);
    std::size_t known = 0;
    for (int step = 0; step < 3600; ++step)
    {
      runoff.advance(p.rainStep);
      if (const auto* sph = runoff.water())
      {
        const auto& s = sph->hostState();
        for (std::size_t i = 0; i < s.size(); ++i)
        {
          if (static_cast<std::size_t>(s.id[i]) >= known)
          {
            EXPECT_LT(s.x[i], 0.5 + 2 * c.spacing) << "a particle made in this step, far from the rain";
          }
        }
        known = s.size();
      }
    }
    const double v = runoff.particleVolume(), fallen = runoff.fallenVolume();
    const double water = static_cast<double>(runoff.particleCount()) * v;
    // It rained what the rate says (60 s over half a square metre), and all of it but less than a
    // particle is water.
    const double expected = c.rate * 1e-3 / 3600.0 * 0.5 * 60.0;
    EXPECT_NEAR(fallen, expected, 0.2 * expected);
    EXPECT_NEAR(water + runoff.waitingVolume(), fallen, 1e-9 * fallen);
    EXPECT_GE(runoff.waitingVolume(), -1e-12);
    EXPECT_LT(runoff.waitingVolume(), v);
    EXPECT_GT(runoff.particleCount(), 0u);
    for (double account : runoff.cellAccounts())
    {
      EXPECT_GT(account, -v);
      EXPECT_LT(account, v);
    }
  }
}

TEST(Runoff, AutomaticCFLNumberFollowsTheSolver)
{
  // CFLNumber 0 (the default) is SPH Step's 0.2 for DFSPH and half that for the weakly compressible
  // solvers; a number given is kept.
  auto ground = groundOf(1.0, 5, [](double, double) { return 0.0; });
  const RainParameters rain = cloudburst(1.0, 10.0);
  RunoffParameters p = water(0.05);
  EXPECT_EQ(p.sph.cflNumber, 0.0f);
  EXPECT_FLOAT_EQ(Runoff(rain, p, ground).sphParameters().cflNumber, 0.2f);
  for (const auto solver : { parafluid::sph::PressureSolverType::DeltaSPH, parafluid::sph::PressureSolverType::WCSPH })
  {
    p.sph.pressureSolver = solver;
    EXPECT_FLOAT_EQ(Runoff(rain, p, ground).sphParameters().cflNumber, 0.1f);
  }
  p.sph.cflNumber = 0.35f;
  EXPECT_FLOAT_EQ(Runoff(rain, p, ground).sphParameters().cflNumber, 0.35f);
}

TEST(Runoff, BadParametersAreRefusedByName)
{
  auto ground = groundOf(1.0, 5, [](double, double) { return 0.0; });
  RainParameters rain = cloudburst(1.0, 10.0);
  RunoffParameters p = water(0.0);
  EXPECT_THROW(Runoff(rain, p, ground), std::invalid_argument);
  p = water(0.05);
  p.sphEvery = 0;
  try
  {
    Runoff runoff(rain, p, ground);
    FAIL() << "SPHEvery 0 accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("SPHEvery"), std::string::npos);
  }
}
