#pragma once
// Trilinear sampling of a GridArray at a point given in cell units (x / h from the grid's
// origin), the inner loop of the advection: the 8 corners and weights are found once and can be
// applied to several arrays of the same layout (density and temperature share their trace).
#include "RowSampling.h"
#include "parafluid/clouds/StaggeredGrid.h"

#include <algorithm>
#include <cstddef>

namespace parafluid::clouds::detail
{
struct Trilinear
{
  std::size_t index[8];
  double weight[8];
  /// Weight that fell outside the array across an open face (read as the ambient value).
  double outside = 0.0;

  double apply(const double* data) const
  {
    double sum = 0.0;
    for (int c = 0; c < 8; ++c)
    {
      sum += weight[c] * data[index[c]];
    }
    return sum;
  }
  void range(const double* data, double& lo, double& hi) const
  {
    lo = hi = data[index[0]];
    for (int c = 1; c < 8; ++c)
    {
      lo = std::min(lo, data[index[c]]);
      hi = std::max(hi, data[index[c]]);
    }
  }
};

/// Corners and weights of `a` at p (cell units), clamped at the array's ends: the hot path.
inline Trilinear locateClamped(const GridArray& a, const double p[3])
{
  int base[3];
  double frac[3];
  std::size_t step[3];
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(a.dims[0]),
                                  static_cast<std::size_t>(a.dims[0]) * static_cast<std::size_t>(a.dims[1]) };
  for (int axis = 0; axis < 3; ++axis)
  {
    const int n = a.dims[axis];
    const double c = std::clamp(p[axis] - a.offset[axis], 0.0, static_cast<double>(n - 1));
    base[axis] = std::min(static_cast<int>(c), std::max(n - 2, 0));
    frac[axis] = c - base[axis];
    step[axis] = n > 1 ? stride[axis] : 0;
  }
  Trilinear t;
  const std::size_t origin = base[0] + stride[1] * base[1] + stride[2] * base[2];
  const double fx = frac[0], fy = frac[1], fz = frac[2];
  const double wy[2] = { 1.0 - fy, fy }, wz[2] = { 1.0 - fz, fz };
  for (int c = 0; c < 8; ++c)
  {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    t.index[c] = origin + dx * step[0] + dy * step[1] + dz * step[2];
    t.weight[c] = (dx ? fx : 1.0 - fx) * wy[dy] * wz[dz];
  }
  t.outside = 0.0;
  return t;
}

/// Corners and weights of `a` at p (cell units). Beyond the samples the array is clamped (its
/// edge value continues), except across the faces flagged in `open` (xmin, xmax, ...) when given:
/// there a point more than half a cell outside the last sample weighs `outside` instead.
inline Trilinear locate(const GridArray& a, const double p[3], const bool* open = nullptr)
{
  if (!open)
  {
    return locateClamped(a, p);
  }
  int base[3], next[3];
  double frac[3], inside[3][2];
  for (int axis = 0; axis < 3; ++axis)
  {
    const int n = a.dims[axis];
    const double s = p[axis] - a.offset[axis];
    inside[axis][0] = inside[axis][1] = 1.0;
    const double c = std::clamp(s, 0.0, static_cast<double>(n - 1));
    base[axis] = std::min(static_cast<int>(c), std::max(n - 2, 0));
    next[axis] = std::min(base[axis] + 1, n - 1);
    frac[axis] = n > 1 ? c - base[axis] : 0.0;
    if (open)
    {
      // Ambient outside an open face: the weight of the missing sample beyond the edge.
      if (open[2 * axis] && s < 0.0)
      {
        frac[axis] = 0.0;
        inside[axis][0] = std::max(0.0, 1.0 + s);
      }
      else if (open[2 * axis + 1] && s > n - 1)
      {
        frac[axis] = 1.0;
        inside[axis][1] = std::max(0.0, 1.0 - (s - (n - 1)));
      }
    }
  }
  Trilinear t;
  double total = 0.0;
  const std::size_t sy = static_cast<std::size_t>(a.dims[0]), sz = sy * static_cast<std::size_t>(a.dims[1]);
  for (int c = 0; c < 8; ++c)
  {
    const int d[3] = { c & 1, (c >> 1) & 1, (c >> 2) & 1 };
    double w = 1.0;
    std::size_t idx = 0;
    const std::size_t stride[3] = { 1, sy, sz };
    for (int axis = 0; axis < 3; ++axis)
    {
      w *= (d[axis] ? frac[axis] : 1.0 - frac[axis]) * inside[axis][d[axis]];
      idx += stride[axis] * static_cast<std::size_t>(d[axis] ? next[axis] : base[axis]);
    }
    t.index[c] = idx;
    t.weight[c] = w;
    total += w;
  }
  t.outside = 1.0 - total;
  return t;
}

/// The hot path of the advection: trilinear reads of one array at points in cell units, clamped
/// at its ends, the 8 samples blended directly (no corner list); optionally their range.
class DirectSampler
{
public:
  explicit DirectSampler(const GridArray& a)
    : Data(a.values.data())
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      N[axis] = a.dims[axis];
      Offset[axis] = a.offset[axis];
    }
    Stride[0] = 1;
    Stride[1] = static_cast<std::size_t>(N[0]);
    Stride[2] = Stride[1] * static_cast<std::size_t>(N[1]);
  }
  /// Reads `data` (laid out like the array given to the constructor) at p.
  double at(const double* data, const double p[3], double* lo = nullptr, double* hi = nullptr) const
  {
    std::size_t base = 0, step[3];
    double f[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      const int n = N[axis];
      const double c = std::min(std::max(p[axis] - Offset[axis], 0.0), static_cast<double>(n - 1));
      const int i = std::min(static_cast<int>(c), std::max(n - 2, 0));
      f[axis] = c - i;
      base += Stride[axis] * static_cast<std::size_t>(i);
      step[axis] = n > 1 ? Stride[axis] : 0;
    }
    const double* d = data + base;
    const double v000 = d[0], v100 = d[step[0]], v010 = d[step[1]], v110 = d[step[0] + step[1]];
    const double v001 = d[step[2]], v101 = d[step[0] + step[2]], v011 = d[step[1] + step[2]],
                 v111 = d[step[0] + step[1] + step[2]];
    if (lo)
    {
      *lo = std::min(std::min(std::min(v000, v100), std::min(v010, v110)),
                     std::min(std::min(v001, v101), std::min(v011, v111)));
      *hi = std::max(std::max(std::max(v000, v100), std::max(v010, v110)),
                     std::max(std::max(v001, v101), std::max(v011, v111)));
    }
    const double x00 = v000 + f[0] * (v100 - v000), x10 = v010 + f[0] * (v110 - v010);
    const double x01 = v001 + f[0] * (v101 - v001), x11 = v011 + f[0] * (v111 - v011);
    const double y0 = x00 + f[1] * (x10 - x00), y1 = x01 + f[1] * (x11 - x01);
    return y0 + f[2] * (y1 - y0);
  }
  double at(const double p[3], double* lo = nullptr, double* hi = nullptr) const { return at(Data, p, lo, hi); }
  /// Calls f(index, weight) for the 8 corners around p (clamped at the ends as at() reads them):
  /// the scatter that is at()'s transpose.
  template<class F>
  void forCorners(const double p[3], F&& f) const
  {
    std::size_t base = 0, step[3];
    double w[3][2];
    for (int axis = 0; axis < 3; ++axis)
    {
      const int n = N[axis];
      const double c = std::min(std::max(p[axis] - Offset[axis], 0.0), static_cast<double>(n - 1));
      const int i = std::min(static_cast<int>(c), std::max(n - 2, 0));
      w[axis][1] = c - i;
      w[axis][0] = 1.0 - w[axis][1];
      base += Stride[axis] * static_cast<std::size_t>(i);
      step[axis] = n > 1 ? Stride[axis] : 0;
    }
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
      {
        const std::size_t row = base + dy * step[1] + dz * step[2];
        const double wyz = w[1][dy] * w[2][dz];
        f(row, wyz * w[0][0]);
        f(row + step[0], wyz * w[0][1]);
      }
  }
  /// Whether p lies more than half a cell beyond one of the `open` faces (there the ambient
  /// value weighs in: the generic locate() handles it).
  bool beyond(const double p[3], const bool* open) const
  {
    if (!open)
    {
      return false;
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      const double s = p[axis] - Offset[axis];
      if ((open[2 * axis] && s < 0.0) || (open[2 * axis + 1] && s > N[axis] - 1))
      {
        return true;
      }
    }
    return false;
  }

private:
  const double* Data;
  int N[3];
  double Offset[3];
  std::size_t Stride[3];
};

/// The velocity [m/s] at p (cell units).
inline void velocityAt(const StaggeredGrid& g, const double p[3], double v[3])
{
  v[0] = locateClamped(g.u, p).apply(g.u.values.data());
  v[1] = locateClamped(g.v, p).apply(g.v.values.data());
  v[2] = locateClamped(g.w, p).apply(g.w.values.data());
}

/// The velocity [m/s] at the samples of an array laid out as `a` (a face array or the cells), a
/// row at a time: the trilinear value there, the mean of the one, two or four samples of each
/// component around it (clamped at the box). The inner samples of a row run as plain sums of
/// shifted rows, which the compiler vectorises.
class RowVelocity
{
public:
  RowVelocity(const StaggeredGrid& g, const GridArray& a)
    : Faces{ &g.u, &g.v, &g.w }
    , Dims(a.dims)
  {
    for (int c = 0; c < 3; ++c)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        // Along each axis the two samples of component c around a's sample: (idx - 1, idx)
        // when a lies half a cell above c's samples, (idx, idx + 1) half a cell below, else idx.
        const double d = a.offset[axis] - Faces[c]->offset[axis];
        Low[c][axis] = d < 0.0 ? -1 : 0;
        High[c][axis] = d > 0.0 ? 1 : 0;
      }
    }
  }
  /// v[c][i] for the samples i of row (j, k), c = 0, 1, 2; each v[c] holds dims[0] values.
  void row(int j, int k, double* const v[3]) const
  {
    for (int c = 0; c < 3; ++c)
    {
      const GridArray& f = *Faces[c];
      const int fx = f.dims[0];
      const int j0 = clampTo(j + Low[c][1], f.dims[1]), j1 = clampTo(j + High[c][1], f.dims[1]);
      const int k0 = clampTo(k + Low[c][2], f.dims[2]), k1 = clampTo(k + High[c][2], f.dims[2]);
      const double* r00 = &f.values[f.index(0, j0, k0)];
      const double* r10 = &f.values[f.index(0, j1, k0)];
      const double* r01 = &f.values[f.index(0, j0, k1)];
      const double* r11 = &f.values[f.index(0, j1, k1)];
      const int a = Low[c][0], b = High[c][0];
      double* out = v[c];
      auto edge = [&](int i)
      {
        const int i0 = clampTo(i + a, fx), i1 = clampTo(i + b, fx);
        out[i] = 0.125 * (r00[i0] + r00[i1] + r10[i0] + r10[i1] + r01[i0] + r01[i1] + r11[i0] + r11[i1]);
      };
      // Samples whose neighbours need no clamp along x: the mean of the distinct rows and shifts
      // (the same as the eight-sample mean, whose repeats come in equal numbers).
      const int first = std::min(-a, Dims[0]), last = std::max(std::min(Dims[0] - 1, fx - 1 - b), first - 1);
      for (int i = 0; i < first; ++i)
        edge(i);
      const double* rows[4] = { r00 };
      int rowCount = 1;
      for (const double* r : { r10, r01, r11 })
      {
        if (std::find(rows, rows + rowCount, r) == rows + rowCount)
          rows[rowCount++] = r;
      }
      const int shifts[2] = { a, b };
      meanOfShiftedRows(rows, rowCount, shifts, a == b ? 1 : 2, first, last, out);
      for (int i = last + 1; i < Dims[0]; ++i)
        edge(i);
    }
  }

private:
  static int clampTo(int i, int n) { return std::min(std::max(i, 0), n - 1); }
  const GridArray* Faces[3];
  std::array<int, 3> Dims;
  int Low[3][3], High[3][3];
};

} // namespace parafluid::clouds::detail
