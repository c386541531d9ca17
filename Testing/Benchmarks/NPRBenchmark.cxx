// Illustration filters on a 2-core budget: flow lines through a rigid vortex sampled on a
// particle slab (run time against the largest radial deviation from the true circles, RK2 and RK4,
// per number of points per line), and foam scoring on the dam-break block with splash.
#include "SurfaceScenes.h"
#include "parafluid/npr/FlowLines.h"
#include "parafluid/npr/FoamClassifier.h"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <vector>

namespace
{
using namespace parafluid::npr;

// A slab 1 m across and 5 particles thick (d = 5 mm: about 200k particles) turning at 2 rad/s.
void BM_FlowLinesVortex(benchmark::State& state)
{
  const double d = 0.005, omega = 2.0;
  std::vector<float> xyz, velocity;
  for (int k = 0; k < 5; ++k)
    for (int j = -100; j <= 100; ++j)
      for (int i = -100; i <= 100; ++i)
        if ((i * i + j * j) * d * d <= 0.25)
        {
          xyz.insert(xyz.end(), { float(i * d), float(j * d), float(k * d) });
          velocity.insert(velocity.end(), { float(-omega * j * d), float(omega * i * d), 0.0f });
        }
  omp_set_num_threads(2);
  FlowLineParameters p;
  p.kernelRadius = 2 * d;
  p.seedStride = 50;
  p.pointsPerLine = static_cast<int>(state.range(0));
  p.lineDuration = 3.14159265358979 / (2 * omega); // a quarter turn
  p.integrator = state.range(1) == 4 ? FlowIntegrator::RK4 : FlowIntegrator::RK2;
  p.maxLines = 1000000;
  FlowLineSet lines;
  for (auto _ : state)
  {
    lines = traceFlowLines(xyz.data(), velocity.data(), xyz.size() / 3, p);
  }
  double worst = 0.0;
  for (std::size_t l = 0; l < lines.lineCount(); ++l)
  {
    const float* s = &lines.points[3 * lines.offsets[l]];
    const double r0 = std::hypot(s[0], s[1]);
    if (r0 < 0.05 || r0 > 0.45)
    {
      continue; // the centre (r0 -> 0) and the rim, where the kernel reaches past the slab
    }
    for (std::uint32_t k = lines.offsets[l]; k < lines.offsets[l + 1]; ++k)
    {
      worst = std::max(worst, std::abs(std::hypot(lines.points[3 * k], lines.points[3 * k + 1]) / r0 - 1.0));
    }
  }
  state.counters["particles"] = static_cast<double>(xyz.size() / 3);
  state.counters["lines"] = static_cast<double>(lines.lineCount());
  state.counters["worst_radial_deviation_percent"] = 100.0 * worst;
}
BENCHMARK(BM_FlowLinesVortex)
  ->ArgsProduct({ { 8, 16, 32 }, { 2, 4 } })
  ->ArgNames({ "points", "rk" })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

void BM_FoamScores(benchmark::State& state)
{
  double d = 0.0;
  const std::vector<float> xyz = parafluid::benchmarks::damBreakWithSplash(static_cast<std::size_t>(state.range(0)), d);
  omp_set_num_threads(2);
  FoamParameters p;
  p.kernelRadius = 3 * d;
  p.particleVolume = d * d * d;
  std::size_t candidates = 0;
  for (auto _ : state)
  {
    const FoamScores scores = scoreFoam(xyz.data(), xyz.size() / 3, p);
    candidates = 0;
    for (std::uint8_t c : scores.candidate)
    {
      candidates += c;
    }
  }
  state.counters["particles"] = static_cast<double>(xyz.size() / 3);
  state.counters["candidates"] = static_cast<double>(candidates);
}
BENCHMARK(BM_FoamScores)->Arg(100000)->ArgName("particles")->Unit(benchmark::kMillisecond)->UseRealTime();
} // namespace

BENCHMARK_MAIN();
