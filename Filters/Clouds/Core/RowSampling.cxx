#include "RowSampling.h"

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

template<bool Range>
inline void readRowImpl(const RowLayout& l, const double* __restrict data, const double* __restrict x,
                        const double* __restrict y, const double* __restrict z, int count, double* __restrict out,
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
    if constexpr (Range)
    {
      double a = v000 < v100 ? v000 : v100, c = v010 < v110 ? v010 : v110;
      double d = v001 < v101 ? v001 : v101, e = v011 < v111 ? v011 : v111;
      a = a < c ? a : c;
      d = d < e ? d : e;
      lo[i] = a < d ? a : d;
      double A = v000 > v100 ? v000 : v100, C = v010 > v110 ? v010 : v110;
      double D = v001 > v101 ? v001 : v101, E = v011 > v111 ? v011 : v111;
      A = A > C ? A : C;
      D = D > E ? D : E;
      hi[i] = A > D ? A : D;
    }
  }
}
} // namespace

// Compiled for AVX-512, AVX2 and the baseline, chosen at load time (GCC's function multi-versioning).
__attribute__((target_clones("arch=skylake-avx512", "avx2", "default"))) void readRow(
  const RowLayout& layout, const double* data, const double* x, const double* y, const double* z, int count,
  double* out, double* lo, double* hi)
{
  if (lo && hi)
  {
    readRowImpl<true>(layout, data, x, y, z, count, out, lo, hi);
  }
  else
  {
    readRowImpl<false>(layout, data, x, y, z, count, out, nullptr, nullptr);
  }
}
} // namespace parafluid::clouds::detail
