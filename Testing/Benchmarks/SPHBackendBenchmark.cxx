// Steps per second and particle-steps per second of SPH Step's backends (CPU, CUDA) against the
// particle count, on SPHERIC Test 2 (Kleefsman et al. 2005): the MARIN tank, its water column
// against the far wall and its box obstacle on the floor as a boundary mesh.
// Usage: ParaFluidSPHBackendBenchmark [spacing [m] ...] (default 0.03 0.015 0.008 0.006); each
// backend runs `steps` adaptive steps after a warm-up of 5; CPU rows stop above 2 M particles.
#include "ClosedBoxMesh.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/CudaBackend.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/Simulation.h"
#include "parafluid/sph/SolverRegistry.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

using namespace parafluid;
using namespace parafluid::sph;

namespace
{
struct Row
{
  std::size_t particles;
  double stepsPerSecond, bytesPerParticle, simulatedSecondsPerHour;
};

/// The obstacle: 0.161 x 0.403 x 0.161 m at x = 0.6635 to 0.8245 m, centred across the tank, its
/// foot a centimetre under the floor (so its bottom face lies outside the water's box).
std::shared_ptr<const TriangleBoundary> obstacle()
{
  const float lo[3] = { 0.6635f, 0.2985f, -0.01f }, hi[3] = { 0.8245f, 0.7015f, 0.161f };
  std::vector<float> points;
  std::vector<std::uint32_t> triangles;
  testing::appendClosedBox(points, triangles, lo, hi);
  return std::make_shared<TriangleBoundary>(std::move(points), std::move(triangles));
}

Row run(PressureSolverType solver, double spacing, Backend backend, int steps)
{
  SPHParameters p;
  p.pressureSolver = solver;
  p.smoothingLength = defaultSmoothingLength(solverEntry(p.pressureSolver), spacing, 0.0);
  p.particleMass = latticeParticleMass(spacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, 3.22f, 0, 1.0f, 0, 1.0f };
  auto lattice = fillBoxWithLattice({ 3.22 - 1.228, 3.22, 0, 1.0, 0, 0.55 }, spacing);
  auto sim = makeSimulation(p, ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z)),
                            obstacle(), backend);
  const double dt = sim->proposedTimeStep();
  for (int k = 0; k < 5; ++k)
  {
    sim->advance(dt);
  }
  const double simulatedBefore = sim->time();
  const std::int64_t before = sim->stepCount();
  const auto start = std::chrono::steady_clock::now();
  while (sim->stepCount() - before < steps)
  {
    sim->advance(sim->proposedTimeStep());
  }
  sim->hostState(); // the GPU's work is done once its state is on the host
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double taken = static_cast<double>(sim->stepCount() - before);
  return { sim->particleCount(), taken / seconds, sim->bytesPerParticle(),
           (sim->time() - simulatedBefore) / seconds * 3600.0 };
}
} // namespace

int main(int argc, char** argv)
{
  std::vector<double> spacings;
  std::vector<PressureSolverType> solvers;
  for (int a = 1; a < argc; ++a)
  {
    const std::string argument = argv[a];
    if (argument.rfind("--solver=", 0) == 0)
    {
      const SolverEntry* entry = findSolver(argument.substr(9));
      if (!entry)
      {
        std::fprintf(stderr, "unknown solver %s (DeltaSPH, WCSPH, DFSPH)\n", argument.c_str());
        return 2;
      }
      solvers.push_back(entry->type);
      continue;
    }
    spacings.push_back(std::atof(argv[a]));
  }
  if (solvers.empty())
  {
    solvers = { PressureSolverType::DeltaSPH };
  }
  if (spacings.empty())
  {
    spacings = { 0.03, 0.015, 0.008, 0.006 };
  }
  std::string why;
  const bool gpu = cudaBackendUsable(&why);
  std::printf("# CPU threads: %u; GPU: %s\n", std::thread::hardware_concurrency(),
              gpu ? cudaDeviceName().c_str() : ("none (" + why + ")").c_str());
  std::printf(
    "solver,backend,spacing_m,particles,steps_per_s,particle_steps_per_s,bytes_per_particle,simulated_s_per_hour\n");
  for (PressureSolverType solver : solvers)
    for (double spacing : spacings)
    {
      for (Backend backend : { Backend::CPU, Backend::CUDA })
      {
        if (backend == Backend::CUDA && !gpu)
        {
          continue;
        }
        const bool large = 1.228 * 0.55 / (spacing * spacing * spacing) > 2.0e6;
        if (backend == Backend::CPU && large)
        {
          continue;
        }
        const int steps = backend == Backend::CUDA ? 200 : (spacing < 0.01 ? 5 : 20);
        const Row r = run(solver, spacing, backend, steps);
        std::printf("%s,%s,%g,%zu,%.1f,%.4g,%.1f,%.1f\n", solverEntry(solver).key,
                    backend == Backend::CUDA ? "CUDA" : "CPU", spacing, r.particles, r.stepsPerSecond,
                    r.stepsPerSecond * static_cast<double>(r.particles), r.bytesPerParticle, r.simulatedSecondsPerHour);
        std::fflush(stdout);
      }
    }
  return 0;
}
