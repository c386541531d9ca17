#include "BodyForces.h"

#include <algorithm>
#include <cmath>

namespace parafluid::clouds::detail
{
namespace
{
// out[i] = d row / dx at sample i (spacing h): central inside, one-sided at the ends, 0 for a
// single sample.
void derivativeAlong(const double* row, int n, double h, double* out)
{
  if (n < 2)
  {
    out[0] = 0.0;
    return;
  }
  out[0] = (row[1] - row[0]) / h;
  out[n - 1] = (row[n - 1] - row[n - 2]) / h;
  const double half = 0.5 / h;
  for (int i = 1; i < n - 1; ++i)
  {
    out[i] = (row[i + 1] - row[i - 1]) * half;
  }
}

// out[i] = (above[i] - below[i]) * inverseSpan: the derivative across rows.
void derivativeAcross(const double* below, const double* above, int n, double inverseSpan, double* out)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = (above[i] - below[i]) * inverseSpan;
  }
}

// The rows either side of row `at` along an axis of `count` rows (clamped) and 1 / (their distance
// in metres), 0 for a single row.
void neighbours(int at, int count, double h, int& below, int& above, double& inverseSpan)
{
  below = std::max(at - 1, 0);
  above = std::min(at + 1, count - 1);
  inverseSpan = above > below ? 1.0 / ((above - below) * h) : 0.0;
}

// The derivatives of cell array f along y and z at row (j, k) into dy and dz.
void derivativesAcross(const GridArray& cells, const std::vector<double>& f, int j, int k, double h, double* dy,
                       double* dz)
{
  const int nx = cells.dims[0];
  int below, above;
  double inverse;
  neighbours(j, cells.dims[1], h, below, above, inverse);
  derivativeAcross(&f[cells.index(0, below, k)], &f[cells.index(0, above, k)], nx, inverse, dy);
  neighbours(k, cells.dims[2], h, below, above, inverse);
  derivativeAcross(&f[cells.index(0, j, below)], &f[cells.index(0, j, above)], nx, inverse, dz);
}
} // namespace

void addCellValuesToFaces(const StaggeredGrid& g, GridArray& faces, int axis, const double* perCell, double scale,
                          bool interiorOnly)
{
  const GridArray& cells = g.density;
  const int nx = g.nx;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < faces.dims[2]; ++k)
  {
    for (int j = 0; j < faces.dims[1]; ++j)
    {
      double* out = &faces.values[faces.index(0, j, k)];
      if (axis == 0)
      {
        const double* cell = perCell + cells.index(0, j, k);
        for (int i = 1; i < nx; ++i)
        {
          out[i] += scale * 0.5 * (cell[i - 1] + cell[i]);
        }
        if (!interiorOnly)
        {
          out[0] += scale * cell[0];
          out[nx] += scale * cell[nx - 1];
        }
        continue;
      }
      // The cell rows below and above this row of faces along `axis` (y or z).
      const int at = axis == 1 ? j : k, count = cells.dims[axis];
      const double* below = nullptr;
      const double* above = nullptr;
      if (at > 0)
        below = perCell + (axis == 1 ? cells.index(0, j - 1, k) : cells.index(0, j, k - 1));
      if (at < count)
        above = perCell + cells.index(0, j, k);
      if (below && above)
      {
        for (int i = 0; i < nx; ++i)
        {
          out[i] += scale * 0.5 * (below[i] + above[i]);
        }
      }
      else if (!interiorOnly)
      {
        const double* one = below ? below : above;
        for (int i = 0; i < nx; ++i)
        {
          out[i] += scale * one[i];
        }
      }
    }
  }
}

void vorticityConfinementForce(const StaggeredGrid& g, double epsilon, ForceScratch& s)
{
  const GridArray& cells = g.density;
  const int nx = g.nx, ny = g.ny, nz = g.nz;
  const double h = g.h;
  const std::size_t n = g.cells();
  for (int a = 0; a < 3; ++a)
  {
    s.centre[a].resize(n);
    s.vorticity[a].resize(n);
    s.force[a].resize(n);
  }
  s.magnitude.resize(n);
  // Cell-centred velocity: the mean of each component's two faces.
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      const std::size_t row = cells.index(0, j, k);
      const double* u = &g.u.values[g.u.index(0, j, k)];
      const double* v0 = &g.v.values[g.v.index(0, j, k)];
      const double* v1 = &g.v.values[g.v.index(0, j + 1, k)];
      const double* w0 = &g.w.values[g.w.index(0, j, k)];
      const double* w1 = &g.w.values[g.w.index(0, j, k + 1)];
      for (int i = 0; i < nx; ++i)
      {
        s.centre[0][row + i] = 0.5 * (u[i] + u[i + 1]);
        s.centre[1][row + i] = 0.5 * (v0[i] + v1[i]);
        s.centre[2][row + i] = 0.5 * (w0[i] + w1[i]);
      }
    }
  }
  // omega = curl of the centred velocity, and its magnitude.
#pragma omp parallel
  {
    std::vector<double> rows(6 * static_cast<std::size_t>(nx));
    double *duy = rows.data(), *duz = duy + nx, *dvx = duz + nx, *dvz = dvx + nx, *dwx = dvz + nx, *dwy = dwx + nx;
    std::vector<double> unused(static_cast<std::size_t>(nx));
#pragma omp for schedule(static)
    for (int k = 0; k < nz; ++k)
    {
      for (int j = 0; j < ny; ++j)
      {
        const std::size_t row = cells.index(0, j, k);
        derivativesAcross(cells, s.centre[0], j, k, h, duy, duz);
        derivativesAcross(cells, s.centre[1], j, k, h, unused.data(), dvz);
        derivativesAcross(cells, s.centre[2], j, k, h, dwy, unused.data());
        derivativeAlong(&s.centre[1][row], nx, h, dvx);
        derivativeAlong(&s.centre[2][row], nx, h, dwx);
        double* ox = &s.vorticity[0][row];
        double* oy = &s.vorticity[1][row];
        double* oz = &s.vorticity[2][row];
        double* m = &s.magnitude[row];
        for (int i = 0; i < nx; ++i)
        {
          ox[i] = dwy[i] - dvz[i];
          oy[i] = duz[i] - dwx[i];
          oz[i] = dvx[i] - duy[i];
          m[i] = std::sqrt(ox[i] * ox[i] + oy[i] * oy[i] + oz[i] * oz[i]);
        }
      }
    }
  }
  // force = epsilon h (N x omega), N = grad |omega| / |grad |omega||.
  const double scale = epsilon * h;
#pragma omp parallel
  {
    std::vector<double> rows(3 * static_cast<std::size_t>(nx));
    double *gx = rows.data(), *gy = gx + nx, *gz = gy + nx;
#pragma omp for schedule(static)
    for (int k = 0; k < nz; ++k)
    {
      for (int j = 0; j < ny; ++j)
      {
        const std::size_t row = cells.index(0, j, k);
        derivativeAlong(&s.magnitude[row], nx, h, gx);
        derivativesAcross(cells, s.magnitude, j, k, h, gy, gz);
        const double* ox = &s.vorticity[0][row];
        const double* oy = &s.vorticity[1][row];
        const double* oz = &s.vorticity[2][row];
        double* fx = &s.force[0][row];
        double* fy = &s.force[1][row];
        double* fz = &s.force[2][row];
        for (int i = 0; i < nx; ++i)
        {
          const double length = std::sqrt(gx[i] * gx[i] + gy[i] * gy[i] + gz[i] * gz[i]);
          const double inverse = length < 1e-12 ? 0.0 : scale / length;
          const double Nx = gx[i] * inverse, Ny = gy[i] * inverse, Nz = gz[i] * inverse;
          fx[i] = Ny * oz[i] - Nz * oy[i];
          fy[i] = Nz * ox[i] - Nx * oz[i];
          fz[i] = Nx * oy[i] - Ny * ox[i];
        }
      }
    }
  }
}
} // namespace parafluid::clouds::detail
