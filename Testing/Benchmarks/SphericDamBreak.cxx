// The 3-D dam break of SPHERIC benchmark test 2 (Kleefsman et al. 2005) in the geometry of Debian
// python3-pysph's dam_break_3d example (tank 3.22 x 1 x 1 m, water 1.228 x 1 x 0.55 m, a box
// obstacle 0.16 x 0.4 x 0.161 m centred at x = 2.5 m): ParaFluid's solvers on the same particles
// as the peer (pysph_peer.sh runs pysph). Prints steps, wall time, particle-steps per second and
// simulated seconds per second for each solver.
// Usage: ParaFluidSphericDamBreak [spacing=0.02] [simulated seconds=0.01]
#include "ClosedBoxMesh.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/SPHSolver.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

using namespace parafluid;
using namespace parafluid::sph;

namespace
{
std::shared_ptr<TriangleBoundary> obstacle()
{
  const float lo[3] = { 2.42f, 0.3f, -0.01f }, hi[3] = { 2.58f, 0.7f, 0.161f }; // pokes through the floor
  std::vector<float> p;
  std::vector<std::uint32_t> t;
  testing::appendClosedBox(p, t, lo, hi);
  return std::make_shared<TriangleBoundary>(std::move(p), std::move(t));
}
} // namespace

int main(int argc, char** argv)
{
  const double d = argc > 1 ? std::atof(argv[1]) : 0.02;
  const double duration = argc > 2 ? std::atof(argv[2]) : 0.01;
  for (PressureSolverType solver : { PressureSolverType::DeltaSPH, PressureSolverType::DFSPH })
  {
    SPHParameters p;
    p.pressureSolver = solver;
    // δ-SPH at its default kDeltaSPHSupport (the peer: Wendland quintic at 2.6), DFSPH at its 2.
    p.smoothingLength = static_cast<float>((solver == PressureSolverType::DeltaSPH ? kDeltaSPHSupport : 2.0f) * d);
    p.particleMass = latticeParticleMass(static_cast<float>(d), p.smoothingLength, p.restDensity, p.densityKernel());
    p.domainBounds = { 0.0f, 3.22f, 0.0f, 1.0f, 0.0f, 1.0f };
    auto l = fillBoxWithLattice({ 0, 1.228, 0, 1.0, 0, 0.55 }, d);
    const std::size_t n = l.x.size();
    SPHSolver s(p, ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z)), obstacle());
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t steps = s.advance(duration);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-8s %zu particles, %lld steps over %.3f s simulated in %.2f s: %.0f particle-steps/s, "
                "%.2e simulated s per s\n",
                solver == PressureSolverType::DeltaSPH ? "DeltaSPH" : "DFSPH", n, static_cast<long long>(steps),
                duration, wall, static_cast<double>(n) * static_cast<double>(steps) / wall, duration / wall);
  }
  return 0;
}
