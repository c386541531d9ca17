// The three wall conditions of the SPH box: free-slip, no-slip through the viscous term, and the
// turbulent law of the wall; and the law itself.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"
#include "parafluid/sph/TurbulentWallLaw.h"
#include "parafluid/sph/WallMirrors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace
{
using namespace parafluid;
using namespace parafluid;
using namespace parafluid::sph;

const char* solverName(PressureSolverType solver)
{
  return solver == PressureSolverType::DFSPH ? "DFSPH" : "WCSPH";
}

/// u* from the log layer u = u* (ln(y u* / nu) / kappa + B) by bisection, an independent check of
/// the Newton solve; the right side increases with u* from y+ = 1 up.
double logLayerFrictionVelocity(double u, double y, double nu)
{
  double lo = nu / y, hi = u;
  for (int k = 0; k < 200; ++k)
  {
    const double mid = 0.5 * (lo + hi);
    const double speed = mid * (std::log(y * mid / nu) / TurbulentWallLaw::kappa + TurbulentWallLaw::logIntercept);
    (speed < u ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(TurbulentWallLaw, SublayerMeetsTheLogLayerNearYPlusEleven)
{
  const double edge = TurbulentWallLaw::sublayerEdge();
  EXPECT_NEAR(edge, 11.0, 0.3);
  EXPECT_NEAR(edge, std::log(edge) / TurbulentWallLaw::kappa + TurbulentWallLaw::logIntercept, 1e-4);
}

TEST(TurbulentWallLaw, FrictionVelocitySatisfiesTheLawInBothLayers)
{
  const float y = 2.5e-3f, nu = 1.0e-6f; // half a 5 mm particle spacing above a floor, water
  float previous = 0.0f;
  int sublayer = 0, logLayer = 0;
  for (float u = 1e-4f; u < 20.0f; u *= 1.5f)
  {
    const float ustar = TurbulentWallLaw::frictionVelocity(u, y, nu);
    const double yPlus = y * ustar / nu;
    const double uPlus = u / ustar;
    if (yPlus <= TurbulentWallLaw::sublayerEdge())
    {
      ++sublayer;
      EXPECT_NEAR(uPlus, yPlus, 1e-3 * yPlus) << "u = " << u;
    }
    else
    {
      ++logLayer;
      EXPECT_NEAR(uPlus, std::log(yPlus) / TurbulentWallLaw::kappa + TurbulentWallLaw::logIntercept, 1e-3 * uPlus)
        << "u = " << u;
      EXPECT_NEAR(ustar, logLayerFrictionVelocity(u, y, nu), 1e-4 * ustar) << "u = " << u;
    }
    EXPECT_GT(ustar, previous) << "u* grows with the speed";
    previous = ustar;
  }
  EXPECT_GT(sublayer, 3);
  EXPECT_GT(logLayer, 3);
  // Water at 1 m/s, 2.5 mm off a smooth floor: y+ about 140, u+ = 17, so u* is near 6 % of the speed.
  const float ustar = TurbulentWallLaw::frictionVelocity(1.0f, y, nu);
  EXPECT_GT(ustar, 0.055f);
  EXPECT_LT(ustar, 0.06f);
  EXPECT_EQ(TurbulentWallLaw::frictionVelocity(0.0f, y, nu), 0.0f);
  EXPECT_EQ(TurbulentWallLaw::frictionVelocity(-1.0f, y, nu), ustar) << "depends on the speed only";
}

TEST(WallMirrors, NoSlipImagesReverseTheWholeVelocityAndComposeWithFreeSlip)
{
  const std::array<float, 6> bounds = { 0, 1, 0, 1, 0, 1 };
  const float corner[3] = { 0.01f, 0.5f, 0.01f }; // near xmin (free-slip) and zmin (no-slip)
  const WallMirrors m = WallMirrors::around(corner, bounds, 0.05f, { false, false, false, false, true, false });
  ASSERT_EQ(m.count, 3);
  int seen = 0;
  for (int k = 0; k < m.count; ++k)
  {
    const float* s = m.scale[k];
    const float* v = m.velocityScale[k];
    if (s[0] < 0 && s[2] > 0) // across xmin only: free-slip, the normal (x) reverses
    {
      EXPECT_EQ(v[0], -1.0f);
      EXPECT_EQ(v[1], 1.0f);
      EXPECT_EQ(v[2], 1.0f);
      seen |= 1;
    }
    if (s[0] > 0 && s[2] < 0) // across the floor only: no-slip, everything reverses
    {
      EXPECT_EQ(v[0], -1.0f);
      EXPECT_EQ(v[1], -1.0f);
      EXPECT_EQ(v[2], -1.0f);
      seen |= 2;
    }
    if (s[0] < 0 && s[2] < 0) // both: -(flip x) = (+1, -1, -1)
    {
      EXPECT_EQ(v[0], 1.0f);
      EXPECT_EQ(v[1], -1.0f);
      EXPECT_EQ(v[2], -1.0f);
      seen |= 4;
    }
  }
  EXPECT_EQ(seen, 7);
  const WallMirrors free = WallMirrors::around(corner, bounds, 0.05f);
  for (int k = 0; k < free.count; ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(free.velocityScale[k][a], free.scale[k][a]) << "free-slip images mirror the velocity";
    }
  }
}

/// A slab of water 20 x 4 x 12 particles (5 mm apart) sliding at 1 m/s along a floor, without
/// gravity, far from the end walls; the y walls are free-slip symmetry planes.
struct SlidingSlab
{
  static constexpr float spacing = 0.005f, speed = 1.0f;
  static constexpr double length = 0.1, width = 0.02, depth = 0.06;

  static SPHParameters parameters(PressureSolverType solver, WallFriction friction, float viscosity)
  {
    SPHParameters p;
    p.pressureSolver = solver;
    p.smoothingLength = 2.0f * spacing;
    p.particleMass = latticeParticleMass(spacing, p.smoothingLength, p.restDensity, p.densityKernel());
    p.gravity = { 0, 0, 0 };
    p.viscosity = viscosity;
    p.domainBounds = { -1.0f, 1.0f, 0.0f, static_cast<float>(width), 0.0f, 0.2f };
    p.wallFriction = friction;
    p.frictionWalls = { true, true, false, false, true, true };
    return p;
  }

  /// x momentum per unit floor area [kg/(m s)] after `duration` seconds.
  static double momentumAfter(const SPHParameters& p, double duration)
  {
    auto lattice = fillBoxWithLattice({ 0, length, 0, width, 0, depth }, spacing);
    ParticleState state = ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
    std::fill(state.vx.begin(), state.vx.end(), speed);
    SPHSolver solver(p, std::move(state));
    solver.advance(duration);
    double sum = 0.0;
    for (float v : solver.state().vx)
    {
      sum += static_cast<double>(p.particleMass) * v;
    }
    return sum / (length * width);
  }

  static double initialMomentum(const SPHParameters& p)
  {
    const double particles = std::round(length / spacing) * std::round(width / spacing) * std::round(depth / spacing);
    return particles * p.particleMass * speed / (length * width);
  }
};

TEST(WallFriction, FreeSlipFloorKeepsTheSlidingMomentum)
{
  for (PressureSolverType solver : { PressureSolverType::WCSPH, PressureSolverType::DFSPH })
  {
    const SPHParameters p = SlidingSlab::parameters(solver, WallFriction::FreeSlip, 3.5f);
    const double start = SlidingSlab::initialMomentum(p);
    EXPECT_NEAR(SlidingSlab::momentumAfter(p, 0.02), start, 1e-4 * start);
  }
}

TEST(WallFriction, NoSlipFloorTakesMomentumAsStokesFirstProblem)
{
  // Stokes' first problem: a wall suddenly stopped under fluid moving at U takes momentum
  // 2 rho U sqrt(nu t / pi) per unit area by time t. nu = 0.05 m^2/s gives a boundary layer of
  // 18 mm (3.6 spacings) by t = 20 ms, inside the 60 mm slab.
  const float mu = 50.0f; // [Pa s]
  const double t = 0.02, nu = mu / 1000.0;
  const double expected = 2.0 * 1000.0 * SlidingSlab::speed * std::sqrt(nu * t / 3.14159265358979);
  for (PressureSolverType solver : { PressureSolverType::WCSPH, PressureSolverType::DFSPH })
  {
    const SPHParameters p = SlidingSlab::parameters(solver, WallFriction::NoSlip, mu);
    const double lost = SlidingSlab::initialMomentum(p) - SlidingSlab::momentumAfter(p, t);
    EXPECT_NEAR(lost, expected, 0.1 * expected) << solverName(solver);
    std::printf("no-slip floor, %s: momentum lost %.4f kg/(m s), Stokes %.4f\n", solverName(solver), lost, expected);
    // Off on the floor (and everywhere else the slab touches), nothing is lost.
    SPHParameters off = p;
    off.frictionWalls = { true, true, true, true, false, true };
    off.frictionWalls[2] = off.frictionWalls[3] = false;
    EXPECT_NEAR(SlidingSlab::momentumAfter(off, t), SlidingSlab::initialMomentum(p),
                1e-4 * SlidingSlab::initialMomentum(p));
  }
}

TEST(WallFriction, LogLawFloorTakesMomentumAtTheWallShearStress)
{
  // The floor layer moves at U, half a spacing off the floor; the wall takes rho u*^2 per unit area
  // and time. Over 20 ms that layer slows by under 1 %, so u* hardly changes.
  const double t = 0.02;
  const double ustar = TurbulentWallLaw::frictionVelocity(SlidingSlab::speed, 0.5f * SlidingSlab::spacing, 1.0e-6f);
  const double expected = 1000.0 * ustar * ustar * t;
  for (PressureSolverType solver : { PressureSolverType::WCSPH, PressureSolverType::DFSPH })
  {
    const SPHParameters p = SlidingSlab::parameters(solver, WallFriction::LogLaw, 3.5f);
    const double lost = SlidingSlab::initialMomentum(p) - SlidingSlab::momentumAfter(p, t);
    EXPECT_NEAR(lost, expected, 0.05 * expected) << solverName(solver);
    std::printf("log-law floor, %s: momentum lost %.5f kg/(m s), rho u*^2 t %.5f\n", solverName(solver), lost,
                expected);
  }
}

TEST(WallFriction, RejectsANonPositiveWallViscosity)
{
  SPHParameters p;
  p.pressureSolver = PressureSolverType::WCSPH; // DFSPH would refuse this mass for its kernel width
  p.particleMass = 1e-3f;
  for (float nu : { 0.0f, -1e-6f, std::nanf(""), 2.0f })
  {
    p.wallKinematicViscosity = nu;
    EXPECT_NE(p.validate().find("WallKinematicViscosity"), std::string::npos) << nu;
  }
  p.wallKinematicViscosity = 1e-6f;
  EXPECT_EQ(p.validate(), "");
}
} // namespace
