// The Gerstner ocean on the CPU: what the Gerstner Ocean source spends per frame. 1M vertices
// (a 1000 x 1000 grid) and 8 waves (the Storm preset), deep water and over a sloping beach
// (phase fields sampled per wave), 1 and 2 OpenMP threads. Target: 0.2 s a frame in deep water.
#include "parafluid/ocean/Bathymetry.h"
#include "parafluid/ocean/GerstnerOcean.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

namespace
{
using namespace parafluid::ocean;

struct Grid
{
  std::vector<float> x, y;
  explicit Grid(int n, float size)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        x.push_back(size * i / (n - 1));
        y.push_back(size * j / (n - 1));
      }
    }
  }
};

std::shared_ptr<Bathymetry> beach(float size)
{
  const int n = 257;
  std::vector<float> elevation;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      elevation.push_back(-20.0f + 21.0f * i / (n - 1)); // 20 m deep to 1 m of land across the patch
    }
  }
  return std::make_shared<Bathymetry>(elevation, n, n, 0.0, 0.0, size / (n - 1), size / (n - 1), 0.0);
}

void BM_OceanFrame(benchmark::State& state)
{
  const int threads = static_cast<int>(state.range(0));
  const bool overFloor = state.range(1) != 0;
  const float size = 400.0f;
  const Grid grid(1000, size);
  OceanParameters p;
  p.waves = seaStatePreset(SeaState::Storm, 30.0);
  p.windDirection = 30.0;
  p.windLean = 0.2;
  const double region[4] = { 0.0, size, 0.0, size };
  const GerstnerOcean ocean(p, overFloor ? beach(size) : nullptr, region);
  const std::size_t n = grid.x.size();
  std::vector<float> displacement(3 * n), normal(3 * n), jacobian(n), foam(n), depth(n);
  double time = 0.0;
  for (auto _ : state)
  {
    ocean.evaluate(grid.x.data(), grid.y.data(), n, time, displacement.data(), normal.data(), jacobian.data(),
                   foam.data(), depth.data(), threads);
    benchmark::DoNotOptimize(displacement.data());
    time += 1.0 / 30.0;
  }
  state.counters["vertices"] = static_cast<double>(n);
  state.counters["vertices/s"] =
    benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_OceanFrame)
  ->ArgNames({ "threads", "bathymetry" })
  ->Args({ 1, 0 })
  ->Args({ 2, 0 })
  ->Args({ 1, 1 })
  ->Args({ 2, 1 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
} // namespace

BENCHMARK_MAIN();
