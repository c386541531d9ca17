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
  closeWalls(g);
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
  EXPECT_LE(fluid.lastProjection().residual, 1e-8);
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
