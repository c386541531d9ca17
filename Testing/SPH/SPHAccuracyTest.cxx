// Surface tension, adaptive time stepping, the divergence-free solver and the mesh boundary.
#include "parafluid/common/Kernels.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

TEST(LatticeCorrections, MorrisLaplacianIsNearlyExactOnTheLatticeWhereMonaghansIsWeakAlongItsAxes)
{
  // Wendland C2 at 3 spacings (δ-SPH's default until it became 2.9): Monaghan's operator, whose error depends on the
  // direction of shear against the lattice, misses an axis-aligned shear by about 8 %; Morris's,
  // whose second moment is isotropic on a cubic lattice, by about the eta^2 of the pair closest in.
  const float monaghan = latticeLaplacianCorrection(0.01f, 0.03f, DensityKernel::WendlandC2);
  const float morris = latticeMorrisLaplacianCorrection(0.01f, 0.03f, DensityKernel::WendlandC2);
  std::printf("lattice Laplacian corrections at 3 spacings: Monaghan %.4f, Morris %.4f\n", monaghan, morris);
  EXPECT_GT(monaghan, 1.05f);
  EXPECT_GT(morris, 1.0f);
  EXPECT_LT(morris, 1.03f);
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

TEST(DFSPH, ConjugateGradientBuildsADeepColumnsPressureWhereJacobiRunsOutOfIterations)
{
  // A narrow column 60 particles deep, starting without pressure: its weight has to be carried
  // down 60 layers within the first steps. Jacobi's iterations carry pressure one neighbourhood
  // each and reach the cap of 100; the conjugate gradient converges within it (52 at most here) and
  // keeps the column within 1.5 % of rest density.
  const auto run = [](bool conjugateGradient, int& mostIterations, double& densest)
  {
    SPHParameters p = water(PressureSolverType::DFSPH);
    p.pressureConjugateGradient = conjugateGradient;
    p.domainBounds = { 0, 4 * kSpacing, 0, 4 * kSpacing, 0, 80 * kSpacing };
    SPHSolver solver(p, block({ 0, 4 * kSpacing, 0, 4 * kSpacing, 0, 60 * kSpacing }));
    mostIterations = 0;
    densest = 0.0;
    for (int k = 0; k < 10; ++k)
    {
      solver.advance(0.0025);
      mostIterations = std::max(mostIterations, solver.lastStep().densityIterations);
      densest = std::max(densest, solver.lastStep().maxDensityRatio);
    }
  };
  int jacobiIterations = 0, gradientIterations = 0;
  double jacobiDensest = 0.0, gradientDensest = 0.0;
  run(false, jacobiIterations, jacobiDensest);
  run(true, gradientIterations, gradientDensest);
  std::printf("60 deep: Jacobi at most %d iterations, densest %.4f rho0; conjugate gradient %d, %.4f rho0\n",
              jacobiIterations, jacobiDensest, gradientIterations, gradientDensest);
  EXPECT_EQ(jacobiIterations, 100);
  EXPECT_LT(gradientIterations, 100);
  EXPECT_LT(gradientDensest, 1.015);
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
TEST(MeshBoundary, WaterOnAMeshFloorHasRestDensityInItsBottomLayer)
{
  // A lattice block whose bottom layer lies half a spacing over a flat mesh floor (the box's own
  // floor far below). DFSPH's density of that layer is rest density when the mesh counts as a wall,
  // as a box wall's mirror images give; with the mesh only stopping particles, the layer's cut
  // neighbourhood sums to much less.
  const float floorZ = 0.1f;
  auto floor = std::make_shared<TriangleBoundary>(
    std::vector<float>{ -0.1f, -0.1f, floorZ, 0.5f, -0.1f, floorZ, 0.5f, 0.5f, floorZ, -0.1f, 0.5f, floorZ },
    std::vector<std::uint32_t>{ 0, 1, 2, 0, 2, 3 });
  auto bottomLayerDensity = [&](bool wall)
  {
    SPHParameters p = water(PressureSolverType::DFSPH);
    p.domainBounds = { 0, 0.4f, 0, 0.4f, 0, 0.4f };
    p.meshWallDensity = wall;
    const SPHSolver solver(p, block({ 0.1, 0.3, 0.1, 0.3, floorZ, floorZ + 6 * kSpacing }), floor);
    const auto& s = solver.state();
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      // The bottom layer, away from the block's sides (their neighbourhoods are cut sideways).
      const float inset = 0.1f + 2.5f * kSpacing;
      if (s.z[i] < floorZ + kSpacing && s.x[i] > inset && s.x[i] < 0.4f - inset && s.y[i] > inset &&
          s.y[i] < 0.4f - inset)
      {
        sum += s.density[i];
        ++count;
      }
    }
    EXPECT_GT(count, 9);
    return sum / count / p.restDensity;
  };
  const double withWall = bottomLayerDensity(true);
  const double without = bottomLayerDensity(false);
  RecordProperty("with_wall", std::to_string(withWall));
  RecordProperty("without_wall", std::to_string(without));
  EXPECT_NEAR(withWall, 1.0, 0.005);
  EXPECT_LT(without, 0.9);
}

TEST(BoxWalls, DeltaSPHTankAtRestPushesNoFloorParticleIntoItsEdgeOrCorner)
{
  // δ-SPH water 10 layers deep in a box (a slab 4 particles thick, walls on every side), at SPH
  // Step's kernel of 3 spacings until 2026-11-28 (2.9 since), as it starts in hydrostatic equilibrium. A wall holds a
  // particle off through the pair with its own image, whose stiffened profile is scaled to Wendland's at one spacing;
  // an edge or corner particle's image across two or three walls is sqrt(2) or sqrt(3) spacings away, where that
  // profile pushed 11 % less: those particles started at 2 m/s^2 into their corners (and 2.0 m/s^2 down), every other
  // floor particle at rest.
  SPHParameters p = water(PressureSolverType::DeltaSPH);
  p.smoothingLength = 3.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0.0f, 10 * kSpacing, 0.0f, 4 * kSpacing, 0.0f, 20 * kSpacing };
  const SPHSolver solver(p, block({ 0.0, 10 * kSpacing, 0.0, 4 * kSpacing, 0.0, 10 * kSpacing }));
  const auto& s = solver.state();
  double sideways = 0.0, lowestUp = 1e30, highestUp = -1e30;
  int floorParticles = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    if (s.z[i] > kSpacing)
    {
      continue;
    }
    ++floorParticles;
    sideways = std::max<double>(sideways, std::hypot(s.ax[i], s.ay[i]));
    lowestUp = std::min<double>(lowestUp, s.az[i]);
    highestUp = std::max<double>(highestUp, s.az[i]);
  }
  RecordProperty("largest_sideways_acceleration", std::to_string(sideways));
  RecordProperty("vertical_acceleration_spread", std::to_string(highestUp - lowestUp));
  ASSERT_EQ(floorParticles, 40);
  EXPECT_LT(sideways, 0.01);             // m/s^2, against 9.81 of gravity
  EXPECT_LT(highestUp - lowestUp, 0.01); // every floor particle alike
}

TEST(MeshBoundary, DeltaSPHWaterRestsStillOnAMeshFloor)
{
  // δ-SPH water 8 layers deep on a flat mesh floor (the box's floor far below), at SPH Step's
  // kernel of 3 spacings until 2026-11-28 (2.9 since): with the mesh a wall in its sums it rests (bottom layer half a
  // spacing up, the top where it started). With the mesh only stopping particles, the bottom layer fell onto the mesh
  // within 0.8 s and the water sloshed at 0.1-0.5 m/s.
  const float floorZ = 0.1f;
  auto floor = std::make_shared<TriangleBoundary>(
    std::vector<float>{ -0.1f, -0.1f, floorZ, 0.5f, -0.1f, floorZ, 0.5f, 0.5f, floorZ, -0.1f, 0.5f, floorZ },
    std::vector<std::uint32_t>{ 0, 1, 2, 0, 2, 3 });
  SPHParameters p = water(PressureSolverType::DeltaSPH);
  p.smoothingLength = 3.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0.1f, 0.3f, 0.1f, 0.3f, 0, 0.4f };
  SPHSolver solver(p, block({ 0.1, 0.3, 0.1, 0.3, floorZ, floorZ + 8 * kSpacing }), floor);
  solver.advance(1.0);
  const auto& s = solver.state();
  double lowest = 1.0, highest = 0.0, fastest = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    lowest = std::min<double>(lowest, s.z[i]);
    highest = std::max<double>(highest, s.z[i]);
    fastest = std::max<double>(fastest, std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]));
  }
  RecordProperty("lowest_over_spacing", std::to_string((lowest - floorZ) / kSpacing));
  RecordProperty("fastest", std::to_string(fastest));
  EXPECT_GT(lowest - floorZ, 0.3 * kSpacing);
  EXPECT_NEAR(highest - floorZ, 7.5 * kSpacing, 0.1 * kSpacing);
  EXPECT_LT(fastest, 0.01);
}

TEST(MeshBoundary, DeltaSPHWaterFallingOnAWavyTerrainOnlyLosesEnergy)
{
  // A block of water dropped 5-9 cm onto a wavy terrain mesh spreads over it in δ-SPH with the mesh
  // as a wall: the mechanical energy (potential over the box floor plus kinetic) never grows, and
  // no particle gets under the terrain. (With a wall that only pushed, the spreading film's tension
  // took in energy and the run blew up within 0.3 s.)
  const int nx = 41, ny = 21;
  const float dx = 0.02f;
  auto height = [](float x, float y) { return 0.1f + 0.04f * std::sin(7.0f * x) * std::cos(9.0f * y); };
  std::vector<float> points;
  std::vector<std::uint32_t> triangles;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      points.insert(points.end(), { i * dx, j * dx, height(i * dx, j * dx) });
    }
  }
  for (int j = 0; j + 1 < ny; ++j)
  {
    for (int i = 0; i + 1 < nx; ++i)
    {
      const std::uint32_t a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      triangles.insert(triangles.end(), { a, b, d, a, d, c });
    }
  }
  auto terrain = std::make_shared<TriangleBoundary>(points, triangles);
  const float spacing = 0.01f;
  SPHParameters p = water(PressureSolverType::DeltaSPH);
  p.smoothingLength = 3.0f * spacing;
  p.particleMass = latticeParticleMass(spacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, 0.8f, 0, 0.4f, 0.0f, 0.4f };
  SPHSolver solver(p, block({ 0.18, 0.26, 0.16, 0.24, 0.15, 0.19 }, spacing), terrain);
  auto energy = [&]()
  {
    const auto& s = solver.state();
    double e = solver.kineticEnergy();
    for (float z : s.z)
    {
      e += p.particleMass * 9.81 * z;
    }
    return e;
  };
  const double initial = energy();
  double largest = initial;
  float deepest = 0.0f;
  for (int k = 0; k < 20; ++k)
  {
    solver.advance(0.025);
    largest = std::max(largest, energy());
    const auto& s = solver.state();
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      // Under the triangulated surface: the height field's linear interpolation across the
      // triangle the point is over (diagonal from (i, j) to (i + 1, j + 1)).
      const float fx = std::clamp(s.x[i] / dx, 0.0f, nx - 1.001f), fy = std::clamp(s.y[i] / dx, 0.0f, ny - 1.001f);
      const int ci = static_cast<int>(fx), cj = static_cast<int>(fy);
      const float u = fx - ci, v = fy - cj;
      const float h00 = height(ci * dx, cj * dx), h10 = height((ci + 1) * dx, cj * dx);
      const float h01 = height(ci * dx, (cj + 1) * dx), h11 = height((ci + 1) * dx, (cj + 1) * dx);
      const float ground = u >= v ? h00 + u * (h10 - h00) + v * (h11 - h10) : h00 + v * (h01 - h00) + u * (h11 - h01);
      deepest = std::max(deepest, ground - s.z[i]);
    }
  }
  RecordProperty("largest_energy_over_initial", std::to_string(largest / initial));
  RecordProperty("final_energy_over_initial", std::to_string(energy() / initial));
  EXPECT_LT(largest, 1.001 * initial);
  EXPECT_LT(energy(), initial);
  EXPECT_LT(deepest, 1e-4f) << "a particle got under the terrain";
}

} // namespace
