// The discrete divergence, the boundary velocities, and the pressure projection (MGPCG by default).
#include "ConjugateGradients.h"
#include "PoissonMultigrid.h"
#include "parafluid/clouds/GridSolvers.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace parafluid::clouds
{
std::vector<double> divergence(const StaggeredGrid& g)
{
  std::vector<double> div(g.cells());
#pragma omp parallel for schedule(static)
  for (int k = 0; k < g.nz; ++k)
  {
    for (int j = 0; j < g.ny; ++j)
    {
      for (int i = 0; i < g.nx; ++i)
      {
        div[g.density.index(i, j, k)] = (g.u.at(i + 1, j, k) - g.u.at(i, j, k) + g.v.at(i, j + 1, k) - g.v.at(i, j, k) +
                                         g.w.at(i, j, k + 1) - g.w.at(i, j, k)) /
                                        g.h;
      }
    }
  }
  return div;
}

void setBoundaryVelocities(StaggeredGrid& g)
{
  // Closed: no flow through the face. Open: the face's velocity continues the one inside it.
  auto set = [&](bool open, double& face, double inner) { face = open ? inner : 0.0; };
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
    {
      set(g.open[0], g.u.at(0, j, k), g.u.at(1, j, k));
      set(g.open[1], g.u.at(g.nx, j, k), g.u.at(g.nx - 1, j, k));
    }
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i)
    {
      set(g.open[2], g.v.at(i, 0, k), g.v.at(i, 1, k));
      set(g.open[3], g.v.at(i, g.ny, k), g.v.at(i, g.ny - 1, k));
    }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
    {
      set(g.open[4], g.w.at(i, j, 0), g.w.at(i, j, 1));
      set(g.open[5], g.w.at(i, j, g.nz), g.w.at(i, j, g.nz - 1));
    }
}

struct ProjectionWorkspace
{
  std::unique_ptr<detail::PoissonMultigrid> multigrid;
  std::vector<double> b;
  std::array<std::vector<double>, 4> cg; // the conjugate gradients' work vectors
  std::vector<double> previous;          // the pressure of the projection before the last (warm starts)
};

std::shared_ptr<ProjectionWorkspace> makeProjectionWorkspace()
{
  return std::make_shared<ProjectionWorkspace>();
}

SolveReport project(StaggeredGrid& g, double dt, const ProjectionOptions& options)
{
  setBoundaryVelocities(g);
  ProjectionWorkspace local;
  ProjectionWorkspace& work = options.workspace ? *options.workspace : local;
  const std::array<int, 3> dims{ g.nx, g.ny, g.nz };
  if (!work.multigrid || !work.multigrid->matches(dims, g.open))
  {
    work.multigrid = std::make_unique<detail::PoissonMultigrid>(dims, g.open);
  }
  detail::PoissonMultigrid& multigrid = *work.multigrid;
  // New face velocity u - dt/h (p_right - p_left) makes each cell's outflow sum zero when
  // A p = -(h^2 / dt) div, A = h^2 times the negative Laplacian (PoissonMultigrid's operator).
  const bool closed = !g.anyOpen();
  std::vector<double>& b = work.b;
  b.resize(g.cells());
  const double toRightSide = -g.h / dt; // -(h^2 / dt) times the divergence's 1 / h
  double mean = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : mean)
  for (int k = 0; k < g.nz; ++k)
  {
    for (int j = 0; j < g.ny; ++j)
    {
      const double* u = &g.u.values[g.u.index(0, j, k)];
      const double* vLow = &g.v.values[g.v.index(0, j, k)];
      const double* vHigh = &g.v.values[g.v.index(0, j + 1, k)];
      const double* wLow = &g.w.values[g.w.index(0, j, k)];
      const double* wHigh = &g.w.values[g.w.index(0, j, k + 1)];
      double* out = &b[g.density.index(0, j, k)];
      for (int i = 0; i < g.nx; ++i)
      {
        out[i] = toRightSide * (u[i + 1] - u[i] + vHigh[i] - vLow[i] + wHigh[i] - wLow[i]);
        mean += out[i];
      }
    }
  }
  mean /= static_cast<double>(b.size());
  if (closed)
  {
    for (double& value : b)
    {
      value -= mean; // closed walls: consistent up to rounding
    }
  }
  // Solved in place from zero, or (warm) from the last pressure; with a workspace that saw the
  // step before, from the pressure extrapolated linearly in time, 2 p_n - p_(n-1): the pressure of
  // a flow that changes smoothly moves smoothly, and the solve then starts nearer (the plume at
  // 64^3: 2 iterations instead of 4). It is only the first guess: CG still solves to the tolerance.
  std::vector<double>& p = g.pressure.values;
  p.resize(b.size());
  if (!options.warmStart)
  {
    std::fill(p.begin(), p.end(), 0.0);
    work.previous.clear();
  }
  else if (options.workspace && work.previous.size() == p.size())
  {
    const long long count = static_cast<long long>(p.size());
#pragma omp parallel for schedule(static)
    for (long long c = 0; c < count; ++c)
    {
      const double last = p[c];
      p[c] = 2.0 * last - work.previous[c];
      work.previous[c] = last;
    }
  }
  else if (options.workspace)
  {
    work.previous = p;
  }
  detail::LinearMap A = [&](const std::vector<double>& x, std::vector<double>& y) { multigrid.multiply(x, y); };
  detail::LinearMapDot ADot = [&](const std::vector<double>& x, std::vector<double>& y)
  { return multigrid.multiplyDot(x, y); };
  detail::LinearMap preconditioner;
  if (options.preconditioner == Preconditioner::Multigrid)
  {
    preconditioner = [&](const std::vector<double>& r, std::vector<double>& z) { multigrid.apply(r, z); };
  }
  else
  {
    // Jacobi: the diagonal (the neighbour count plus the open faces).
    std::vector<double> diagonal(multigrid.diagonal().begin(), multigrid.diagonal().end());
    preconditioner = [diagonal](const std::vector<double>& r, std::vector<double>& z)
    {
      for (std::size_t c = 0; c < r.size(); ++c)
      {
        z[c] = r[c] / diagonal[c];
      }
    };
  }
  // The scale of the right-hand side a velocity field of this size would make: a field already
  // nearly divergence-free is solved to the tolerance of that, not of its rounding errors.
  double speed2 = 0.0;
  for (const GridArray* f : { &g.u, &g.v, &g.w })
  {
    const double* values = f->values.data();
    const long long count = static_cast<long long>(f->values.size());
#pragma omp parallel for schedule(static) reduction(+ : speed2)
    for (long long c = 0; c < count; ++c)
    {
      speed2 += values[c] * values[c];
    }
  }
  const double scale = (g.h / dt) * std::sqrt(speed2 / 3.0);
  const SolveReport report = detail::conjugateGradients(A, preconditioner, b, p, options.tolerance,
                                                        options.maxIterations, closed, scale, ADot, &work.cg);
  const double step = dt / g.h;
  const GridArray& cell = g.density;
  const int nx = g.nx;
  // The pressure gradient across each face, a row at a time; beyond an open face the pressure is 0.
#pragma omp parallel for schedule(static)
  for (int k = 0; k < g.nz; ++k)
  {
    for (int j = 0; j < g.ny; ++j)
    {
      const double* pc = &p[cell.index(0, j, k)];
      double* u = &g.u.values[g.u.index(0, j, k)];
      for (int i = 1; i < nx; ++i)
        u[i] -= step * (pc[i] - pc[i - 1]);
      if (g.open[0])
        u[0] -= step * pc[0];
      if (g.open[1])
        u[nx] += step * pc[nx - 1];
      double* v = &g.v.values[g.v.index(0, j, k)];
      if (j > 0)
      {
        const double* below = &p[cell.index(0, j - 1, k)];
        for (int i = 0; i < nx; ++i)
          v[i] -= step * (pc[i] - below[i]);
      }
      else if (g.open[2])
      {
        for (int i = 0; i < nx; ++i)
          v[i] -= step * pc[i];
      }
      if (j == g.ny - 1 && g.open[3])
      {
        double* top = &g.v.values[g.v.index(0, g.ny, k)];
        for (int i = 0; i < nx; ++i)
          top[i] += step * pc[i];
      }
      double* w = &g.w.values[g.w.index(0, j, k)];
      if (k > 0)
      {
        const double* below = &p[cell.index(0, j, k - 1)];
        for (int i = 0; i < nx; ++i)
          w[i] -= step * (pc[i] - below[i]);
      }
      else if (g.open[4])
      {
        for (int i = 0; i < nx; ++i)
          w[i] -= step * pc[i];
      }
      if (k == g.nz - 1 && g.open[5])
      {
        double* top = &g.w.values[g.w.index(0, j, g.nz)];
        for (int i = 0; i < nx; ++i)
          top[i] += step * pc[i];
      }
    }
  }
  return report;
}

SolveReport project(StaggeredGrid& grid, double dt, double tolerance, int maxIterations)
{
  ProjectionOptions options;
  options.tolerance = tolerance;
  options.maxIterations = maxIterations;
  return project(grid, dt, options);
}
} // namespace parafluid::clouds
