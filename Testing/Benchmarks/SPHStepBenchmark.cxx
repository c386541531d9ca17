// Time of one SPH step on a dam break (water block 1 x 2 x 1 of its height against a wall of a
// tank 4 wide), 10k and 100k particles, 1 and 2 threads: Müller's WCSPH, and δ-SPH at h = 2 and 3
// spacings. Reports particle-steps per second, the neighbour count (the work per particle) and
// the solver's bytes per particle; then the implicit viscosity's two conjugate-gradient solvers,
// and simulated seconds per second of the three solvers with adaptive steps.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/SPHSolver.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace
{
using namespace parafluid;
using namespace parafluid;
using namespace parafluid::sph;

SPHSolver damBreak(std::size_t particles, int threads, PressureSolverType solverKind = PressureSolverType::WCSPH,
                   float surfaceTension = 0.0f, bool adaptive = false, double kernelRatio = 2.0,
                   float kinematicViscosity = 1e-6f, ViscositySolver cg = ViscositySolver::HandWrittenCG,
                   bool particleShifting = false, SurfaceTensionModel tensionModel = SurfaceTensionModel::Akinci)
{
  // Block of a x 2a x a (x, z, y) layers of spacing d: particles = 2 a^3 / d^3.
  const double a = 0.5;
  const double d = a * std::cbrt(2.0 / static_cast<double>(particles));
  SPHParameters p;
  p.pressureSolver = solverKind;
  p.surfaceTension = surfaceTension;
  p.surfaceTensionModel = tensionModel;
  p.adaptiveTimeStep = adaptive;
  p.smoothingLength = static_cast<float>(kernelRatio * d);
  // Müller's seed method with its paper's viscosity; the others at water's.
  p.viscosity = solverKind == PressureSolverType::WCSPH ? 3.5f : 0.0f;
  p.kinematicViscosity = kinematicViscosity;
  p.viscositySolver = cg;
  p.particleShifting = particleShifting;
  // Fixed steps at CFL 0.2 of each scheme's sound speed (sqrt(k) = 31.6 m/s for Müller's, c0 =
  // 10 sqrt(2 g 1 m) = 44 m/s for δ-SPH).
  p.timeStep = static_cast<float>(0.2 * p.smoothingLength / (solverKind == PressureSolverType::DeltaSPH ? 44.3 : 31.6));
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
  // solver 0: Müller's WCSPH; 2: δ-SPH at h = 2 spacings; 3: δ-SPH at its default kDeltaSPHSupport; 4: the same with
  // particle shifting (SPH Step's ParticleShifting).
  const bool delta = state.range(2) >= 2;
  SPHSolver solver =
    damBreak(static_cast<std::size_t>(state.range(0)), static_cast<int>(state.range(1)),
             delta ? PressureSolverType::DeltaSPH : PressureSolverType::WCSPH, 0.0f, false,
             state.range(2) >= 3 ? kDeltaSPHSupport : 2.0, 1e-6f, ViscositySolver::HandWrittenCG, state.range(2) == 4);
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
  ->ArgNames({ "particles", "threads", "solver" })
  ->Args({ 10'000, 1, 0 })
  ->Args({ 10'000, 2, 0 })
  ->Args({ 100'000, 1, 0 })
  ->Args({ 100'000, 2, 0 })
  ->Args({ 100'000, 2, 2 })
  ->Args({ 100'000, 2, 3 })
  ->Args({ 100'000, 2, 4 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(2.0);

/// What surface tension costs, on δ-SPH's step at its default support (kDeltaSPHSupport): 0 off, 1 Akinci's two
/// terms (the default model), 2 Akinci's cohesion alone (Müller's colour field is WCSPH's and
/// DFSPH's, fused into their force pass).
void BM_SPHStepWithSurfaceTension(benchmark::State& state)
{
  const SurfaceTensionModel models[] = { SurfaceTensionModel::Akinci, SurfaceTensionModel::Akinci,
                                         SurfaceTensionModel::AkinciCohesion };
  SPHSolver solver =
    damBreak(static_cast<std::size_t>(state.range(0)), 2, PressureSolverType::DeltaSPH, state.range(1) ? 0.0728f : 0.0f,
             false, kDeltaSPHSupport, 1e-6f, ViscositySolver::HandWrittenCG, false, models[state.range(1)]);
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
  ->Args({ 100'000, 2 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(2.0);

/// DFSPH's implicit viscosity step, the hand-written conjugate gradients against Eigen's, at a
/// viscosity that needs iterations (nu = 1e-2 m^2/s, honey) and at water's.
void BM_ImplicitViscosity(benchmark::State& state)
{
  const auto cg = state.range(1) ? ViscositySolver::EigenCG : ViscositySolver::HandWrittenCG;
  const float nu = state.range(2) ? 1e-2f : 1e-6f;
  SPHSolver solver =
    damBreak(static_cast<std::size_t>(state.range(0)), 2, PressureSolverType::DFSPH, 0.0f, false, 2.0, nu, cg);
  long long iterations = 0;
  for (auto _ : state)
  {
    solver.step();
    iterations += solver.lastStep().viscosityIterations;
  }
  state.counters["cg_iterations"] = static_cast<double>(iterations) / static_cast<double>(state.iterations());
  state.counters["particle_steps_per_s"] = benchmark::Counter(
    static_cast<double>(solver.state().size()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ImplicitViscosity)
  ->ArgNames({ "particles", "eigen", "honey" })
  ->Args({ 100'000, 0, 1 })
  ->Args({ 100'000, 1, 1 })
  ->Args({ 100'000, 0, 0 })
  ->Args({ 100'000, 1, 0 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(2.0);

/// Simulated time per wall-clock time: the solvers with adaptive steps advance the same 0.01 s
/// output interval of a dam break (DFSPH takes fewer, dearer steps).
void BM_AdvanceOutputInterval(benchmark::State& state)
{
  const auto kind = static_cast<PressureSolverType>(state.range(1));
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
  ->ArgNames({ "particles", "solver" })
  ->Args({ 50'000, 0 })
  ->Args({ 50'000, 1 })
  ->Args({ 50'000, 2 })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Iterations(5);
} // namespace

BENCHMARK_MAIN();
