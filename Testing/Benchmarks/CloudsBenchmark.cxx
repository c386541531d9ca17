// Stable fluids: time per step against grid size (split into forces, advection and projection)
// for a rising plume with vorticity confinement at a CFL number near 1; the projection's error
// against its iterations with the multigrid and the Jacobi preconditioner; and the same pressure
// solve by Eigen's ConjugateGradient (incomplete Cholesky and diagonal preconditioners) on the
// assembled 7-point matrix, the peer for "Eigen or the hand-written matrix-free CG".
// Run: build/bin/ParaFluidCloudsBenchmark [--quick | --steps | --grid N]
#include "parafluid/clouds/GridSolvers.h"
#include "parafluid/clouds/StableFluids.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace parafluid::clouds;

namespace
{
double now()
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

StableFluidsParameters plume(int n)
{
  StableFluidsParameters p;
  p.resolution[0] = p.resolution[1] = p.resolution[2] = n;
  p.cellSize = 1.0 / n;
  p.emitter = true;
  const double box[6] = { 0.4, 0.6, 0.4, 0.6, 0.05, 0.2 };
  std::copy(box, box + 6, p.emitterBox);
  p.emitterSpeed = 0.5;
  p.vorticity = 0.3;
  p.open[5] = true;
  return p;
}

double rms(const std::vector<double>& v)
{
  double s = 0.0;
  for (double x : v)
    s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

double velocityRms(const StaggeredGrid& g)
{
  double s = 0.0;
  std::size_t count = 0;
  for (const GridArray* f : { &g.u, &g.v, &g.w })
  {
    for (double x : f->values)
      s += x * x;
    count += f->values.size();
  }
  return std::sqrt(s / static_cast<double>(count));
}

void stepTimes(const std::vector<int>& sizes, bool plain)
{
  if (plain)
  {
    std::printf("\n## The same with plain semi-Lagrangian advection (no MacCormack, scalars not conserved), no "
                "vorticity confinement\n\n");
  }
  else
  {
    std::printf("\n## Time per step against grid size (plume, vorticity 0.3, MacCormack, conservative scalars, "
                "MGPCG to 1e-5, dt = h / 1 m/s)\n\n");
  }
  std::printf("| grid | ms/step, median (least) | forces | advection (of which scalars) | projection | projection "
              "iterations |\n|---|---|---|---|---|---|\n");
  auto median = [](std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  for (int n : sizes)
  {
    StableFluidsParameters p = plume(n);
    if (plain)
    {
      p.macCormack = p.conservative = false;
      p.vorticity = 0.0;
    }
    StableFluids fluid(p);
    const double dt = 1.0 / n;
    for (int s = 0; s < 20; ++s)
      fluid.step(dt); // the plume under way
    // The median of several steps: this machine's timings jump between runs and within one.
    const int steps = n >= 128 ? 7 : (n >= 96 ? 9 : 15);
    std::vector<double> total, forces, advection, scalars, projection;
    int iterations = 0;
    for (int s = 0; s < steps; ++s)
    {
      const double start = now();
      fluid.step(dt);
      total.push_back(now() - start);
      forces.push_back(fluid.lastTimings().forces);
      advection.push_back(fluid.lastTimings().advection);
      scalars.push_back(fluid.lastTimings().scalarAdvection);
      projection.push_back(fluid.lastTimings().projection);
      iterations += fluid.lastProjection().iterations;
    }
    std::printf("| %d^3 | %.1f (%.1f) | %.1f | %.1f (%.1f) | %.1f | %.1f |\n", n, median(total),
                *std::min_element(total.begin(), total.end()), median(forces), median(advection), median(scalars),
                median(projection), static_cast<double>(iterations) / steps);
  }
}

// The plume's velocity before a projection: the field every solve below starts from.
StaggeredGrid unprojected(int n, double& dt)
{
  StableFluids fluid(plume(n));
  dt = 1.0 / n;
  for (int s = 0; s < 20; ++s)
    fluid.step(dt);
  StaggeredGrid g = fluid.grid();
  // Buoyancy and a swirl's worth of divergence: what one step's forces and advection leave.
  for (std::size_t i = 0; i < g.w.values.size(); ++i)
    g.w.values[i] += 0.05 * std::sin(0.37 * static_cast<double>(i));
  setBoundaryVelocities(g);
  return g;
}

void projectionError(int n)
{
  double dt;
  const StaggeredGrid start = unprojected(n, dt);
  const double scale = velocityRms(start) / start.h;
  std::printf("\n## Projection error against iterations (%d^3, the plume's field, RMS divergence / (RMS velocity "
              "/ h))\n\n| iterations | multigrid | ms | Jacobi | ms |\n|---|---|---|---|---|\n",
              n);
  std::printf("| 0 | %.2e | | %.2e | |\n", rms(divergence(start)) / scale, rms(divergence(start)) / scale);
  for (int it : { 1, 2, 3, 4, 6, 8, 16, 32, 64, 128 })
  {
    double error[2], ms[2];
    for (int k = 0; k < 2; ++k)
    {
      StaggeredGrid g = start;
      ProjectionOptions o;
      o.tolerance = 1e-14;
      o.maxIterations = it;
      o.preconditioner = k == 0 ? Preconditioner::Multigrid : Preconditioner::Jacobi;
      const double t0 = now();
      project(g, dt, o);
      ms[k] = now() - t0;
      error[k] = rms(divergence(g)) / scale;
    }
    std::printf("| %d | %.2e | %.1f | %.2e | %.1f |\n", it, error[0], ms[0], error[1], ms[1]);
  }
}

void eigenPeer(int n)
{
  double dt;
  const StaggeredGrid start = unprojected(n, dt);
  const std::vector<double> div = divergence(start);
  const int cells = n * n * n;
  Eigen::VectorXd b(cells);
  double mean = 0.0;
  for (int c = 0; c < cells; ++c)
  {
    b[c] = -(start.h * start.h / dt) * div[c];
    mean += b[c];
  }
  b.array() -= mean / cells;
  // The 7-point matrix of h^2 times the negative Laplacian, walls closed except the open top
  // (zero pressure beyond it), as the projection solves it.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(7 * static_cast<std::size_t>(cells));
  auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        double diagonal = k == n - 1 ? 1.0 : 0.0; // the open top
        const int c = id(i, j, k);
        const int neighbours[6][3] = { { i - 1, j, k }, { i + 1, j, k }, { i, j - 1, k },
                                       { i, j + 1, k }, { i, j, k - 1 }, { i, j, k + 1 } };
        for (const auto& q : neighbours)
        {
          if (q[0] >= 0 && q[1] >= 0 && q[2] >= 0 && q[0] < n && q[1] < n && q[2] < n)
          {
            entries.emplace_back(c, id(q[0], q[1], q[2]), -1.0);
            diagonal += 1.0;
          }
        }
        entries.emplace_back(c, c, diagonal);
      }
  Eigen::SparseMatrix<double, Eigen::RowMajor> A(cells, cells);
  A.setFromTriplets(entries.begin(), entries.end());
  std::printf("\n## The pressure solve at %d^3: MGPCG (matrix-free) against Eigen's ConjugateGradient (assembled "
              "matrix)\n\n| solver | tolerance | iterations | ms (setup + solve) |\n|---|---|---|---|\n",
              n);
  for (double tolerance : { 1e-5, 1e-8 })
  {
    {
      StaggeredGrid g = start;
      ProjectionOptions o;
      o.tolerance = tolerance;
      const double t0 = now();
      const SolveReport r = project(g, dt, o);
      std::printf("| ParaFluid MGPCG | %.0e | %d | %.1f |\n", tolerance, r.iterations, now() - t0);
    }
    {
      StaggeredGrid g = start;
      ProjectionOptions o;
      o.tolerance = tolerance;
      o.preconditioner = Preconditioner::Jacobi;
      o.maxIterations = 5000;
      const double t0 = now();
      const SolveReport r = project(g, dt, o);
      std::printf("| ParaFluid Jacobi PCG | %.0e | %d | %.1f |\n", tolerance, r.iterations, now() - t0);
    }
    {
      const double t0 = now();
      Eigen::ConjugateGradient<decltype(A), Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>> cg;
      cg.setTolerance(tolerance);
      cg.setMaxIterations(5000);
      cg.compute(A);
      Eigen::VectorXd x = cg.solve(b);
      std::printf("| Eigen CG, diagonal | %.0e | %ld | %.1f |\n", tolerance, static_cast<long>(cg.iterations()),
                  now() - t0);
    }
    {
      const double t0 = now();
      Eigen::ConjugateGradient<decltype(A), Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> cg;
      cg.setTolerance(tolerance);
      cg.setMaxIterations(5000);
      cg.compute(A);
      Eigen::VectorXd x = cg.solve(b);
      std::printf("| Eigen CG, incomplete Cholesky | %.0e | %ld | %.1f |\n", tolerance,
                  static_cast<long>(cg.iterations()), now() - t0);
    }
  }
}
} // namespace

int main(int argc, char** argv)
{
  // --steps: the step times at 32^3 and 64^3 only; --grid N: at N^3 only.
  const bool grid = argc > 2 && std::strcmp(argv[1], "--grid") == 0;
  const bool steps = grid || (argc > 1 && std::strcmp(argv[1], "--steps") == 0);
  const bool quick = steps || (argc > 1 && std::strcmp(argv[1], "--quick") == 0);
  std::vector<int> sizes = quick ? std::vector<int>{ 32, 64 } : std::vector<int>{ 32, 48, 64, 96, 128 };
  if (grid)
  {
    sizes = { std::clamp(std::atoi(argv[2]), 2, 512) };
  }
  stepTimes(sizes, false);
  stepTimes(sizes, true);
  if (steps)
  {
    return 0;
  }
  projectionError(64);
  eigenPeer(quick ? 32 : 64);
  return 0;
}
