// Surface tension, adaptive time stepping, the divergence-free solver and the mesh boundary.
#include "parafluid/common/Kernels.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace
{
using namespace parafluid;
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.02f; // [m]

SPHParameters water(PressureSolverType solver = PressureSolverType::WCSPH)
{
  SPHParameters p;
  p.pressureSolver = solver;
  p.smoothingLength = 2.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  return p;
}

ParticleState block(const std::array<double, 6>& bounds, double spacing = kSpacing)
{
  auto lattice = fillBoxWithLattice(bounds, spacing);
  return ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
}

TEST(CubicSplineKernel, IntegratesToOneAndItsDerivativeMatchesFiniteDifferences)
{
  const float h = 0.1f;
  const CubicSplineKernel w(h);
  double integral = 0.0;
  const int n = 4000;
  for (int k = 0; k < n; ++k)
  {
    const double r = (k + 0.5) * h / n;
    integral += 4.0 * kPiF * r * r * w.value(static_cast<float>(r)) * h / n;
  }
  EXPECT_NEAR(integral, 1.0, 1e-4);
  for (float q : { 0.1f, 0.3f, 0.49f, 0.51f, 0.8f, 0.95f })
  {
    const float r = q * h, e = 1e-4f * h;
    const float numeric = (w.value(r + e) - w.value(r - e)) / (2 * e);
    EXPECT_NEAR(w.radialDerivative(r), numeric, 2e-3f * std::fabs(numeric) + 1e-2f) << "q = " << q;
  }
  EXPECT_EQ(w.value(h), 0.0f);
  EXPECT_EQ(w.radialDerivative(h), 0.0f);
}

TEST(LatticeCorrections, MassAndSpacingAreInversesAndTheGradientCorrectionIsSmall)
{
  for (DensityKernel k : { DensityKernel::Poly6, DensityKernel::CubicSpline })
  {
    const float m = latticeParticleMass(0.01f, 0.02f, 1000.0f, k);
    EXPECT_NEAR(latticeSpacingForMass(m, 0.02f, 1000.0f, k), 0.01f, 1e-6f);
  }
  const float correction = latticeGradientCorrection(0.01f, 0.02f, DensityKernel::CubicSpline);
  EXPECT_NEAR(correction, 1.0f / 1.02f, 0.005f);
  // A wide kernel is close to the continuous one.
  EXPECT_NEAR(latticeGradientCorrection(0.01f, 0.06f, DensityKernel::CubicSpline), 1.0f, 0.01f);
}

TEST(AdaptiveTimeStep, RespectsTheCFLConditionAndLandsExactlyOnTheEndTime)
{
  SPHParameters p = water();
  p.domainBounds = { 0, 0.6f, 0, 0.1f, 0, 0.5f };
  SPHSolver solver(p, block({ 0, 0.2, 0, 0.1, 0, 0.3 }));
  const double c = std::sqrt(p.gasStiffness);
  for (int k = 0; k < 40; ++k)
  {
    double vmax = 0.0;
    const auto& s = solver.state();
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      vmax =
        std::max(vmax, std::sqrt(double(s.vx[i]) * s.vx[i] + double(s.vy[i]) * s.vy[i] + double(s.vz[i]) * s.vz[i]));
    }
    const double dt = solver.step();
    EXPECT_LE(dt, p.cflNumber * p.smoothingLength / (c + vmax) * (1 + 1e-6));
    EXPECT_LE(dt, p.maxTimeStep);
  }
  const double before = solver.time();
  const std::int64_t steps = solver.advance(0.0123);
  EXPECT_EQ(solver.time(), before + 0.0123) << "lands exactly on the requested time";
  EXPECT_GT(steps, 40) << "dt is about 2.5e-4 s here";
  // Fixed steps fit the interval exactly: 0.004 s at 2e-4 s is 20 steps.
  p.adaptiveTimeStep = false;
  SPHSolver fixed(p, block({ 0, 0.2, 0, 0.1, 0, 0.3 }));
  EXPECT_EQ(fixed.advance(0.004), 20);
}

TEST(AdaptiveTimeStep, TakesLargerStepsForDFSPHWhichHasNoSoundSpeedLimit)
{
  SPHParameters w = water(PressureSolverType::WCSPH), d = water(PressureSolverType::DFSPH);
  w.domainBounds = d.domainBounds = { 0, 0.6f, 0, 0.1f, 0, 0.5f };
  SPHSolver wc(w, block({ 0, 0.2, 0, 0.1, 0, 0.3 }));
  SPHSolver df(d, block({ 0, 0.2, 0, 0.1, 0, 0.3 }));
  const std::int64_t wcSteps = wc.advance(0.05), dfSteps = df.advance(0.05);
  EXPECT_GT(wcSteps, 5 * dfSteps) << wcSteps << " WCSPH steps against " << dfSteps << " DFSPH steps";
}

TEST(DFSPH, KeepsTheMeanDensityErrorBelowTheToleranceInADamBreak)
{
  SPHParameters p = water(PressureSolverType::DFSPH);
  p.domainBounds = { 0, 0.6f, 0, 0.1f, 0, 0.5f };
  SPHSolver solver(p, block({ 0, 0.2, 0, 0.1, 0, 0.4 }));
  double worst = 0.0, average = 0.0;
  int steps = 0;
  const double end = 0.3;
  while (solver.time() < end)
  {
    solver.step(end - solver.time());
    worst = std::max(worst, solver.lastStep().meanCompression);
    average += solver.lastStep().meanCompression;
    ++steps;
    EXPECT_LE(solver.lastStep().densityIterations, p.maxPressureIterations);
  }
  // The solve bounds the predicted error; the measured one, after the move, follows it on average
  // but peaks higher in the step where the surge hits the far wall.
  EXPECT_LT(average / steps, p.densityTolerance);
  EXPECT_LT(worst, 6.0 * p.densityTolerance);
  double maxX = 0.0;
  for (float x : solver.state().x)
  {
    maxX = std::max<double>(maxX, x);
  }
  EXPECT_GT(maxX, 0.35) << "the column collapsed and the front moved";
}

TEST(DFSPH, ConservesMomentumWithoutWallsOrGravity)
{
  SPHParameters p = water(PressureSolverType::DFSPH);
  p.gravity = { 0, 0, 0 };
  p.viscosity = 0.0f;
  p.domainBounds = { -10, 10, -10, 10, -10, 10 };
  ParticleState s = block({ 0, 0.16, 0, 0.16, 0, 0.16 }, kSpacing * 0.97); // compressed by 9 %
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    s.vx[i] = 0.1f * std::sin(float(i));
  }
  double before[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    before[0] += s.vx[i];
  }
  SPHSolver solver(p, s);
  for (int k = 0; k < 20; ++k)
  {
    solver.step();
  }
  double after[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < solver.state().size(); ++i)
  {
    after[0] += solver.state().vx[i];
    after[1] += solver.state().vy[i];
    after[2] += solver.state().vz[i];
  }
  EXPECT_NEAR(after[0], before[0], 1e-3);
  EXPECT_NEAR(after[1], 0.0, 1e-3);
  EXPECT_NEAR(after[2], 0.0, 1e-3);
}

TEST(DFSPH, RestingColumnHasHydrostaticPressure)
{
  SPHParameters p = water(PressureSolverType::DFSPH);
  const float height = 0.2f;
  p.domainBounds = { 0, 0.2f, 0, 4 * kSpacing, 0, 0.4f };
  SPHSolver solver(p, block({ 0, 0.2, 0, 4 * kSpacing, 0, height }));
  solver.advance(0.4);
  // Averaged over 0.1 s, as the validation benchmark does: single steps carry solver noise.
  std::vector<double> pressure(solver.state().size(), 0.0); // by id
  for (int k = 0; k < 20; ++k)
  {
    solver.advance(0.005);
    const std::vector<float> sample = solver.smoothedPressure();
    for (std::size_t i = 0; i < sample.size(); ++i)
    {
      pressure[static_cast<std::size_t>(solver.state().id[i])] += sample[i] / 20.0;
    }
  }
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < pressure.size(); ++i)
  {
    const double reference = p.restDensity * 9.81 * (height - solver.state().z[i]);
    const double value = pressure[static_cast<std::size_t>(solver.state().id[i])];
    num += (value - reference) * (value - reference);
    den += reference * reference;
  }
  EXPECT_LT(std::sqrt(num / den), 0.04) << "relative L2 error against rho0 g depth (10 particles across)";
}

TEST(SurfaceTension, PullsCornersInwardAndLeavesTheInteriorAlone)
{
  SPHParameters p = water();
  p.gravity = { 0, 0, 0 };
  p.viscosity = 0.0f;
  p.surfaceTensionModel = SurfaceTensionModel::ColourField;
  p.domainBounds = { -10, 10, -10, 10, -10, 10 };
  const ParticleState cube = block({ 0, 0.2, 0, 0.2, 0, 0.2 });
  SPHSolver plain(p, cube);
  p.surfaceTension = 0.0728f;
  SPHSolver tense(p, cube);
  // Both keep the same (sorted) order: same positions, same grid.
  const auto& a = plain.state();
  const auto& b = tense.state();
  ASSERT_EQ(a.id, b.id);
  const float centre = 0.1f;
  double interior = 0.0, corner = 0.0;
  int corners = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    const float extra[3] = { b.ax[i] - a.ax[i], b.ay[i] - a.ay[i], b.az[i] - a.az[i] };
    const float toCentre[3] = { centre - a.x[i], centre - a.y[i], centre - a.z[i] };
    const float magnitude = std::sqrt(extra[0] * extra[0] + extra[1] * extra[1] + extra[2] * extra[2]);
    const float depth = std::min({ a.x[i], 0.2f - a.x[i], a.y[i], 0.2f - a.y[i], a.z[i], 0.2f - a.z[i] });
    if (depth > p.smoothingLength)
    {
      interior = std::max<double>(interior, magnitude);
    }
    else if (std::fabs(toCentre[0]) > 0.08f && std::fabs(toCentre[1]) > 0.08f && std::fabs(toCentre[2]) > 0.08f)
    {
      ++corners;
      corner +=
        (extra[0] * toCentre[0] + extra[1] * toCentre[1] + extra[2] * toCentre[2]) /
        (magnitude * std::sqrt(toCentre[0] * toCentre[0] + toCentre[1] * toCentre[1] + toCentre[2] * toCentre[2]) +
         1e-30f);
    }
  }
  ASSERT_EQ(corners, 8);
  EXPECT_GT(corner / corners, 0.9) << "corner particles are pulled towards the centre";
  EXPECT_EQ(interior, 0.0) << "no surface, no surface force";
}

TEST(MeshBoundary, ParticlesFallingOnATiltedPlaneStayAboveItAndSlideDownhill)
{
  // A plane z = 0.1 + 0.3 (0.4 - x) across the box, two triangles.
  auto z = [](float x) { return 0.1f + 0.3f * (0.4f - x); };
  auto ramp = std::make_shared<TriangleBoundary>(
    std::vector<float>{ -0.1f, -0.1f, z(-0.1f), 0.5f, -0.1f, z(0.5f), 0.5f, 0.2f, z(0.5f), -0.1f, 0.2f, z(-0.1f) },
    std::vector<std::uint32_t>{ 0, 1, 2, 0, 2, 3 });
  SPHParameters p = water();
  p.domainBounds = { 0, 0.4f, 0, 0.1f, 0, 0.6f };
  SPHSolver solver(p, block({ 0.1, 0.3, 0, 0.1, 0.3, 0.4 }), ramp);
  double meanX0 = 0.0;
  for (float x : solver.state().x)
  {
    meanX0 += x / solver.state().size();
  }
  solver.advance(0.4);
  double meanX = 0.0;
  for (std::size_t i = 0; i < solver.state().size(); ++i)
  {
    const auto& s = solver.state();
    ASSERT_GT(s.z[i], z(s.x[i])) << "particle " << s.id[i] << " went through the ramp";
    meanX += s.x[i] / s.size();
  }
  EXPECT_GT(meanX, meanX0 + 0.02) << "water slides down the ramp towards +x";
}
} // namespace
