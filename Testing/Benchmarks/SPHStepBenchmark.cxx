// Time of one WCSPH step on a dam break (water block 1 x 2 x 1 of its height against a wall of a
// tank 4 wide), 10k and 100k particles, 1 and 2 threads. Reports particle-steps per second, the
// neighbour count (the work per particle) and the solver's bytes per particle.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHSolver.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace
{
using namespace parafluid;
using namespace parafluid;
using namespace parafluid::sph;

SPHSolver damBreak(std::size_t particles, int threads, PressureSolverType solverKind = PressureSolverType::WCSPH,
                   float surfaceTension = 0.0f, bool adaptive = false)
{
  // Block of a x 2a x a (x, z, y) layers of spacing d: particles = 2 a^3 / d^3.
  const double a = 0.5;
  const double d = a * std::cbrt(2.0 / static_cast<double>(particles));
  SPHParameters p;
  p.pressureSolver = solverKind;
  p.surfaceTension = surfaceTension;
  p.adaptiveTimeStep = adaptive;
  p.smoothingLength = static_cast<float>(2.0 * d);
  p.timeStep = static_cast<float>(0.2 * p.smoothingLength / 31.6); // CFL 0.2 at c = sqrt(k)
  p.particleMass = latticeParticleMass(static_cast<float>(d), p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0.f, static_cast<float>(4 * a), 0.f, static_cast<float>(a), 0.f, static_cast<float>(3 * a) };
  p.threads = threads;
  auto lattice = fillBoxWithLattice({ 0, a, 0, a, 0, 2 * a }, d);
  SPHSolver solver(p, ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z)));
  for (int k = 0; k < 20; ++k) // leave the perfect lattice, as in a running simulation
  {
    solver.step();
  }
  return solver;
}

double meanNeighbours(const SPHSolver& solver)
{
  // mass-weighted: density / (m W(0)) ~ neighbours inside h weighted by the kernel; report the
  // plain count instead by sampling.
  const auto& s = solver.state();
  const float h2 = solver.parameters().smoothingLength * solver.parameters().smoothingLength;
  std::size_t count = 0, samples = 0;
  for (std::size_t i = 0; i < s.size(); i += 97)
  {
    for (std::size_t j = 0; j < s.size(); ++j)
    {
      const float dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
      count += dx * dx + dy * dy + dz * dz < h2;
    }
    ++samples;
  }
  return static_cast<double>(count) / static_cast<double>(samples);
}

void BM_SPHStep(benchmark::State& state)
{
  SPHSolver solver = damBreak(static_cast<std::size_t>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state)
  {
    solver.step();
  }
  const auto n = static_cast<double>(solver.state().size());
  state.counters["particles"] = n;
  state.counters["particle_steps_per_s"] =
    benchmark::Counter(n * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["neighbours"] = meanNeighbours(solver);
  state.counters["bytes_per_particle"] = solver.bytesPerParticle();
}
BENCHMARK(BM_SPHStep)
  ->ArgNames({ "particles", "threads" })
  ->Args({ 10'000, 1 })
  ->Args({ 10'000, 2 })
  ->Args({ 100'000, 1 })
  ->Args({ 100'000, 2 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(2.0);

/// The colour-field pass costs this much when on; with sigma = 0 it is not compiled into the loop.
void BM_SPHStepWithSurfaceTension(benchmark::State& state)
{
  SPHSolver solver =
    damBreak(static_cast<std::size_t>(state.range(0)), 2, PressureSolverType::WCSPH, state.range(1) ? 0.0728f : 0.0f);
  for (auto _ : state)
  {
    solver.step();
  }
  state.counters["particle_steps_per_s"] = benchmark::Counter(
    static_cast<double>(solver.state().size()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SPHStepWithSurfaceTension)
  ->ArgNames({ "particles", "tension" })
  ->Args({ 100'000, 0 })
  ->Args({ 100'000, 1 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(2.0);

/// Simulated time per wall-clock time: both solvers with adaptive steps advance the same 0.01 s
/// output interval of a dam break (DFSPH takes fewer, dearer steps).
void BM_AdvanceOutputInterval(benchmark::State& state)
{
  const auto kind = state.range(1) ? PressureSolverType::DFSPH : PressureSolverType::WCSPH;
  SPHSolver solver = damBreak(static_cast<std::size_t>(state.range(0)), 2, kind, 0.0f, true);
  std::int64_t steps = 0;
  for (auto _ : state)
  {
    steps += solver.advance(0.01);
  }
  state.counters["steps_per_interval"] = static_cast<double>(steps) / static_cast<double>(state.iterations());
  state.counters["simulated_s_per_s"] =
    benchmark::Counter(0.01 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["mean_density_error"] = solver.lastStep().meanCompression;
}
BENCHMARK(BM_AdvanceOutputInterval)
  ->ArgNames({ "particles", "dfsph" })
  ->Args({ 50'000, 0 })
  ->Args({ 50'000, 1 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Iterations(5);
} // namespace

BENCHMARK_MAIN();
