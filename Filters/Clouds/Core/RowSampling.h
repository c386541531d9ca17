#pragma once
// Trilinear reads of one grid array at a row of points, the advection's inner loop, written so
// that the compiler vectorises it and compiled for AVX-512, AVX2 and the baseline, the widest
// picked at run time. The eight samples of a read are fetched by vector loads along runs of
// points whose corners lie side by side (most of a row traced through a smooth flow), by gathers
// elsewhere: the loads made the 128^3 step of the stable fluids 1.3-1.4x faster. Points are in
// cell units (x / h from the grid's origin) and clamped at the array's ends, as DirectSampler
// reads them.
#include "parafluid/clouds/StaggeredGrid.h"

namespace parafluid::clouds::detail
{
struct RowLayout
{
  int n[3];
  double offset[3];
  explicit RowLayout(const GridArray& a)
    : n{ a.dims[0], a.dims[1], a.dims[2] }
    , offset{ a.offset[0], a.offset[1], a.offset[2] }
  {
  }
};

/// out[i] = `data` (laid out as `layout`) read at (x[i], y[i], z[i]), i < count; with lo and hi
/// (both or neither) also the least and greatest of the eight samples it blended.
void readRow(const RowLayout& layout, const double* data, const double* x, const double* y, const double* z, int count,
             double* out, double* lo = nullptr, double* hi = nullptr);
/// The same for two arrays of one layout at once (the corners and weights found once): out from
/// `data`, out2 from `data2`, and with lo2 and hi2 the range of data2's samples.
void readRowPair(const RowLayout& layout, const double* data, const double* data2, const double* x, const double* y,
                 const double* z, int count, double* out, double* out2, double* lo2 = nullptr, double* hi2 = nullptr);
/// Two reads and two ranges at the same points: out from `data`, out2 from `data2`, and lo, hi
/// (lo2, hi2) the least and greatest of the eight samples of `range` (`range2`) a read blends.
void readRowPairRanged(const RowLayout& layout, const double* data, const double* data2, const double* range,
                       const double* range2, const double* x, const double* y, const double* z, int count, double* out,
                       double* out2, double* lo, double* hi, double* lo2, double* hi2);
/// The transpose of readRow: target[corner] += its weight in a read at point i, for the eight
/// corners of each of the count points (clamped at the array's ends as the reads are). base, fx,
/// fy, fz: buffers of count values (the corners and fractions, found in vectors first).
void scatterRow(const RowLayout& layout, const double* x, const double* y, const double* z, int count, int* base,
                double* fx, double* fy, double* fz, double* target);
/// out[i] = the mean of rows[r][i + shifts[s]] over the rowCount rows and shiftCount shifts, for i
/// from first to last (inclusive): the velocity at a row's samples from the faces around them.
void meanOfShiftedRows(const double* const* rows, int rowCount, const int* shifts, int shiftCount, int first, int last,
                       double* out);
} // namespace parafluid::clouds::detail
