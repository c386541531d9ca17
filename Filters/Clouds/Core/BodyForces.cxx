#include "BodyForces.h"

#include "parafluid/common/SimdDispatch.h"

#include <algorithm>
#include <cmath>

namespace parafluid::clouds::detail
{
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

namespace
{
// The cells either side of cell `at` along an axis of `count` cells (clamped at the walls) and
// 1 / their distance [1/m] (one-sided differences at the walls, 0 for a single cell).
struct Across
{
  int below, above;
  double inverse;
  Across(int at, int count, double h)
    : below(std::max(at - 1, 0))
    , above(std::min(at + 1, count - 1))
    , inverse(above > below ? 1.0 / ((above - below) * h) : 0.0)
  {
  }
};

// The derivative along a row of n samples [1/m]: central inside, one-sided at the ends.
template<class Value>
__attribute__((always_inline)) inline void alongRow(const Value* __restrict row, int n, double h,
                                                    double* __restrict out)
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

// A thread's row buffers for the vorticity confinement.
struct ConfinementRows
{
  explicit ConfinementRows(int n)
    : storage(10 * static_cast<std::size_t>(n))
  {
    double* p = storage.data();
    for (double** row : { &cv, &cw, &dvx, &dwx, &gx, &fx, &fy, &fz, &previousFy, &belowFz })
    {
      *row = p;
      p += n;
    }
  }
  std::vector<double> storage;
  double *cv, *cw, *dvx, *dwx, *gx, *fx, *fy, *fz, *previousFy, *belowFz;
};

// What the curl of one cell row reads and writes: the face rows either side of it along y and z
// (b: below, a: above), its own v and w face rows, the strides to the next v row along y and the
// next w row along z, half the inverse spans along y and z [1/m], the cell size [m].
struct CurlRow
{
  const double *uyb, *uya, *uzb, *uza, *vzb, *vza, *wyb, *wya, *vrow, *wrow;
  std::size_t vy, wz;
  double hy, hz, h;
  int nx;
  ConfinementRows* rows;
  float *ox, *oy, *oz, *magnitude;
};

__attribute__((always_inline)) inline void curlRowBody(const CurlRow& c)
{
  const int nx = c.nx;
  double* __restrict cv = c.rows->cv;
  double* __restrict cw = c.rows->cw;
  for (int i = 0; i < nx; ++i)
  {
    cv[i] = 0.5 * (c.vrow[i] + c.vrow[i + c.vy]);
    cw[i] = 0.5 * (c.wrow[i] + c.wrow[i + c.wz]);
  }
  double* __restrict dvx = c.rows->dvx;
  double* __restrict dwx = c.rows->dwx;
  alongRow(cv, nx, c.h, dvx);
  alongRow(cw, nx, c.h, dwx);
  const double* __restrict uyb = c.uyb, * __restrict uya = c.uya, * __restrict uzb = c.uzb, * __restrict uza = c.uza;
  const double* __restrict vzb = c.vzb, * __restrict vza = c.vza, * __restrict wyb = c.wyb, * __restrict wya = c.wya;
  float* __restrict ox = c.ox, * __restrict oy = c.oy, * __restrict oz = c.oz, * __restrict m = c.magnitude;
  const std::size_t vy = c.vy, wz = c.wz;
  const double hy = c.hy, hz = c.hz;
  for (int i = 0; i < nx; ++i)
  {
    const double duy = hy * ((uya[i] + uya[i + 1]) - (uyb[i] + uyb[i + 1]));
    const double duz = hz * ((uza[i] + uza[i + 1]) - (uzb[i] + uzb[i + 1]));
    const double dvz = hz * ((vza[i] + vza[i + vy]) - (vzb[i] + vzb[i + vy]));
    const double dwy = hy * ((wya[i] + wya[i + wz]) - (wyb[i] + wyb[i + wz]));
    const double a = dwy - dvz, b = duz - dwx[i], d = dvx[i] - duy;
    ox[i] = static_cast<float>(a);
    oy[i] = static_cast<float>(b);
    oz[i] = static_cast<float>(d);
    m[i] = static_cast<float>(std::sqrt(a * a + b * b + d * d)); // -fno-math-errno: vectorises
  }
}

PARAFLUID_SIMD_DISPATCH(curlOfRow, (const CurlRow& c), (c), curlRowBody)

// omega (the curl of the cell-centred velocity) and |omega| of cell row (j, k). The centred
// velocity is the mean of each component's two faces, taken where the differences need it
// instead of stored.
void curlRow(const StaggeredGrid& g, int j, int k, ConfinementRows& r, ForceScratch& s)
{
  const Across y(j, g.ny, g.h), z(k, g.nz, g.h);
  const double* u = &g.u.values[0];
  const double* v = &g.v.values[0];
  const double* w = &g.w.values[0];
  const std::size_t row = g.density.index(0, j, k);
  CurlRow c;
  c.uyb = u + g.u.index(0, y.below, k);
  c.uya = u + g.u.index(0, y.above, k);
  c.uzb = u + g.u.index(0, j, z.below);
  c.uza = u + g.u.index(0, j, z.above);
  c.vzb = v + g.v.index(0, j, z.below);
  c.vza = v + g.v.index(0, j, z.above);
  c.wyb = w + g.w.index(0, y.below, k);
  c.wya = w + g.w.index(0, y.above, k);
  c.vrow = v + g.v.index(0, j, k);
  c.wrow = w + g.w.index(0, j, k);
  c.vy = g.v.index(0, 1, 0);
  c.wz = g.w.index(0, 0, 1);
  c.hy = 0.5 * y.inverse;
  c.hz = 0.5 * z.inverse;
  c.h = g.h;
  c.nx = g.nx;
  c.rows = &r;
  c.ox = &s.vorticity[0][row];
  c.oy = &s.vorticity[1][row];
  c.oz = &s.vorticity[2][row];
  c.magnitude = &s.magnitude[row];
  curlOfRow(c);
}

// What the confinement force of one cell row reads: |omega| along the row and at the rows either
// side along y and z, the inverse spans [1/m], omega of the row; epsilon h.
struct ForceRow
{
  const float *m, *myb, *mya, *mzb, *mza, *ox, *oy, *oz;
  double inverseY, inverseZ, h, scale;
  int nx;
  ConfinementRows* rows;
};

__attribute__((always_inline)) inline void forceRowBody(const ForceRow& f)
{
  const int nx = f.nx;
  double* __restrict gxRow = f.rows->gx;
  alongRow(f.m, nx, f.h, gxRow);
  const float* __restrict myb = f.myb, * __restrict mya = f.mya, * __restrict mzb = f.mzb, * __restrict mza = f.mza;
  const float* __restrict ox = f.ox, * __restrict oy = f.oy, * __restrict oz = f.oz;
  double* __restrict fx = f.rows->fx, * __restrict fy = f.rows->fy, * __restrict fz = f.rows->fz;
  const double iy = f.inverseY, iz = f.inverseZ, scale = f.scale;
  for (int i = 0; i < nx; ++i)
  {
    const double gx = gxRow[i];
    const double gy = (double(mya[i]) - double(myb[i])) * iy;
    const double gz = (double(mza[i]) - double(mzb[i])) * iz;
    const double length = std::sqrt(gx * gx + gy * gy + gz * gz);
    const double inverse = length < 1e-12 ? 0.0 : scale / length;
    const double Nx = gx * inverse, Ny = gy * inverse, Nz = gz * inverse;
    fx[i] = Ny * oz[i] - Nz * oy[i];
    fy[i] = Nz * ox[i] - Nx * oz[i];
    fz[i] = Nx * oy[i] - Ny * ox[i];
  }
}

PARAFLUID_SIMD_DISPATCH(forceOfRow, (const ForceRow& f), (f), forceRowBody)

// The confinement force epsilon h (N x omega) of cell row (j, k) into r.fx, r.fy, r.fz,
// N = grad |omega| / |grad |omega||, zero where that gradient vanishes.
void forceRow(const StaggeredGrid& g, const ForceScratch& s, double scale, int j, int k, ConfinementRows& r)
{
  const GridArray& cells = g.density;
  const std::size_t row = cells.index(0, j, k);
  const Across y(j, g.ny, g.h), z(k, g.nz, g.h);
  const float* m = s.magnitude.data();
  ForceRow f;
  f.m = m + row;
  f.myb = m + cells.index(0, y.below, k);
  f.mya = m + cells.index(0, y.above, k);
  f.mzb = m + cells.index(0, j, z.below);
  f.mza = m + cells.index(0, j, z.above);
  f.ox = &s.vorticity[0][row];
  f.oy = &s.vorticity[1][row];
  f.oz = &s.vorticity[2][row];
  f.inverseY = y.inverse;
  f.inverseZ = z.inverse;
  f.h = g.h;
  f.scale = scale;
  f.nx = g.nx;
  f.rows = &r;
  forceOfRow(f);
}
} // namespace

void addVorticityConfinement(StaggeredGrid& g, double epsilon, double dt, ForceScratch& s)
{
  const int nx = g.nx, ny = g.ny, nz = g.nz;
  const std::size_t n = g.cells();
  for (int a = 0; a < 3; ++a)
  {
    s.vorticity[a].resize(n);
  }
  s.magnitude.resize(n);
  // 1. omega and |omega| per cell (single precision: they only steer the force's direction).
#pragma omp parallel
  {
    ConfinementRows r(nx);
#pragma omp for schedule(static)
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        curlRow(g, j, k, r, s);
  }
  // 2. The force of each cell row, onto the faces between cells as the mean of the two cells'
  // forces (the walls' faces are left alone). A row of faces is written by one iteration only:
  // the x faces of row (j, k) take cell row (j, k)'s force, its y faces also row (j - 1, k)'s
  // (the previous iteration's), its z faces row (j, k - 1)'s (worked out again here).
  const double scale = epsilon * g.h;
#pragma omp parallel
  {
    ConfinementRows r(nx);
#pragma omp for schedule(static)
    for (int k = 0; k < nz; ++k)
    {
      for (int j = 0; j < ny; ++j)
      {
        if (k > 0)
        {
          forceRow(g, s, scale, j, k - 1, r);
          std::copy(r.fz, r.fz + nx, r.belowFz);
        }
        forceRow(g, s, scale, j, k, r);
        double* u = &g.u.values[g.u.index(0, j, k)];
        for (int i = 1; i < nx; ++i)
        {
          u[i] += dt * 0.5 * (r.fx[i - 1] + r.fx[i]);
        }
        if (j > 0)
        {
          double* v = &g.v.values[g.v.index(0, j, k)];
          for (int i = 0; i < nx; ++i)
          {
            v[i] += dt * 0.5 * (r.previousFy[i] + r.fy[i]);
          }
        }
        if (k > 0)
        {
          double* w = &g.w.values[g.w.index(0, j, k)];
          for (int i = 0; i < nx; ++i)
          {
            w[i] += dt * 0.5 * (r.belowFz[i] + r.fz[i]);
          }
        }
        std::swap(r.previousFy, r.fy);
      }
    }
  }
}
} // namespace parafluid::clouds::detail
