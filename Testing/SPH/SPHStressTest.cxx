// Stability stress tests: long runs and extreme settings either run stably or stop with a clear
// error; they never hang, crash or hand on NaN.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"

#include "EverySolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace
{
using namespace parafluid;
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.01f; // [m]

const char* solverName(PressureSolverType s)
{
  return s == PressureSolverType::DFSPH ? "DFSPH" : s == PressureSolverType::DeltaSPH ? "DeltaSPH" : "WCSPH";
}

SPHParameters water(PressureSolverType solver)
{
  SPHParameters p;
  p.pressureSolver = solver;
  // Müller's seed method keeps its paper's viscosity (it also damps that scheme's acoustic noise).
  p.viscosity = solver == PressureSolverType::WCSPH ? 3.5f : 0.0f;
  p.smoothingLength = 2.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, 0.6f, 0, 0.1f, 0, 0.4f };
  return p;
}

ParticleState damBreakBlock()
{
  // 20 x 10 x 25 = 5000 particles.
  auto lattice = fillBoxWithLattice({ 0, 0.2, 0, 0.1, 0, 0.25 }, kSpacing);
  return ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
}

/// In the path of the surge: a closed box pillar standing on the floor (it pokes through it, so no
/// face lies on the floor), then a ramp rising from the floor at x = 0.3 to z = 0.1 at the far wall
/// across the whole tank (two triangles reaching past the side walls). The pillar's sharp convex
/// edges are where rounding used to let particles in.
constexpr float kPillar[6] = { 0.22f, 0.26f, 0.03f, 0.07f, -0.01f, 0.05f };

float rampHeight(float x)
{
  return x <= 0.3f ? -1.0f : (x - 0.3f) / 3.0f;
}

std::shared_ptr<TriangleBoundary> obstacle()
{
  std::vector<float> p = { 0.3f,  -0.05f, 0.0f,         0.65f, -0.05f, 0.35f / 3.0f,
                           0.65f, 0.15f,  0.35f / 3.0f, 0.3f,  0.15f,  0.0f };
  std::vector<std::uint32_t> t = { 0, 1, 2, 0, 2, 3 };
  for (int k = 0; k < 8; ++k)
  {
    p.insert(p.end(), { kPillar[(k & 1) ? 1 : 0], kPillar[(k & 2) ? 3 : 2], kPillar[(k & 4) ? 5 : 4] });
  }
  // Each face as a quad counter-clockwise seen from outside (pillar corners are vertices 4..11).
  const std::uint32_t quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                                      { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& q : quads)
  {
    t.insert(t.end(), { 4 + q[0], 4 + q[1], 4 + q[2], 4 + q[0], 4 + q[2], 4 + q[3] });
  }
  return std::make_shared<TriangleBoundary>(std::move(p), std::move(t));
}

bool insideObstacle(float x, float y, float z)
{
  const bool inPillar =
    x > kPillar[0] && x < kPillar[1] && y > kPillar[2] && y < kPillar[3] && z > kPillar[4] && z < kPillar[5];
  return inPillar || z < rampHeight(x);
}

/// Potential (above the floor) plus kinetic energy [J].
double mechanicalEnergy(const SPHSolver& s)
{
  double potential = 0.0;
  for (float z : s.state().z)
  {
    potential += s.parameters().particleMass * 9.81 * (z - s.parameters().domainBounds[4]);
  }
  return potential + s.kineticEnergy();
}

void runDamBreakPastTheObstacle(PressureSolverType solver, int steps)
{
  SPHParameters p = water(solver);
  if (solver == PressureSolverType::DeltaSPH)
  {
    // δ-SPH at its default support, as SPH Step gives it. At 2 spacings this surge is marginal: the
    // landed scheme of 2026-11-28 blew up at 0.54 s with CFLNumber 0.19 and ran through at 0.18,
    // 0.2, 0.21 and 0.22; with the push's high pass it blew up at 0.59 s at 0.2 only. At 2.9 it
    // ran through at 0.19, 0.2 and 0.21 (Testing/Benchmarks/README.md, "The pressure push's high
    // pass").
    p.smoothingLength = kDeltaSPHSupport * kSpacing;
    p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  }
  SPHSolver s(p, damBreakBlock(), obstacle());
  ASSERT_EQ(s.state().size(), 5000u);
  const double initial = mechanicalEnergy(s);
  double largestEnergy = initial;
  for (int k = 0; k < steps; ++k)
  {
    s.step();
    if (k % 100 == 99 || k == steps - 1)
    {
      const auto& st = s.state();
      for (std::size_t i = 0; i < st.size(); ++i)
      {
        const float x = st.x[i], y = st.y[i], z = st.z[i];
        ASSERT_TRUE(std::isfinite(x + y + z + st.vx[i] + st.vy[i] + st.vz[i] + st.density[i] + st.pressure[i]))
          << "step " << k;
        ASSERT_TRUE(x >= p.domainBounds[0] && x <= p.domainBounds[1] && y >= p.domainBounds[2] &&
                    y <= p.domainBounds[3] && z >= p.domainBounds[4] && z <= p.domainBounds[5])
          << "particle " << st.id[i] << " left the domain at step " << k;
        ASSERT_FALSE(insideObstacle(x, y, z))
          << "particle " << st.id[i] << " got into the pillar or under the ramp at step " << k;
      }
      largestEnergy = std::max(largestEnergy, mechanicalEnergy(s));
    }
  }
  std::printf("%s: %d steps, %.3f s simulated, energy %.3f of the start (largest %.3f)\n", solverName(solver), steps,
              s.time(), mechanicalEnergy(s) / initial, largestEnergy / initial);
  // Walls, viscosity and the obstacle only take energy out; a weakly compressible fluid may store a
  // little as compression. Allow 2 % of the initial potential energy.
  EXPECT_LT(largestEnergy, 1.02 * initial);
  EXPECT_LT(mechanicalEnergy(s), 0.9 * initial) << "the surge should have lost energy by now";
}

TEST(SPHStress, WCSPHDamBreakTenThousandStepsPastAPillarOverARamp)
{
  runDamBreakPastTheObstacle(PressureSolverType::WCSPH, 10000);
}

TEST(SPHStress, DFSPHDamBreakThreeThousandStepsPastAPillarOverARamp)
{
  // DFSPH's steps are about 3 ms here (WCSPH's 0.12 ms): 3000 of them are 10 s of the surge, its
  // sloshing and the water coming to rest (10000, 34 s, took 11 minutes of CI for the same checks).
  runDamBreakPastTheObstacle(PressureSolverType::DFSPH, 3000);
}

/// Runs `steps` steps; returns the error message, or "" when it ran through. Fails the test on NaN.
std::string runOrStop(const SPHParameters& p, ParticleState s, int steps)
{
  try
  {
    SPHSolver solver(p, std::move(s));
    for (int k = 0; k < steps; ++k)
    {
      solver.step();
      for (std::size_t i = 0; i < solver.state().size(); ++i)
      {
        const auto& st = solver.state();
        if (!std::isfinite(st.x[i] + st.y[i] + st.z[i] + st.vx[i] + st.vy[i] + st.vz[i]))
        {
          ADD_FAILURE() << "NaN handed on at step " << k;
          return "NaN";
        }
      }
    }
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

ParticleState smallBlock()
{
  auto lattice = fillBoxWithLattice({ 0, 0.1, 0, 0.05, 0, 0.15 }, kSpacing);
  return ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
}

TEST(SPHStress, DeltaSPHDamBreakFourThousandStepsPastAPillarOverARamp)
{
  // 0.95 s of the surge: over the ramp, around the pillar and up the far wall. (Before the mesh
  // counted as a wall in δ-SPH's sums, the water packed onto the ramp and the run blew up at 0.46 s.)
  runDamBreakPastTheObstacle(PressureSolverType::DeltaSPH, 4000);
}

class SPHStressEverySolver : public parafluid::testing::EverySolverTest
{
};

TEST_P(SPHStressEverySolver, HundredTimesTooLargeFixedStepStopsWithAClearError)
{
  const PressureSolverType solver = GetParam().type;
  SPHParameters p = water(solver);
  p.adaptiveTimeStep = false;
  p.timeStep = solver != PressureSolverType::DFSPH ? 1e-2f : 0.1f; // 100 x the adaptive step
  const std::string outcome = runOrStop(p, smallBlock(), 300);
  // WCSPH at 100 x its CFL step runs away (it used to go on at 600-800 m/s and 11 x rest density
  // without a word): it must stop and name the property. DFSPH may hold it (checked for NaN
  // inside) or stop the same way.
  if (solver != PressureSolverType::DFSPH)
  {
    EXPECT_FALSE(outcome.empty()) << solverName(solver) << " at 100 x its stable step ran on";
  }
  if (!outcome.empty())
  {
    EXPECT_TRUE(outcome.find("unstable") != std::string::npos || outcome.find("blown up") != std::string::npos)
      << outcome;
    EXPECT_NE(outcome.find("TimeStep"), std::string::npos) << "the message names the property: " << outcome;
    EXPECT_EQ(outcome.find("GasStiffness"),
              solver != PressureSolverType::WCSPH ? std::string::npos : outcome.find("GasStiffness"))
      << "only Müller's WCSPH has a GasStiffness to advise: " << outcome;
    if (solver == PressureSolverType::DeltaSPH)
    {
      EXPECT_NE(outcome.find("SoundSpeed"), std::string::npos) << outcome;
    }
  }
}

TEST(SPHStress, ThousandTimesStifferRunsStablyWithAdaptiveSteps)
{
  SPHParameters p = water(PressureSolverType::WCSPH);
  p.gasStiffness *= 1000.0f;
  SPHSolver solver(p, smallBlock());
  const std::int64_t steps = solver.advance(0.01);
  EXPECT_GT(steps, 100) << "c = 1000 m/s needs steps of about 4e-6 s";
  EXPECT_EQ(solver.time(), 0.01);
  for (float v : solver.state().vz)
  {
    ASSERT_TRUE(std::isfinite(v));
  }
}

TEST(SPHStress, DFSPHRefusesKernelsWiderThanItsSolveConvergesFor)
{
  // At h = 3 spacings the DFSPH density solve diverges within the first step; it is refused up
  // front with a message naming the limit, and WCSPH runs the same scene.
  SPHParameters p = water(PressureSolverType::DFSPH);
  p.smoothingLength = 3.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  const std::string message = runOrStop(p, smallBlock(), 5);
  EXPECT_NE(message.find("at most 2.25 particle spacings"), std::string::npos) << message;
  p.pressureSolver = PressureSolverType::WCSPH;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  EXPECT_EQ(runOrStop(p, smallBlock(), 20), "");
}

TEST_P(SPHStressEverySolver, ZeroViscositySkipsThePassAndStaysBounded)
{
  const PressureSolverType solver = GetParam().type;
  SPHParameters p = water(solver);
  p.viscosity = 0.0f;
  SPHSolver s(p, smallBlock());
  const double initial = mechanicalEnergy(s);
  s.advance(0.3);
  // DFSPH stays within its bound. Müller's WCSPH without viscosity gains energy (its pressure
  // force is not the gradient of the poly6 density's internal energy): bounded, not conserved.
  const double bound = solver == PressureSolverType::WCSPH ? 2.0 : 1.05;
  EXPECT_LT(mechanicalEnergy(s), bound * initial) << (solverName(solver));
}

TEST_P(SPHStressEverySolver, WallFrictionAtExtremesOnlyTakesEnergyAndNeverBlowsUp)
{
  // The small block (10 x 5 x 15 particles) collapses onto walls that stick: no-slip under a
  // viscosity of 200 Pa s, and the law of the wall for a fluid a million times more viscous than
  // water. Friction only takes energy out, whatever its strength.
  const PressureSolverType solver = GetParam().type;
  const char* name = solverName(solver);
  for (WallFriction friction : { WallFriction::FreeSlip, WallFriction::NoSlip, WallFriction::LogLaw })
  {
    SPHParameters p = water(solver);
    p.wallFriction = friction;
    p.viscosity = friction == WallFriction::NoSlip ? 200.0f : p.viscosity;
    p.wallKinematicViscosity = 1.0f;
    SPHSolver s(p, smallBlock());
    const double initial = mechanicalEnergy(s);
    s.advance(0.2);
    for (std::size_t i = 0; i < s.state().size(); ++i)
    {
      ASSERT_TRUE(std::isfinite(s.state().x[i] + s.state().vx[i] + s.state().vz[i])) << name;
    }
    const double final = mechanicalEnergy(s);
    std::printf("%s, wall friction %d: mechanical energy %.4f of the initial after 0.2 s\n", name,
                static_cast<int>(friction), final / initial);
    EXPECT_LT(final, initial) << name << ", friction " << static_cast<int>(friction);
    // A step 100 times too large with adaptivity off: the implicit wall law cannot make it worse
    // than free-slip walls do; it runs or stops with the usual message.
    p.adaptiveTimeStep = false;
    p.timeStep = solver != PressureSolverType::DFSPH ? 1e-2f : 0.1f;
    const std::string outcome = runOrStop(p, smallBlock(), 300);
    if (!outcome.empty())
    {
      EXPECT_NE(outcome.find("TimeStep"), std::string::npos) << name << ": " << outcome;
    }
  }
}

TEST_P(SPHStressEverySolver, ParticlesOnTopOfEachOtherAreRefusedByName)
{
  const PressureSolverType solver = GetParam().type;
  ParticleState s = smallBlock();
  for (std::size_t i = 1; i < s.size(); i += 2) // every other particle onto its neighbour
  {
    s.x[i] = s.x[i - 1];
    s.y[i] = s.y[i - 1];
    s.z[i] = s.z[i - 1];
  }
  // SPH forces vanish at zero distance: such particles would never separate (500 at one point
  // used to run on as one clump). Refused at the start, naming the first pair.
  const std::string outcome = runOrStop(water(solver), s, 200);
  EXPECT_NE(outcome.find("share their position"), std::string::npos) << outcome;
  EXPECT_NE(outcome.find("particles 0 and 1"), std::string::npos) << outcome;
}

TEST_P(SPHStressEverySolver, ASingleParticleFallsFreelyAndZeroParticlesAreFine)
{
  const PressureSolverType solver = GetParam().type;
  SPHParameters p = water(solver);
  SPHSolver one(p, ParticleState::atRest({ 0.3f }, { 0.05f }, { 0.35f }));
  one.advance(0.1);
  // Free fall: the symplectic schemes are exact for constant acceleration up to O(dt g t).
  EXPECT_NEAR(one.state().z[0], 0.35 - 0.5 * 9.81 * 0.01, 3e-3);
  EXPECT_NEAR(one.state().vz[0], -0.981, 1e-3);
  SPHSolver none(p, ParticleState{});
  EXPECT_GE(none.advance(0.1), 1);
  EXPECT_EQ(none.state().size(), 0u);
  EXPECT_EQ(none.kineticEnergy(), 0.0);
}
} // namespace

namespace
{
TEST_P(SPHStressEverySolver, FastButPhysicalRunsAreNotMistakenForBlowUps)
{
  // A block thrown at 5 m/s stays under the scene's speed limit (10 x (free fall + 5 m/s) + 1),
  // and its density stays near rest: the plausibility checks leave it alone.
  const PressureSolverType solver = GetParam().type;
  ParticleState s = smallBlock();
  std::fill(s.vx.begin(), s.vx.end(), 5.0f);
  const std::string outcome = runOrStop(water(solver), s, 100);
  EXPECT_TRUE(outcome.empty()) << outcome;
}
} // namespace

namespace
{
TEST(SPHStress, StabilityAdviceNamesOnlyTheChosenSolversProperties)
{
  // DFSPH has no GasStiffness: its advice used to tell users to lower it.
  for (bool adaptive : { true, false })
  {
    SPHParameters p = water(PressureSolverType::DFSPH);
    p.adaptiveTimeStep = adaptive;
    const std::string dfsph = SPHSolver(p, smallBlock()).stabilityAdvice();
    EXPECT_EQ(dfsph.find("GasStiffness"), std::string::npos) << dfsph;
    EXPECT_NE(dfsph.find("MaxPressureIterations"), std::string::npos) << dfsph;
    p.pressureSolver = PressureSolverType::WCSPH;
    const std::string wcsph = SPHSolver(p, smallBlock()).stabilityAdvice();
    EXPECT_NE(wcsph.find(adaptive ? "CFLNumber" : "TimeStep"), std::string::npos) << wcsph;
  }
}
} // namespace

PARAFLUID_FOR_EVERY_SOLVER(SPHStressEverySolver);
