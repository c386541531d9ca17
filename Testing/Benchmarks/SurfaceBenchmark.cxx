// Surface extraction on the scenes: a dam-break block (a x a x 2a) with 5 % of its
// particles as splash scattered above it, 100k and 1M particles, cell 0.5 d; the jittered ball
// (R = 25 d) for time against error; and the carpet against marching cubes on one shallow flow.
#include "SurfaceScenes.h"
#include "parafluid/surface/CarpetSurface.h"
#include "parafluid/surface/ParticleSurface.h"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using namespace parafluid::surface;
using parafluid::benchmarks::damBreakWithSplash;
using parafluid::benchmarks::jitteredBall;
using parafluid::benchmarks::meanRadialError;

void BM_ParticleSurface(benchmark::State& state)
{
  double d = 0.0;
  const std::vector<float> xyz = damBreakWithSplash(static_cast<std::size_t>(state.range(0)), d);
  const std::size_t n = xyz.size() / 3;
  omp_set_num_threads(static_cast<int>(state.range(1)));
  ParticleSurfaceParameters p;
  p.particleSpacing = d;
  p.cellSize = 0.5;
  p.smoothingIterations = 10;
  ParticleSurface surface;
  std::size_t triangles = 0;
  for (auto _ : state)
  {
    SurfaceMesh mesh = surface.extract(xyz.data(), n, p);
    triangles = mesh.triangleCount();
    benchmark::DoNotOptimize(mesh.points.data());
  }
  const auto& stats = surface.statistics();
  state.counters["particles"] = static_cast<double>(n);
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["field_s"] = stats.fieldSeconds;
  state.counters["mesh_s"] = stats.meshSeconds;
  state.counters["smooth_s"] = stats.smoothSeconds;
  state.counters["working_bytes_per_particle"] = static_cast<double>(stats.workingBytes) / static_cast<double>(n);
  state.counters["blocks"] = static_cast<double>(stats.allocatedBlocks);
  state.counters["surface_blocks"] = static_cast<double>(stats.surfaceBlocks);
}
BENCHMARK(BM_ParticleSurface)
  ->ArgsProduct({ { 100000, 1000000 }, { 1, 2 } })
  ->ArgNames({ "particles", "threads" })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

// The accuracy scene: lattice points within R = 25 d, jittered by up to 0.1 d per axis;
// error = mean |r - R| of the vertices, in d. Cell size (in d) = range(0) / 100.
void BM_BallAccuracy(benchmark::State& state)
{
  const double d = 0.01, radius = 25 * d;
  const std::vector<float> xyz = jitteredBall(d, radius);
  omp_set_num_threads(2);
  ParticleSurfaceParameters p;
  p.particleSpacing = d;
  p.cellSize = state.range(0) / 100.0;
  p.smoothingIterations = static_cast<int>(state.range(1));
  ParticleSurface surface;
  SurfaceMesh mesh;
  for (auto _ : state)
  {
    mesh = surface.extract(xyz.data(), xyz.size() / 3, p);
  }
  state.counters["particles"] = static_cast<double>(xyz.size() / 3);
  state.counters["mean_error_d"] = meanRadialError(mesh.points.data(), mesh.vertexCount(), radius) / d;
  state.counters["grid_error_d"] = surface.meanLevelSetDistance(mesh) / d;
  state.counters["vertices"] = static_cast<double>(mesh.vertexCount());
}
BENCHMARK(BM_BallAccuracy)
  ->ArgsProduct({ { 100, 50, 25 }, { 0, 10 } })
  ->ArgNames({ "cell_percent_d", "smoothing" })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

// A shallow flow: three layers of particles over 1 m x 1 m with a travelling bump, d = 5 mm.
std::vector<float> shallowFlow(double d)
{
  std::vector<float> xyz;
  const int n = static_cast<int>(std::lround(1.0 / d));
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = (i + 0.5) * d, y = (j + 0.5) * d;
      const double bump = 0.01 * std::exp(-((x - 0.5) * (x - 0.5) + (y - 0.3) * (y - 0.3)) / 0.02);
      for (int k = 0; k < 3; ++k)
      {
        xyz.insert(xyz.end(), { float(x), float(y), float((k + 0.5) * d + bump) });
      }
    }
  }
  return xyz;
}

void BM_ShallowFlowCarpet(benchmark::State& state)
{
  const double d = 0.005;
  const std::vector<float> xyz = shallowFlow(d);
  const int resolution = static_cast<int>(std::lround(1.0 / d));
  CarpetSurface carpet;
  carpet.setGrid(0.0, 0.0, 1.0, 1.0, resolution,
                 std::vector<float>(static_cast<std::size_t>(resolution) * resolution, 0.0f));
  std::size_t triangles = 0;
  for (auto _ : state)
  {
    carpet.reset();
    carpet.advance(xyz.data(), xyz.size() / 3, 0.0, 9.81, 0.001);
    triangles = carpet.mesh().triangleCount();
  }
  state.counters["particles"] = static_cast<double>(xyz.size() / 3);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_ShallowFlowCarpet)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShallowFlowMarchingCubes(benchmark::State& state)
{
  const double d = 0.005;
  const std::vector<float> xyz = shallowFlow(d);
  omp_set_num_threads(2);
  ParticleSurfaceParameters p;
  p.particleSpacing = d;
  p.smoothingIterations = 10;
  ParticleSurface surface;
  std::size_t triangles = 0;
  for (auto _ : state)
  {
    triangles = surface.extract(xyz.data(), xyz.size() / 3, p).triangleCount();
  }
  state.counters["particles"] = static_cast<double>(xyz.size() / 3);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_ShallowFlowMarchingCubes)->Unit(benchmark::kMillisecond)->UseRealTime();
} // namespace

BENCHMARK_MAIN();
