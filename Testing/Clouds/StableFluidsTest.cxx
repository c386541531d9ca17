// Stable fluids on the staggered grid: the projection, the advection (plain and MacCormack),
// stability far past the CFL limit, buoyancy, and bad input.
#include "parafluid/clouds/StableFluids.h"
#include "parafluid/clouds/GridSolvers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace parafluid::clouds;

namespace
{
double rms(const std::vector<double>& values)
{
  double sum = 0.0;
  for (double v : values)
  {
    sum += v * v;
  }
  return std::sqrt(sum / static_cast<double>(values.size()));
}

void randomVelocity(StaggeredGrid& g, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (GridArray* f : { &g.u, &g.v, &g.w })
  {
    for (double& value : f->values)
    {
      value = u(rng);
    }
  }
}

double maxSpeed(const StaggeredGrid& g)
{
  double m = 0.0;
  for (const GridArray* f : { &g.u, &g.v, &g.w })
  {
    for (double value : f->values)
    {
      m = std::max(m, std::abs(value));
    }
  }
  return m;
}

// A Gaussian blob of density (sigma cells) centred at cell coordinates c.
void blob(StaggeredGrid& g, const double c[3], double sigma)
{
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        const double r2 = (i + 0.5 - c[0]) * (i + 0.5 - c[0]) + (j + 0.5 - c[1]) * (j + 0.5 - c[1]) +
                          (k + 0.5 - c[2]) * (k + 0.5 - c[2]);
        g.density.at(i, j, k) = std::exp(-0.5 * r2 / (sigma * sigma));
      }
}

double centroidX(const StaggeredGrid& g)
{
  double sum = 0.0, weight = 0.0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        sum += (i + 0.5) * g.density.at(i, j, k);
        weight += g.density.at(i, j, k);
      }
  return sum / weight;
}
} // namespace

TEST(StableFluids, ProjectionLeavesNoDivergence)
{
  StaggeredGrid g;
  g.resize(24, 20, 16, 0.05);
  randomVelocity(g, 1);
  setBoundaryVelocities(g);
  const double before = rms(divergence(g));
  const SolveReport report = project(g, 0.01, 1e-10, 2000);
  std::vector<double> speeds;
  for (const GridArray* f : { &g.u, &g.v, &g.w })
  {
    speeds.insert(speeds.end(), f->values.begin(), f->values.end());
  }
  const double after = rms(divergence(g));
  EXPECT_GT(before, 1.0);
  EXPECT_LE(after, 1e-4 * rms(speeds) / g.h) << report.iterations << " iterations, residual " << report.residual;
}

TEST(StableFluids, DivergenceFreeFieldPassesUnchanged)
{
  // u = d(psi)/dy, v = -d(psi)/dx from a stream function on the cells' z edges, zero on the walls:
  // its discrete divergence is zero exactly, whatever psi is.
  StaggeredGrid g;
  g.resize(20, 16, 6, 0.1);
  auto psi = [&](int i, int j)
  {
    if (i == 0 || j == 0 || i == g.nx || j == g.ny)
    {
      return 0.0;
    }
    return std::sin(3.14159 * i / g.nx) * std::sin(2.0 * 3.14159 * j / g.ny) * (1.0 + 0.3 * i / g.nx);
  };
  for (int k = 0; k < g.nz; ++k)
  {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i <= g.nx; ++i)
        g.u.at(i, j, k) = (psi(i, j + 1) - psi(i, j)) / g.h;
    for (int j = 0; j <= g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        g.v.at(i, j, k) = -(psi(i + 1, j) - psi(i, j)) / g.h;
  }
  const StaggeredGrid original = g;
  project(g, 0.02);
  double change = 0.0;
  for (std::size_t n = 0; n < g.u.values.size(); ++n)
  {
    change = std::max(change, std::abs(g.u.values[n] - original.u.values[n]));
  }
  for (std::size_t n = 0; n < g.v.values.size(); ++n)
  {
    change = std::max(change, std::abs(g.v.values[n] - original.v.values[n]));
  }
  EXPECT_LT(change, 1e-9 * maxSpeed(original));
  EXPECT_GT(maxSpeed(original), 1.0);
}

TEST(StableFluids, BlobMovesWithTheWindAndMacCormackKeepsItsPeak)
{
  // A uniform wind along x (advection alone: no projection), a blob of sigma 4 cells carried 24
  // cells, three eighths of the box (the grid has closed walls, so not a whole crossing).
  for (bool macCormack : { false, true })
  {
    StaggeredGrid g;
    g.resize(64, 16, 16, 0.1);
    std::fill(g.u.values.begin(), g.u.values.end(), 2.0);
    const double start[3] = { 16.0, 8.0, 8.0 };
    blob(g, start, 4.0);
    const double peak = *std::max_element(g.density.values.begin(), g.density.values.end());
    const double x0 = centroidX(g);
    const double dt = 0.5 * g.h / 2.0; // half a cell per step
    for (int s = 0; s < 48; ++s)
    {
      g.density = advect(g.density, g, dt, macCormack);
    }
    const double moved = centroidX(g) - x0;
    const double kept = *std::max_element(g.density.values.begin(), g.density.values.end()) / peak;
    std::printf("%s: moved %.3f cells (wind: 24), peak kept %.3f\n", macCormack ? "MacCormack" : "semi-Lagrangian",
                moved, kept);
    EXPECT_NEAR(moved, 24.0, 0.5);
    if (macCormack)
    {
      EXPECT_GE(kept, 0.95);
    }
  }
}

TEST(StableFluids, ScalarsSharingATraceMatchTracingEachAlone)
{
  // Density and temperature are carried along one trace (its corners found once), open faces and
  // ambients included, in plain tracing and in the conservative step with and without BFECC: the
  // result must be the one each field gets traced alone.
  StaggeredGrid g;
  g.resize(21, 17, 15, 0.1);
  g.open = { false, true, false, false, false, true };
  randomVelocity(g, 7);
  for (GridArray* f : { &g.u, &g.v, &g.w })
  {
    for (double& value : f->values)
    {
      value *= 3.0; // up to 1.5 cells a step: traces leave through the open faces
    }
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (double& value : g.density.values)
    value = unit(rng);
  for (double& value : g.temperature.values)
    value = 5.0 + unit(rng);
  const double dt = 0.05;
  const struct
  {
    bool sharpen, conservative;
  } modes[3] = { { false, false }, { false, true }, { true, true } };
  for (const auto& mode : modes)
  {
    StaggeredGrid together = g, alone = g;
    advectScalars(together, { { &together.density, 0.0 }, { &together.temperature, 4.0 } }, dt, mode.sharpen,
                  mode.conservative);
    advectScalars(alone, { { &alone.density, 0.0 } }, dt, mode.sharpen, mode.conservative);
    advectScalars(alone, { { &alone.temperature, 4.0 } }, dt, mode.sharpen, mode.conservative);
    double largest = 0.0, changed = 0.0;
    for (std::size_t c = 0; c < g.cells(); ++c)
    {
      largest = std::max(largest, std::abs(together.density.values[c] - alone.density.values[c]));
      largest = std::max(largest, std::abs(together.temperature.values[c] - alone.temperature.values[c]));
      changed = std::max(changed, std::abs(together.temperature.values[c] - g.temperature.values[c]));
    }
    EXPECT_LE(largest, 1e-12) << "sharpen " << mode.sharpen << ", conservative " << mode.conservative;
    EXPECT_GT(changed, 0.1); // the fields did move: not a comparison of two copies of the start
  }
}

TEST(StableFluids, ProductAdvectionCarriesABlobFortyCellsKeepingItsMassAndPeak)
{
  // A blob of sigma 4 cells carried 40.5 cells at 1.5 cells a step (27 steps, the fraction of
  // a cell that interpolation smears most), by plain MacCormack and by the scalars' own path
  // (conservative BFECC + mass fixer), in a 96-cell box whose far wall it never nears.
  for (bool conservative : { false, true })
  {
    StaggeredGrid g;
    g.resize(96, 16, 16, 0.1);
    std::fill(g.u.values.begin(), g.u.values.end(), 2.0);
    setBoundaryVelocities(g);
    const double start[3] = { 12.0, 8.0, 8.0 };
    blob(g, start, 4.0);
    const double peak = *std::max_element(g.density.values.begin(), g.density.values.end());
    double mass = 0.0;
    for (double v : g.density.values)
      mass += v;
    const double x0 = centroidX(g);
    const double dt = 1.5 * g.h / 2.0;
    for (int s = 0; s < 27; ++s)
    {
      if (conservative)
      {
        advectScalars(g, { { &g.density, 0.0 } }, dt, true, true);
      }
      else
      {
        g.density = advect(g.density, g, dt, true);
      }
    }
    double after = 0.0;
    for (double v : g.density.values)
      after += v;
    const double kept = *std::max_element(g.density.values.begin(), g.density.values.end()) / peak;
    std::printf("%s: moved %.3f cells (wind: 40.5), peak kept %.3f, mass changed by %.2e\n",
                conservative ? "conservative BFECC" : "MacCormack", centroidX(g) - x0, kept, after / mass - 1.0);
    // Plain MacCormack gains mass (its clamp fills the negative lobes) and lags (38.5 cells);
    // the conservative BFECC keeps the mass, the place and the peak.
    EXPECT_GE(kept, 0.95);
    if (conservative)
    {
      EXPECT_NEAR(centroidX(g) - x0, 40.5, 0.5);
      EXPECT_NEAR(after / mass, 1.0, 1e-9);
    }
  }
}

TEST(StableFluids, DensityConservedInASwirlWithClosedWalls)
{
  // 500 steps of the whole solver in a swirling, divergence-free flow, no sources, no buoyancy:
  // the conservative scalars keep the total to rounding (plain tracing changed it by 520 %).
  for (bool conservative : { true })
  {
    StableFluidsParameters p;
    p.resolution[0] = p.resolution[1] = p.resolution[2] = 24;
    p.cellSize = 0.1;
    p.buoyancyDensity = p.buoyancyHeat = 0.0;
    p.conservative = conservative;
    StableFluids fluid(p);
    StaggeredGrid& g = fluid.grid();
    randomVelocity(g, 9);
    project(g, 1.0);
    const double c[3] = { 12.0, 12.0, 12.0 };
    blob(g, c, 4.0);
    const double mass = fluid.totalDensity();
    const double dt = 1.0 * p.cellSize / maxSpeed(g);
    for (int s = 0; s < 500; ++s)
    {
      fluid.step(dt);
    }
    const double drift = fluid.totalDensity() / mass - 1.0;
    std::printf("%s: total density changed by %.3g %%\n", conservative ? "conservative" : "plain", 100.0 * drift);
    if (conservative)
    {
      EXPECT_LE(std::abs(drift), 0.01);
      EXPECT_LE(std::abs(drift), 1e-9);
    }
  }
}

TEST(StableFluids, MultigridPreconditionerNeedsFarFewerIterationsThanJacobi)
{
  int iterations[2];
  for (Preconditioner pre : { Preconditioner::Multigrid, Preconditioner::Jacobi })
  {
    StaggeredGrid g;
    g.resize(48, 40, 32, 0.05);
    randomVelocity(g, 3);
    ProjectionOptions options;
    options.tolerance = 1e-8;
    options.preconditioner = pre;
    const SolveReport report = project(g, 0.01, options);
    EXPECT_LE(report.residual, 1e-8);
    iterations[pre == Preconditioner::Jacobi] = report.iterations;
    const std::vector<double> div = divergence(g);
    EXPECT_LE(rms(div), 1e-6 * maxSpeed(g) / g.h);
  }
  std::printf("iterations to 1e-8: multigrid %d, Jacobi %d\n", iterations[0], iterations[1]);
  EXPECT_LE(4 * iterations[0], iterations[1]);
}

TEST(StableFluids, OpenFacesLetSmokeOutAndKeepTheFlowDivergenceFree)
{
  // An updraught through open top and bottom faces: the projection keeps it (no wall stops it)
  // and the smoke leaves through the top; with closed faces it stays in the box.
  for (bool open : { true, false })
  {
    StableFluidsParameters p;
    p.resolution[0] = p.resolution[1] = 12;
    p.resolution[2] = 24;
    p.cellSize = 0.1;
    p.buoyancyDensity = p.buoyancyHeat = 0.0;
    p.open[4] = p.open[5] = open;
    StableFluids fluid(p);
    StaggeredGrid& g = fluid.grid();
    std::fill(g.w.values.begin(), g.w.values.end(), 1.0);
    const double c[3] = { 6.0, 6.0, 12.0 };
    blob(g, c, 2.0);
    const double mass = fluid.totalDensity();
    for (int s = 0; s < 60; ++s)
    {
      fluid.step(0.05);
    }
    const double left = fluid.totalDensity() / mass;
    std::printf("%s: %.3f of the smoke left in the box, updraught %.3f m/s, last projection %d iterations\n",
                open ? "open" : "closed", left, g.w.at(6, 6, 12), fluid.lastProjection().iterations);
    EXPECT_LE(rms(divergence(g)), 1e-3 * 1.0 / g.h);
    if (open)
    {
      EXPECT_LT(left, 0.05);
      EXPECT_NEAR(g.w.at(6, 6, 12), 1.0, 0.05);
    }
    else
    {
      EXPECT_NEAR(left, 1.0, 1e-9);
      EXPECT_LT(std::abs(g.w.at(6, 6, 12)), 0.05);
    }
  }
}

TEST(StableFluids, StableAtTenTimesTheCflLimitWithoutGainingEnergy)
{
  StableFluidsParameters p;
  p.resolution[0] = p.resolution[1] = p.resolution[2] = 10;
  p.cellSize = 0.1;
  p.buoyancyDensity = p.buoyancyHeat = 0.0;
  p.projectionTolerance = 1e-6;
  StableFluids fluid(p);
  randomVelocity(fluid.grid(), 5);
  project(fluid.grid(), 1.0);
  const double energy = fluid.kineticEnergy();
  const double dt = 10.0 * p.cellSize / maxSpeed(fluid.grid());
  for (int s = 0; s < 2000; ++s)
  {
    fluid.step(dt);
    const double e = fluid.kineticEnergy();
    ASSERT_TRUE(std::isfinite(e)) << "step " << s;
    ASSERT_LE(e, energy * (1.0 + 1e-9)) << "step " << s;
  }
}

TEST(StableFluids, HotEmitterMakesAPlumeRise)
{
  StableFluidsParameters p;
  p.resolution[0] = p.resolution[1] = 16;
  p.resolution[2] = 32;
  p.cellSize = 0.1;
  p.emitter = true;
  const double box[6] = { 0.6, 1.0, 0.6, 1.0, 0.1, 0.4 };
  std::copy(box, box + 6, p.emitterBox);
  StableFluids fluid(p);
  for (int s = 0; s < 60; ++s)
  {
    fluid.step(0.05);
  }
  // The density's centre of mass is above the emitter, and the air rises over it.
  double top = 0.0, weight = 0.0;
  const StaggeredGrid& g = fluid.grid();
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        top += (k + 0.5) * g.h * g.density.at(i, j, k);
        weight += g.density.at(i, j, k);
      }
  EXPECT_GT(top / weight, 0.5);
  EXPECT_GT(g.w.at(8, 8, 10), 0.0);
  EXPECT_LE(fluid.lastProjection().residual, p.projectionTolerance);
}

TEST(StableFluids, EmitterFillsExactlyTheCellsWhoseCentresLieInItsBox)
{
  // A box off the cell boundaries, away from the origin; after one vanishing step the density
  // is the emitter's in exactly the cells whose centres it holds.
  StableFluidsParameters p;
  p.resolution[0] = 13;
  p.resolution[1] = 11;
  p.resolution[2] = 9;
  p.cellSize = 0.1;
  p.origin[0] = -0.4;
  p.origin[1] = 0.2;
  p.origin[2] = 1.0;
  p.emitter = true;
  const double box[6] = { -0.17, 0.31, 0.52, 0.78, 1.26, 1.61 };
  std::copy(box, box + 6, p.emitterBox);
  p.emitterDensity = 2.0;
  StableFluids fluid(p);
  fluid.step(1e-9);
  const StaggeredGrid& g = fluid.grid();
  int filled = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        const double c[3] = { p.origin[0] + (i + 0.5) * p.cellSize, p.origin[1] + (j + 0.5) * p.cellSize,
                              p.origin[2] + (k + 0.5) * p.cellSize };
        const bool in =
          c[0] >= box[0] && c[0] <= box[1] && c[1] >= box[2] && c[1] <= box[3] && c[2] >= box[4] && c[2] <= box[5];
        EXPECT_NEAR(g.density.at(i, j, k), in ? 2.0 : 0.0, 1e-6) << i << " " << j << " " << k;
        filled += in;
      }
  EXPECT_EQ(filled, 5 * 3 * 3);
}

TEST(StableFluids, RejectsBadParametersByName)
{
  StableFluidsParameters p;
  p.resolution[1] = 1;
  try
  {
    StableFluids fluid(p);
    FAIL() << "a resolution of 1 was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("Resolution"), std::string::npos);
  }
  p.resolution[1] = 32;
  p.cellSize = std::nan("");
  EXPECT_THROW(StableFluids{ p }, std::invalid_argument);
  p.cellSize = 0.1;
  StableFluids fluid(p);
  EXPECT_THROW(fluid.step(0.0), std::invalid_argument);
  EXPECT_THROW(fluid.step(std::nan("")), std::invalid_argument);
}
