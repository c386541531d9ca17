// Terrain on the CPU, 1 and 2 OpenMP threads (argument: threads):
//  - fBm of 8 octaves of Perlin noise on a 1024^2 grid (target >= 50 M samples/s on 2 cores),
//    the same domain-warped (target <= 3x the time), ridged, and diamond-square on 1025^2;
//  - droplet erosion of a 1024^2 terrain by 200k drops (target <= 2 s on 2 cores);
//  - one virtual-pipe step on 1024^2 (target <= 20 ms on 2 cores).
// samples/s is items_per_second. The FastNoise Lite peer is fastnoise_peer.sh.
#include "parafluid/terrain/DiamondSquare.h"
#include "parafluid/terrain/DropletErosion.h"
#include "parafluid/terrain/PipeErosion.h"
#include "parafluid/terrain/TerrainGenerator.h"

#include <benchmark/benchmark.h>
#include <omp.h>

namespace
{
using namespace parafluid::terrain;

ElevationGrid grid1024()
{
  ElevationGrid g;
  g.nx = g.ny = 1024;
  g.dx = g.dy = 1.0;
  return g;
}

/// A hilly 1024^2 terrain to erode.
ElevationGrid hills1024()
{
  TerrainSettings t;
  t.featureSize = 600.0;
  t.heightScale = 120.0;
  ElevationGrid g = grid1024();
  generateTerrain(t, g);
  return g;
}

void runTerrain(benchmark::State& state, const TerrainSettings& s)
{
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ElevationGrid g = grid1024();
  for (auto _ : state)
  {
    generateTerrain(s, g);
    benchmark::DoNotOptimize(g.elevation.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(g.size()));
}

void FBm8Octaves(benchmark::State& state)
{
  TerrainSettings s;
  s.featureSize = 512.0;
  runTerrain(state, s);
}

void FBm8OctavesWarped(benchmark::State& state)
{
  TerrainSettings s;
  s.featureSize = 512.0;
  s.warpStrength = 100.0;
  s.warpScale = 300.0;
  runTerrain(state, s);
}

void Ridged8Octaves(benchmark::State& state)
{
  TerrainSettings s;
  s.featureSize = 512.0;
  s.fractal.type = FractalType::Ridged;
  runTerrain(state, s);
}

void DiamondSquare1025(benchmark::State& state)
{
  omp_set_num_threads(static_cast<int>(state.range(0)));
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(diamondSquare(10, 0.8, 1).data());
  }
  state.SetItemsProcessed(state.iterations() * 1025LL * 1025LL);
}

void DropletErosion200k(benchmark::State& state)
{
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const ElevationGrid base = hills1024();
  DropletSettings s;
  s.drops = 200000;
  for (auto _ : state)
  {
    state.PauseTiming();
    ElevationGrid g = base;
    ErosionMaps maps;
    state.ResumeTiming();
    erodeWithDroplets(s, g, maps);
    benchmark::DoNotOptimize(g.elevation.data());
  }
  state.SetItemsProcessed(state.iterations() * s.drops);
}

void PipeStep1024(benchmark::State& state)
{
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const ElevationGrid g = hills1024();
  PipeErosion erosion(g, PipeSettings{});
  for (int k = 0; k < 20; ++k)
  {
    erosion.step(); // wet the terrain first
  }
  for (auto _ : state)
  {
    erosion.step();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(g.size()));
}
} // namespace

BENCHMARK(FBm8Octaves)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(FBm8OctavesWarped)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Ridged8Octaves)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DiamondSquare1025)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DropletErosion200k)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(PipeStep1024)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
