#include "RowSampling.h"

#include "parafluid/common/SimdDispatch.h"

namespace parafluid::clouds::detail
{
namespace
{
// The corner (clamped so that corner + 1 stays inside) and the fraction of p along one axis.
struct AxisStep
{
  double offset, last;
  int lastCorner, stride;
  __attribute__((always_inline)) AxisStep(int n, double offset_, int stride_)
    : offset(offset_)
    , last(n - 1)
    , lastCorner(n > 2 ? n - 2 : 0)
    , stride(n > 1 ? stride_ : 0)
  {
  }
  // The fraction of coordinate p (clamped to the array) past its lower corner, and that corner.
  __attribute__((always_inline)) double at(double p, int& corner) const
  {
    double c = p - offset;
    c = c < 0.0 ? 0.0 : (c > last ? last : c);
    const int i = static_cast<int>(c);
    corner = i > lastCorner ? lastCorner : i;
    return c - corner;
  }
};

// The eight samples of d at corners c0..c7 (x fastest, then y, then z).
struct Corners
{
  double v0, v1, v2, v3, v4, v5, v6, v7;
};

__attribute__((always_inline)) inline Corners loadCorners(const double* __restrict d, int c0, int c1, int c2, int c3,
                                                          int c4, int c5, int c6, int c7)
{
  return { d[c0], d[c1], d[c2], d[c3], d[c4], d[c5], d[c6], d[c7] };
}

// Their trilinear blend at fractions fx, fy, fz.
__attribute__((always_inline)) inline double blend(const Corners& c, double fx, double fy, double fz)
{
  const double x00 = c.v0 + fx * (c.v1 - c.v0), x10 = c.v2 + fx * (c.v3 - c.v2);
  const double x01 = c.v4 + fx * (c.v5 - c.v4), x11 = c.v6 + fx * (c.v7 - c.v6);
  const double y0 = x00 + fy * (x10 - x00), y1 = x01 + fy * (x11 - x01);
  return y0 + fz * (y1 - y0);
}

// Their least and greatest.
__attribute__((always_inline)) inline void rangeOf(const Corners& c, double& lo, double& hi)
{
  double a = c.v0 < c.v1 ? c.v0 : c.v1, b = c.v2 < c.v3 ? c.v2 : c.v3;
  double e = c.v4 < c.v5 ? c.v4 : c.v5, f = c.v6 < c.v7 ? c.v6 : c.v7;
  a = a < b ? a : b;
  e = e < f ? e : f;
  lo = a < e ? a : e;
  double A = c.v0 > c.v1 ? c.v0 : c.v1, B = c.v2 > c.v3 ? c.v2 : c.v3;
  double E = c.v4 > c.v5 ? c.v4 : c.v5, F = c.v6 > c.v7 ? c.v6 : c.v7;
  A = A > B ? A : B;
  E = E > F ? E : F;
  hi = A > E ? A : E;
}

// Which ranges a row read also finds.
enum class Ranges
{
  None,
  OfRead,  // lo/hi of the samples blended (data2's when there are two arrays, else data's)
  OfOthers // lo/hi of range's samples, lo2/hi2 of range2's, at the same corners
};

// A row's points are read in blocks of this many (their corners kept on the stack).
constexpr int Block = 256;

// The corners and fractions of a block's points: point i's first corner is base[i] (its others
// one stride on along each axis), its fractions fx[i], fy[i], fz[i].
struct BlockCorners
{
  int base[Block];
  double fx[Block], fy[Block], fz[Block];
};

// The first corner (as an index) and the fractions of each of count points: the reads' and the
// scatter's shared first step.
__attribute__((always_inline)) inline void cornersOfRowBody(const RowLayout& l, const double* __restrict x,
                                                            const double* __restrict y, const double* __restrict z,
                                                            int count, int* __restrict base, double* __restrict fx,
                                                            double* __restrict fy, double* __restrict fz)
{
  const AxisStep ax(l.n[0], l.offset[0], 1), ay(l.n[1], l.offset[1], l.n[0]), az(l.n[2], l.offset[2], l.n[0] * l.n[1]);
#pragma omp simd
  for (int i = 0; i < count; ++i)
  {
    int ix, iy, iz;
    fx[i] = ax.at(x[i], ix);
    fy[i] = ay.at(y[i], iy);
    fz[i] = az.at(z[i], iz);
    base[i] = ix + l.n[0] * (iy + l.n[1] * iz);
  }
}

// out[first + i] = data at block point i, and with Second also out2 = data2 there, with the
// ranges R asks for, for from <= i < to. With Run, the points' first corners are known to be
// `run` + i, one sample apart along the array: the compiler then fetches the corners of a vector
// of points with vector loads instead of gathers (in a smooth flow traced over a step of a cell
// or so, most of a row's points move alike and land in neighbouring cells).
template<bool Second, Ranges R, bool Run>
__attribute__((always_inline)) inline void readSpan(const RowLayout& l, const BlockCorners& c, int run, int from,
                                                    int to, int first, const double* __restrict data,
                                                    const double* __restrict data2, const double* __restrict range,
                                                    const double* __restrict range2, double* __restrict out,
                                                    double* __restrict out2, double* __restrict lo,
                                                    double* __restrict hi, double* __restrict lo2,
                                                    double* __restrict hi2)
{
  const int sx = l.n[0] > 1 ? 1 : 0, sy = l.n[1] > 1 ? l.n[0] : 0, sz = l.n[2] > 1 ? l.n[0] * l.n[1] : 0;
#pragma omp simd
  for (int i = from; i < to; ++i)
  {
    const int b = Run ? run + i : c.base[i];
    const double fx = c.fx[i], fy = c.fy[i], fz = c.fz[i];
    const int o = first + i;
    const int c1 = b + sx, c2 = b + sy, c3 = b + sx + sy, c4 = b + sz, c5 = b + sx + sz, c6 = b + sy + sz,
              c7 = b + sx + sy + sz;
    const Corners one = loadCorners(data, b, c1, c2, c3, c4, c5, c6, c7);
    out[o] = blend(one, fx, fy, fz);
    if constexpr (Second)
    {
      const Corners two = loadCorners(data2, b, c1, c2, c3, c4, c5, c6, c7);
      out2[o] = blend(two, fx, fy, fz);
      if constexpr (R == Ranges::OfRead)
        rangeOf(two, lo[o], hi[o]);
    }
    else if constexpr (R == Ranges::OfRead)
    {
      rangeOf(one, lo[o], hi[o]);
    }
    if constexpr (R == Ranges::OfOthers)
    {
      rangeOf(loadCorners(range, b, c1, c2, c3, c4, c5, c6, c7), lo[o], hi[o]);
      rangeOf(loadCorners(range2, b, c1, c2, c3, c4, c5, c6, c7), lo2[o], hi2[o]);
    }
  }
}

// A run shorter than this is read by gathers with its neighbours (a vector loop's start and
// masked tail cost more than the loads save).
constexpr int ShortestRun = 6;

// out[i] = data at point i, and with Second also out2[i] = data2 there, with the ranges R asks
// for (the corners and weights found once for all): block by block, the runs of points whose
// corners lie side by side by vector loads, the rest by gathers.
template<bool Second, Ranges R>
__attribute__((always_inline)) inline void readRowImpl(const RowLayout& l, const double* __restrict data,
                                                       const double* __restrict data2, const double* __restrict range,
                                                       const double* __restrict range2, const double* __restrict x,
                                                       const double* __restrict y, const double* __restrict z,
                                                       int count, double* __restrict out, double* __restrict out2,
                                                       double* __restrict lo, double* __restrict hi,
                                                       double* __restrict lo2, double* __restrict hi2)
{
  BlockCorners c;
  for (int first = 0; first < count; first += Block)
  {
    const int m = count - first < Block ? count - first : Block;
    cornersOfRowBody(l, x + first, y + first, z + first, m, c.base, c.fx, c.fy, c.fz);
    int gatherFrom = 0; // the first point not yet read
    for (int i = 0; i < m;)
    {
      const int run = c.base[i] - i;
      int end = i + 1;
      while (end < m && c.base[end] - end == run)
        ++end;
      if (end - i >= ShortestRun)
      {
        if (gatherFrom < i)
          readSpan<Second, R, false>(l, c, 0, gatherFrom, i, first, data, data2, range, range2, out, out2, lo, hi, lo2,
                                     hi2);
        readSpan<Second, R, true>(l, c, run, i, end, first, data, data2, range, range2, out, out2, lo, hi, lo2, hi2);
        gatherFrom = end;
      }
      i = end;
    }
    if (gatherFrom < m)
      readSpan<Second, R, false>(l, c, 0, gatherFrom, m, first, data, data2, range, range2, out, out2, lo, hi, lo2,
                                 hi2);
  }
}

// Four arrays of one layout: reads of data and data2, the ranges of range and range2.
__attribute__((always_inline)) inline void readRowPairRangedBody(const RowLayout& l, const double* data,
                                                                 const double* data2, const double* range,
                                                                 const double* range2, const double* x, const double* y,
                                                                 const double* z, int count, double* out, double* out2,
                                                                 double* lo, double* hi, double* lo2, double* hi2)
{
  readRowImpl<true, Ranges::OfOthers>(l, data, data2, range, range2, x, y, z, count, out, out2, lo, hi, lo2, hi2);
}

// out (with lo, hi: the range) from data; the same for a pair of arrays.
__attribute__((always_inline)) inline void readRowBody(const RowLayout& layout, const double* data, const double* x,
                                                       const double* y, const double* z, int count, double* out,
                                                       double* lo, double* hi)
{
  if (lo && hi)
  {
    readRowImpl<false, Ranges::OfRead>(layout, data, nullptr, nullptr, nullptr, x, y, z, count, out, nullptr, lo, hi,
                                       nullptr, nullptr);
  }
  else
  {
    readRowImpl<false, Ranges::None>(layout, data, nullptr, nullptr, nullptr, x, y, z, count, out, nullptr, nullptr,
                                     nullptr, nullptr, nullptr);
  }
}

__attribute__((always_inline)) inline void readRowPairBody(const RowLayout& layout, const double* data,
                                                           const double* data2, const double* x, const double* y,
                                                           const double* z, int count, double* out, double* out2,
                                                           double* lo2, double* hi2)
{
  if (lo2 && hi2)
  {
    readRowImpl<true, Ranges::OfRead>(layout, data, data2, nullptr, nullptr, x, y, z, count, out, out2, lo2, hi2,
                                      nullptr, nullptr);
  }
  else
  {
    readRowImpl<true, Ranges::None>(layout, data, data2, nullptr, nullptr, x, y, z, count, out, out2, nullptr, nullptr,
                                    nullptr, nullptr);
  }
}
} // namespace

// Compiled for AVX-512 (with gathers), AVX2 and the baseline, the widest picked at run time.
PARAFLUID_SIMD_DISPATCH(readRow,
                        (const RowLayout& layout, const double* data, const double* x, const double* y, const double* z,
                         int count, double* out, double* lo, double* hi),
                        (layout, data, x, y, z, count, out, lo, hi), readRowBody)

PARAFLUID_SIMD_DISPATCH(readRowPair,
                        (const RowLayout& layout, const double* data, const double* data2, const double* x,
                         const double* y, const double* z, int count, double* out, double* out2, double* lo2,
                         double* hi2),
                        (layout, data, data2, x, y, z, count, out, out2, lo2, hi2), readRowPairBody)

PARAFLUID_SIMD_DISPATCH(readRowPairRanged,
                        (const RowLayout& layout, const double* data, const double* data2, const double* range,
                         const double* range2, const double* x, const double* y, const double* z, int count,
                         double* out, double* out2, double* lo, double* hi, double* lo2, double* hi2),
                        (layout, data, data2, range, range2, x, y, z, count, out, out2, lo, hi, lo2, hi2),
                        readRowPairRangedBody)

PARAFLUID_SIMD_DISPATCH(cornersOfRow,
                        (const RowLayout& layout, const double* x, const double* y, const double* z, int count,
                         int* base, double* fx, double* fy, double* fz),
                        (layout, x, y, z, count, base, fx, fy, fz), cornersOfRowBody)

void scatterRow(const RowLayout& layout, const double* x, const double* y, const double* z, int count, int* base,
                double* fx, double* fy, double* fz, double* target)
{
  cornersOfRow(layout, x, y, z, count, base, fx, fy, fz);
  const int sx = layout.n[0] > 1 ? 1 : 0;
  const int sy = layout.n[1] > 1 ? layout.n[0] : 0;
  const int sz = layout.n[2] > 1 ? layout.n[0] * layout.n[1] : 0;
  for (int i = 0; i < count; ++i)
  {
    double* t = target + base[i];
    const double x1 = fx[i], x0 = 1.0 - x1, y1 = fy[i], y0 = 1.0 - y1, z1 = fz[i], z0 = 1.0 - z1;
    const double w00 = y0 * z0, w10 = y1 * z0, w01 = y0 * z1, w11 = y1 * z1;
    t[0] += w00 * x0;
    t[sx] += w00 * x1;
    t[sy] += w10 * x0;
    t[sy + sx] += w10 * x1;
    t[sz] += w01 * x0;
    t[sz + sx] += w01 * x1;
    t[sz + sy] += w11 * x0;
    t[sz + sy + sx] += w11 * x1;
  }
}

namespace
{
// The mean over Rows rows and Shifts shifts in one pass (each output written once).
template<int Rows, int Shifts>
__attribute__((always_inline)) inline void meanOf(const double* const* rows, const int* shifts, int first, int last,
                                                  double* __restrict out)
{
  constexpr double weight = 1.0 / (Rows * Shifts);
  const double* r[4] = { rows[0], rows[Rows > 1 ? 1 : 0], rows[Rows > 2 ? 2 : 0], rows[Rows > 3 ? 3 : 0] };
  const int a = shifts[0], b = shifts[Shifts > 1 ? 1 : 0];
  for (int i = first; i <= last; ++i)
  {
    double sum = r[0][i + a];
    if constexpr (Shifts > 1)
      sum += r[0][i + b];
    if constexpr (Rows > 1)
    {
      sum += r[1][i + a];
      if constexpr (Shifts > 1)
        sum += r[1][i + b];
    }
    if constexpr (Rows > 2)
    {
      sum += r[2][i + a] + r[3][i + a];
      if constexpr (Shifts > 1)
        sum += r[2][i + b] + r[3][i + b];
    }
    out[i] = weight * sum;
  }
}

__attribute__((always_inline)) inline void meanOfShiftedRowsBody(const double* const* rows, int rowCount,
                                                                 const int* shifts, int shiftCount, int first, int last,
                                                                 double* out)
{
  const bool two = shiftCount == 2;
  switch (rowCount)
  {
    case 1:
      two ? meanOf<1, 2>(rows, shifts, first, last, out) : meanOf<1, 1>(rows, shifts, first, last, out);
      break;
    case 2:
      two ? meanOf<2, 2>(rows, shifts, first, last, out) : meanOf<2, 1>(rows, shifts, first, last, out);
      break;
    default: // 4 (three distinct rows cannot occur: the rows pair up along y and z)
      two ? meanOf<4, 2>(rows, shifts, first, last, out) : meanOf<4, 1>(rows, shifts, first, last, out);
      break;
  }
}
} // namespace

PARAFLUID_SIMD_DISPATCH(meanOfShiftedRows,
                        (const double* const* rows, int rowCount, const int* shifts, int shiftCount, int first,
                         int last, double* out),
                        (rows, rowCount, shifts, shiftCount, first, last, out), meanOfShiftedRowsBody)
} // namespace parafluid::clouds::detail
