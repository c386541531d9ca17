#include "parafluid/clouds/GridSolvers.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace parafluid::clouds
{
double sampleTrilinear(const GridArray& a, const StaggeredGrid& grid, const double p[3], double* lo, double* hi)
{
  int base[3];
  double frac[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    const int n = a.dims[axis];
    double s = (p[axis] - grid.origin[axis]) / grid.h - a.offset[axis];
    s = std::clamp(s, 0.0, static_cast<double>(n - 1));
    base[axis] = std::min(static_cast<int>(s), std::max(n - 2, 0));
    frac[axis] = n > 1 ? s - base[axis] : 0.0;
  }
  double value = 0.0, smallest = 1e300, largest = -1e300;
  for (int corner = 0; corner < 8; ++corner)
  {
    const int d[3] = { corner & 1, (corner >> 1) & 1, (corner >> 2) & 1 };
    double weight = 1.0;
    int idx[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      idx[axis] = std::min(base[axis] + d[axis], a.dims[axis] - 1);
      weight *= d[axis] ? frac[axis] : 1.0 - frac[axis];
    }
    const double sample = a.at(idx[0], idx[1], idx[2]);
    value += weight * sample;
    smallest = std::min(smallest, sample);
    largest = std::max(largest, sample);
  }
  if (lo)
  {
    *lo = smallest;
  }
  if (hi)
  {
    *hi = largest;
  }
  return value;
}

void sampleVelocity(const StaggeredGrid& grid, const double p[3], double velocity[3])
{
  velocity[0] = sampleTrilinear(grid.u, grid, p);
  velocity[1] = sampleTrilinear(grid.v, grid, p);
  velocity[2] = sampleTrilinear(grid.w, grid, p);
}

namespace
{
// Where the flow at sample (i, j, k) of `a` came from dt ago (midpoint rule), and the value there.
double traceBack(const GridArray& source, const GridArray& a, const StaggeredGrid& grid, int i, int j, int k, double dt,
                 double* lo, double* hi)
{
  const double x[3] = { grid.origin[0] + grid.h * (i + a.offset[0]), grid.origin[1] + grid.h * (j + a.offset[1]),
                        grid.origin[2] + grid.h * (k + a.offset[2]) };
  double v0[3], mid[3], v1[3];
  sampleVelocity(grid, x, v0);
  for (int c = 0; c < 3; ++c)
  {
    mid[c] = x[c] - 0.5 * dt * v0[c];
  }
  sampleVelocity(grid, mid, v1);
  double back[3];
  for (int c = 0; c < 3; ++c)
  {
    back[c] = x[c] - dt * v1[c];
  }
  return sampleTrilinear(source, grid, back, lo, hi);
}
} // namespace

GridArray advect(const GridArray& field, const StaggeredGrid& grid, double dt, bool macCormack)
{
  GridArray forward = field;
  GridArray lo = field, hi = field;
  const int nx = field.dims[0], ny = field.dims[1], nz = field.dims[2];
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        forward.at(i, j, k) = traceBack(field, field, grid, i, j, k, dt, &lo.at(i, j, k), &hi.at(i, j, k));
      }
    }
  }
  if (!macCormack)
  {
    return forward;
  }
  GridArray result = forward;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        // Back along the flow the other way: the round trip's error is twice the forward's.
        const double roundTrip = traceBack(forward, field, grid, i, j, k, -dt, nullptr, nullptr);
        const double corrected = forward.at(i, j, k) + 0.5 * (field.at(i, j, k) - roundTrip);
        // Limited to the blended samples' range, so the correction cannot overshoot.
        result.at(i, j, k) = std::clamp(corrected, lo.at(i, j, k), hi.at(i, j, k));
      }
    }
  }
  return result;
}

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

void closeWalls(StaggeredGrid& g)
{
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
    {
      g.u.at(0, j, k) = 0.0;
      g.u.at(g.nx, j, k) = 0.0;
    }
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i)
    {
      g.v.at(i, 0, k) = 0.0;
      g.v.at(i, g.ny, k) = 0.0;
    }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
    {
      g.w.at(i, j, 0) = 0.0;
      g.w.at(i, j, g.nz) = 0.0;
    }
}

namespace
{
using Operator = std::function<void(const std::vector<double>&, std::vector<double>&)>;

double dot(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0.0;
  const long long n = static_cast<long long>(a.size());
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (long long i = 0; i < n; ++i)
  {
    sum += a[i] * b[i];
  }
  return sum;
}

// Preconditioned conjugate gradients for the SPD (or, with a consistent right-hand side,
// semi-definite) operator A with the diagonal `diagonal` as the preconditioner.
SolveReport conjugateGradients(const Operator& A, const std::vector<double>& diagonal, const std::vector<double>& b,
                               std::vector<double>& x, double tolerance, int maxIterations)
{
  const std::size_t n = b.size();
  std::vector<double> r(n), z(n), p(n), q(n);
  A(x, q);
  for (std::size_t i = 0; i < n; ++i)
  {
    r[i] = b[i] - q[i];
  }
  const double bNorm = std::sqrt(dot(b, b));
  SolveReport report;
  if (bNorm == 0.0)
  {
    std::fill(x.begin(), x.end(), 0.0);
    return report;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    z[i] = r[i] / diagonal[i];
  }
  p = z;
  double rz = dot(r, z);
  report.residual = std::sqrt(dot(r, r)) / bNorm;
  while (report.residual > tolerance && report.iterations < maxIterations)
  {
    A(p, q);
    const double alpha = rz / dot(p, q);
    for (std::size_t i = 0; i < n; ++i)
    {
      x[i] += alpha * p[i];
      r[i] -= alpha * q[i];
      z[i] = r[i] / diagonal[i];
    }
    const double rzNext = dot(r, z);
    for (std::size_t i = 0; i < n; ++i)
    {
      p[i] = z[i] + (rzNext / rz) * p[i];
    }
    rz = rzNext;
    ++report.iterations;
    report.residual = std::sqrt(dot(r, r)) / bNorm;
  }
  return report;
}

// sum over the existing neighbours of (x_c - x_n): the negative 7-point Laplacian times h^2, with
// Neumann ends (a missing neighbour contributes nothing). `count` gets the neighbour counts.
void negativeLaplacian(const std::array<int, 3>& d, const std::vector<double>& x, std::vector<double>& y)
{
  const int nx = d[0], ny = d[1], nz = d[2];
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t c = (static_cast<std::size_t>(k) * ny + j) * nx + i;
        double sum = 0.0;
        const double xc = x[c];
        if (i > 0)
          sum += xc - x[c - 1];
        if (i < nx - 1)
          sum += xc - x[c + 1];
        if (j > 0)
          sum += xc - x[c - nx];
        if (j < ny - 1)
          sum += xc - x[c + nx];
        if (k > 0)
          sum += xc - x[c - static_cast<std::size_t>(nx) * ny];
        if (k < nz - 1)
          sum += xc - x[c + static_cast<std::size_t>(nx) * ny];
        y[c] = sum;
      }
    }
  }
}

std::vector<double> neighbourCounts(const std::array<int, 3>& d)
{
  std::vector<double> count(static_cast<std::size_t>(d[0]) * d[1] * d[2]);
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        count[(static_cast<std::size_t>(k) * d[1] + j) * d[0] + i] =
          (i > 0) + (i < d[0] - 1) + (j > 0) + (j < d[1] - 1) + (k > 0) + (k < d[2] - 1);
      }
  return count;
}
} // namespace

SolveReport project(StaggeredGrid& g, double dt, double tolerance, int maxIterations)
{
  closeWalls(g);
  // New face velocity u - dt/h (p_right - p_left) makes each cell's outflow sum zero when
  // L p = -(h / dt) * outflow, L = sum over neighbours (p_c - p_n).
  const std::vector<double> div = divergence(g);
  std::vector<double> b(div.size());
  double mean = 0.0;
  for (std::size_t c = 0; c < div.size(); ++c)
  {
    b[c] = -(g.h * g.h / dt) * div[c];
    mean += b[c];
  }
  mean /= static_cast<double>(b.size());
  for (double& value : b)
  {
    value -= mean; // closed walls: consistent up to rounding
  }
  const std::array<int, 3> dims{ g.nx, g.ny, g.nz };
  std::vector<double> diagonal = neighbourCounts(dims);
  for (double& value : diagonal)
  {
    value = std::max(value, 1.0);
  }
  std::vector<double> p(b.size(), 0.0);
  const SolveReport report =
    conjugateGradients([&](const std::vector<double>& x, std::vector<double>& y) { negativeLaplacian(dims, x, y); },
                       diagonal, b, p, tolerance, maxIterations);
  const double scale = dt / g.h;
  const GridArray& cell = g.density;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < g.nz; ++k)
  {
    for (int j = 0; j < g.ny; ++j)
    {
      for (int i = 0; i < g.nx; ++i)
      {
        const double pc = p[cell.index(i, j, k)];
        if (i > 0)
          g.u.at(i, j, k) -= scale * (pc - p[cell.index(i - 1, j, k)]);
        if (j > 0)
          g.v.at(i, j, k) -= scale * (pc - p[cell.index(i, j - 1, k)]);
        if (k > 0)
          g.w.at(i, j, k) -= scale * (pc - p[cell.index(i, j, k - 1)]);
      }
    }
  }
  return report;
}

SolveReport diffuse(GridArray& field, double h, double coefficient, double dt, double tolerance, int maxIterations)
{
  const double a = coefficient * dt / (h * h);
  if (!(a > 0.0))
  {
    return {};
  }
  std::vector<double> diagonal = neighbourCounts(field.dims);
  for (double& value : diagonal)
  {
    value = 1.0 + a * value;
  }
  std::vector<double> x = field.values;
  const SolveReport report = conjugateGradients(
    [&](const std::vector<double>& in, std::vector<double>& out)
    {
      negativeLaplacian(field.dims, in, out);
      for (std::size_t i = 0; i < in.size(); ++i)
      {
        out[i] = in[i] + a * out[i];
      }
    },
    diagonal, field.values, x, tolerance, maxIterations);
  field.values = x;
  return report;
}
} // namespace parafluid::clouds
