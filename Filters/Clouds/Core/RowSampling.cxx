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
  AxisStep(int n, double offset_, int stride_)
    : offset(offset_)
    , last(n - 1)
    , lastCorner(n > 2 ? n - 2 : 0)
    , stride(n > 1 ? stride_ : 0)
  {
  }
};

// out[i] = data at point i; with Range also lo/hi of the 8 samples; with Second also out2[i] =
// data2 at the same point (its corners and weights found once for both).
template<bool Range, bool Second>
__attribute__((always_inline)) inline void readRowImpl(const RowLayout& l, const double* __restrict data,
                                                       const double* __restrict data2, const double* __restrict x,
                                                       const double* __restrict y, const double* __restrict z,
                                                       int count, double* __restrict out, double* __restrict out2,
                                                       double* __restrict lo, double* __restrict hi)
{
  const AxisStep ax(l.n[0], l.offset[0], 1), ay(l.n[1], l.offset[1], l.n[0]), az(l.n[2], l.offset[2], l.n[0] * l.n[1]);
  const int sx = ax.stride, sy = ay.stride, sz = az.stride;
#pragma omp simd
  for (int i = 0; i < count; ++i)
  {
    double px = x[i] - ax.offset, py = y[i] - ay.offset, pz = z[i] - az.offset;
    px = px < 0.0 ? 0.0 : (px > ax.last ? ax.last : px);
    py = py < 0.0 ? 0.0 : (py > ay.last ? ay.last : py);
    pz = pz < 0.0 ? 0.0 : (pz > az.last ? az.last : pz);
    int ix = static_cast<int>(px), iy = static_cast<int>(py), iz = static_cast<int>(pz);
    ix = ix > ax.lastCorner ? ax.lastCorner : ix;
    iy = iy > ay.lastCorner ? ay.lastCorner : iy;
    iz = iz > az.lastCorner ? az.lastCorner : iz;
    const double fx = px - ix, fy = py - iy, fz = pz - iz;
    const int b = ix + l.n[0] * (iy + l.n[1] * iz);
    const double v000 = data[b], v100 = data[b + sx], v010 = data[b + sy], v110 = data[b + sx + sy];
    const double v001 = data[b + sz], v101 = data[b + sx + sz], v011 = data[b + sy + sz], v111 = data[b + sx + sy + sz];
    const double x00 = v000 + fx * (v100 - v000), x10 = v010 + fx * (v110 - v010);
    const double x01 = v001 + fx * (v101 - v001), x11 = v011 + fx * (v111 - v011);
    const double y0 = x00 + fy * (x10 - x00), y1 = x01 + fy * (x11 - x01);
    out[i] = y0 + fz * (y1 - y0);
    if constexpr (Second)
    {
      const double w000 = data2[b], w100 = data2[b + sx], w010 = data2[b + sy], w110 = data2[b + sx + sy];
      const double w001 = data2[b + sz], w101 = data2[b + sx + sz], w011 = data2[b + sy + sz],
                   w111 = data2[b + sx + sy + sz];
      const double a00 = w000 + fx * (w100 - w000), a10 = w010 + fx * (w110 - w010);
      const double a01 = w001 + fx * (w101 - w001), a11 = w011 + fx * (w111 - w011);
      const double b0 = a00 + fy * (a10 - a00), b1 = a01 + fy * (a11 - a01);
      out2[i] = b0 + fz * (b1 - b0);
    }
    if constexpr (Range)
    {
      // The range of the second array's samples when there is one, else of the first's.
      const double* d = Second ? data2 : data;
      const double u000 = d[b], u100 = d[b + sx], u010 = d[b + sy], u110 = d[b + sx + sy];
      const double u001 = d[b + sz], u101 = d[b + sx + sz], u011 = d[b + sy + sz], u111 = d[b + sx + sy + sz];
      double a = u000 < u100 ? u000 : u100, c = u010 < u110 ? u010 : u110;
      double e = u001 < u101 ? u001 : u101, f = u011 < u111 ? u011 : u111;
      a = a < c ? a : c;
      e = e < f ? e : f;
      lo[i] = a < e ? a : e;
      double A = u000 > u100 ? u000 : u100, C = u010 > u110 ? u010 : u110;
      double E = u001 > u101 ? u001 : u101, F = u011 > u111 ? u011 : u111;
      A = A > C ? A : C;
      E = E > F ? E : F;
      hi[i] = A > E ? A : E;
    }
  }
}

// out (with lo, hi: the range) from data; the same for a pair of arrays.
__attribute__((always_inline)) inline void readRowBody(const RowLayout& layout, const double* data, const double* x,
                                                       const double* y, const double* z, int count, double* out,
                                                       double* lo, double* hi)
{
  if (lo && hi)
  {
    readRowImpl<true, false>(layout, data, nullptr, x, y, z, count, out, nullptr, lo, hi);
  }
  else
  {
    readRowImpl<false, false>(layout, data, nullptr, x, y, z, count, out, nullptr, nullptr, nullptr);
  }
}

__attribute__((always_inline)) inline void readRowPairBody(const RowLayout& layout, const double* data,
                                                           const double* data2, const double* x, const double* y,
                                                           const double* z, int count, double* out, double* out2,
                                                           double* lo2, double* hi2)
{
  if (lo2 && hi2)
  {
    readRowImpl<true, true>(layout, data, data2, x, y, z, count, out, out2, lo2, hi2);
  }
  else
  {
    readRowImpl<false, true>(layout, data, data2, x, y, z, count, out, out2, nullptr, nullptr);
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
