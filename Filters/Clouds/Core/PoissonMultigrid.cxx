#include "PoissonMultigrid.h"

#include "parafluid/common/SimdDispatch.h"

#include <algorithm>
#include <cstddef>

#include <omp.h>

namespace parafluid::clouds::detail
{
namespace
{
using Level = PoissonMultigrid::Level;
using Real = PoissonMultigrid::Real;

// Levels of fewer cells run on one thread: a fork and join costs more than their sweep.
constexpr std::size_t parallelCells = 16384;

inline std::size_t at(const std::array<int, 3>& n, int i, int j, int k)
{
  return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i;
}

inline std::size_t cellsOf(const std::array<int, 3>& n)
{
  return static_cast<std::size_t>(n[0]) * n[1] * n[2];
}

std::vector<unsigned char> diagonalOf(const std::array<int, 3>& n, const std::array<bool, 6>& open)
{
  std::vector<unsigned char> d(cellsOf(n));
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const int idx[3] = { i, j, k };
        int count = 0;
        for (int axis = 0; axis < 3; ++axis)
        {
          count += idx[axis] > 0 ? 1 : open[2 * axis];
          count += idx[axis] < n[axis] - 1 ? 1 : open[2 * axis + 1];
        }
        d[at(n, i, j, k)] = static_cast<unsigned char>(std::max(count, 1));
      }
  return d;
}

// Sum of the neighbours' x (missing neighbours, closed or open, add nothing): the general stencil
// of the box's outer rows and the rows' ends.
template<class T>
inline T neighbourSum(const std::array<int, 3>& n, const T* x, int i, int j, int k, std::size_t c)
{
  const std::size_t sy = static_cast<std::size_t>(n[0]), sz = sy * n[1];
  T sum = 0;
  if (i > 0)
    sum += x[c - 1];
  if (i < n[0] - 1)
    sum += x[c + 1];
  if (j > 0)
    sum += x[c - sy];
  if (j < n[1] - 1)
    sum += x[c + sy];
  if (k > 0)
    sum += x[c - sz];
  if (k < n[2] - 1)
    sum += x[c + sz];
  return sum;
}

// Calls body(c, sum, inner) for the cells of row (j, k) from i = first in steps of `stride`, sum
// being the sum of c's neighbours in x; `inner`: all six present (the diagonal is 6). The inner
// cells of the inner rows, nearly all of them, take no branch.
template<class T, class Body>
inline void forRow(const std::array<int, 3>& n, const T* x, int j, int k, int first, int stride, Body&& body)
{
  const std::size_t sy = static_cast<std::size_t>(n[0]), sz = sy * n[1];
  const std::size_t row = at(n, 0, j, k);
  int i = first;
  const bool inner = j > 0 && j < n[1] - 1 && k > 0 && k < n[2] - 1 && n[0] > 2;
  if (!inner)
  {
    for (; i < n[0]; i += stride)
      body(row + i, neighbourSum(n, x, i, j, k, row + i), false);
    return;
  }
  if (i == 0)
  {
    body(row, neighbourSum(n, x, 0, j, k, row), false);
    i += stride;
  }
  for (; i < n[0] - 1; i += stride)
  {
    const std::size_t c = row + i;
    body(c, x[c - 1] + x[c + 1] + x[c - sy] + x[c + sy] + x[c - sz] + x[c + sz], true);
  }
  if (i == n[0] - 1)
  {
    body(row + i, neighbourSum(n, x, i, j, k, row + i), false);
  }
}

// The cycle's arrays carry a layer of ghost cells around the box, always 0: a missing neighbour,
// behind a closed face or an open one, adds nothing to the sum (the diagonal counts the open faces
// and leaves out the closed ones), so every cell takes the same branch-free stencil.
inline std::size_t padded(const Level& l, int i, int j, int k)
{
  return (static_cast<std::size_t>(k + 1) * (l.n[1] + 2) + (j + 1)) * (l.n[0] + 2) + (i + 1);
}

inline std::size_t paddedCells(const std::array<int, 3>& n)
{
  return static_cast<std::size_t>(n[0] + 2) * (n[1] + 2) * (n[2] + 2);
}

// The Gauss-Seidel value of every cell of a padded row (x, b and the inverse diagonal from the
// row's first cell): contiguous, so it runs in vector registers (AVX-512, AVX2 copies); a colour
// reads only the other colour, so the values of one colour's cells are those of the update.
__attribute__((always_inline)) inline void relaxedRowBody(const Real* __restrict x, const Real* __restrict b,
                                                          const Real* __restrict inverse, std::size_t sy,
                                                          std::size_t sz, int count, Real* __restrict out)
{
#pragma omp simd
  for (int i = 0; i < count; ++i)
  {
    out[i] = (b[i] + x[i - 1] + x[i + 1] + x[i - sy] + x[i + sy] + x[i - sz] + x[i + sz]) * inverse[i];
  }
}
PARAFLUID_SIMD_DISPATCH(relaxedRow,
                        (const Real* __restrict x, const Real* __restrict b, const Real* __restrict inverse,
                         std::size_t sy, std::size_t sz, int count, Real* __restrict out),
                        (x, b, inverse, sy, sz, count, out), relaxedRowBody)

// One colour's Gauss-Seidel update ((i + j + k) % 2 == colour) on plane k: a colour reads only
// the other, so its cells can be updated in any order. Each row is relaxed whole (twice the
// arithmetic, but in vectors: the V-cycle at 64^3 took 2.0 ms instead of 3.5 with the strided
// scalar loop) and its colour's cells written back. `relaxed` holds n[0] values.
void smoothPlane(const Level& l, Real* x, const Real* b, int k, int colour, Real* relaxed)
{
  const std::size_t sy = static_cast<std::size_t>(l.n[0] + 2), sz = sy * (l.n[1] + 2);
  const Real* inverse = l.inverseDiagonal.data();
  for (int j = 0; j < l.n[1]; ++j)
  {
    const std::size_t row = padded(l, 0, j, k);
    Real* xr = x + row;
    relaxedRow(xr, b + row, inverse + row, sy, sz, l.n[0], relaxed);
    for (int i = (j + k + colour) & 1; i < l.n[0]; i += 2)
    {
      xr[i] = relaxed[i];
    }
  }
}

// One Gauss-Seidel sweep, colour `first` then the other, in one pass over the planes: plane k's
// first colour, then plane k - 1's second (which reads planes k - 2 to k, whose first colour is
// done by then), so each plane comes from memory once instead of twice. The threads take blocks of
// planes; the second colour of a block's two end planes, which reads the neighbouring blocks'
// first colour, waits until every block has done its first. The result is that of two half
// sweeps, on any number of threads.
void sweep(const Level& l, Real* x, const Real* b, int first)
{
  const int nz = l.n[2], second = 1 - first;
#pragma omp parallel if (cellsOf(l.n) >= parallelCells)
  {
    const int threads = omp_get_num_threads(), thread = omp_get_thread_num();
    std::vector<Real> relaxed(static_cast<std::size_t>(l.n[0]));
    const int begin = static_cast<int>(static_cast<long long>(nz) * thread / threads);
    const int end = static_cast<int>(static_cast<long long>(nz) * (thread + 1) / threads);
    for (int k = begin; k < end; ++k)
    {
      smoothPlane(l, x, b, k, first, relaxed.data());
      if (k - 1 > begin)
      {
        smoothPlane(l, x, b, k - 1, second, relaxed.data());
      }
    }
#pragma omp barrier
    if (begin < end)
    {
      smoothPlane(l, x, b, begin, second, relaxed.data());
    }
    if (end - 1 > begin)
    {
      smoothPlane(l, x, b, end - 1, second, relaxed.data());
    }
  }
}

// The coarse right-hand side from the residual r = b - A x, a row at a time (r is never stored):
// the coarse equation is (2h)^2 times the Laplacian, so it is 4 times the children's mean, half
// their sum (missing children at odd edges count as zero, which keeps restriction a multiple of
// prolongation's transpose and the cycle symmetric).
void restrictResidual(const Level& l, const Real* x, const Real* b, const Level& coarse, Real* coarseB)
{
  const auto& n = l.n;
  const auto& m = coarse.n;
  const std::size_t sy = static_cast<std::size_t>(n[0] + 2), sz = sy * (n[1] + 2);
  const Real* diagonal = l.paddedDiagonal.data();
#pragma omp parallel if (cellsOf(n) >= parallelCells)
  {
    std::vector<Real> r(static_cast<std::size_t>(n[0]) + 1);
#pragma omp for schedule(static)
    for (int K = 0; K < m[2]; ++K)
    {
      for (int J = 0; J < m[1]; ++J)
      {
        Real* out = coarseB + padded(coarse, 0, J, K);
        std::fill(out, out + m[0], Real(0));
      }
      for (int k = 2 * K; k < std::min(2 * K + 2, n[2]); ++k)
      {
        for (int j = 0; j < n[1]; ++j)
        {
          const std::size_t row = padded(l, 0, j, k);
          const Real* xr = x + row;
          const Real* br = b + row;
          const Real* dr = diagonal + row;
          for (int i = 0; i < n[0]; ++i)
          {
            r[i] = br[i] + (xr[i - 1] + xr[i + 1] + xr[i - sy] + xr[i + sy] + xr[i - sz] + xr[i + sz]) - dr[i] * xr[i];
          }
          r[n[0]] = 0; // the missing child of an odd row's last pair
          Real* out = coarseB + padded(coarse, 0, j / 2, K);
          for (int I = 0; I < m[0]; ++I)
          {
            out[I] += r[2 * I] + r[2 * I + 1];
          }
        }
      }
      for (int J = 0; J < m[1]; ++J)
      {
        Real* out = coarseB + padded(coarse, 0, J, K);
        for (int I = 0; I < m[0]; ++I)
        {
          out[I] *= Real(0.5);
        }
      }
    }
  }
}

// x += the coarse correction, constant over each cell's children.
void prolongate(const Level& l, Real* x, const Level& coarse, const Real* coarseX)
{
#pragma omp parallel for schedule(static) if (cellsOf(l.n) >= parallelCells)
  for (int k = 0; k < l.n[2]; ++k)
  {
    for (int j = 0; j < l.n[1]; ++j)
    {
      Real* row = x + padded(l, 0, j, k);
      const Real* parent = coarseX + padded(coarse, 0, j / 2, k / 2);
      for (int i = 0; i < l.n[0]; ++i)
      {
        row[i] += parent[i >> 1];
      }
    }
  }
}
} // namespace

PoissonMultigrid::PoissonMultigrid(const std::array<int, 3>& dims, const std::array<bool, 6>& open, int maxLevels)
  : Open(open)
{
  std::array<int, 3> n = dims;
  for (;;)
  {
    Level l;
    l.n = n;
    l.diagonal = diagonalOf(n, open);
    const std::size_t withGhosts = paddedCells(n);
    l.x.assign(withGhosts, Real(0));
    l.b.assign(withGhosts, Real(0));
    l.inverseDiagonal.assign(withGhosts, Real(0));
    l.paddedDiagonal.assign(withGhosts, Real(0));
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
        {
          const Real d = l.diagonal[at(n, i, j, k)];
          l.paddedDiagonal[padded(l, i, j, k)] = d;
          l.inverseDiagonal[padded(l, i, j, k)] = Real(1) / d;
        }
    this->Levels.push_back(std::move(l));
    if (std::min({ n[0], n[1], n[2] }) <= 4 || static_cast<int>(this->Levels.size()) >= maxLevels)
    {
      break;
    }
    for (int& v : n)
    {
      v = (v + 1) / 2;
    }
  }
}

void PoissonMultigrid::multiply(const std::vector<double>& x, std::vector<double>& y) const
{
  this->multiplyDot(x, y);
}

double PoissonMultigrid::multiplyDot(const std::vector<double>& xv, std::vector<double>& yv) const
{
  const Level& l = this->Levels.front();
  const auto& n = l.n;
  const unsigned char* d = l.diagonal.data();
  const double* x = xv.data();
  double* y = yv.data();
  double dot = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : dot) if (cellsOf(n) >= parallelCells)
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      forRow(n, x, j, k, 0, 1,
             [&](std::size_t c, double sum, bool inner)
             {
               y[c] = (inner ? 6.0 : static_cast<double>(d[c])) * x[c] - sum;
               dot += x[c] * y[c];
             });
    }
  }
  return dot;
}

void PoissonMultigrid::apply(const std::vector<double>& r, std::vector<double>& z)
{
  Level& top = this->Levels.front();
  const auto& n = top.n;
  z.resize(r.size());
  const bool parallel = cellsOf(n) >= parallelCells;
#pragma omp parallel for schedule(static) if (parallel)
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
    {
      const double* in = &r[at(n, 0, j, k)];
      Real* out = &top.b[padded(top, 0, j, k)];
      for (int i = 0; i < n[0]; ++i)
        out[i] = static_cast<Real>(in[i]);
    }
  this->vcycle(0, top.x.data(), top.b.data());
#pragma omp parallel for schedule(static) if (parallel)
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
    {
      const Real* in = &top.x[padded(top, 0, j, k)];
      double* out = &z[at(n, 0, j, k)];
      for (int i = 0; i < n[0]; ++i)
        out[i] = in[i];
    }
}

void PoissonMultigrid::vcycle(std::size_t index, Real* x, const Real* b)
{
  Level& l = this->Levels[index];
  std::fill(x, x + paddedCells(l.n), Real(0));
  if (index + 1 == this->Levels.size())
  {
    // The coarsest level: symmetric sweeps until the slowest mode has had time to settle.
    const int longest = std::max({ l.n[0], l.n[1], l.n[2] });
    const int sweeps = std::clamp(longest * longest, 4, 2000);
    for (int s = 0; s < sweeps; ++s)
    {
      sweep(l, x, b, 0);
      sweep(l, x, b, 1);
    }
    return;
  }
  // Three sweeps each way: two needed 4-5 CG iterations (64^3, 128^3), three 3, at less time in all.
  constexpr int presmoothing = 3;
  for (int s = 0; s < presmoothing; ++s)
  {
    sweep(l, x, b, 0);
  }
  Level& coarse = this->Levels[index + 1];
  restrictResidual(l, x, b, coarse, coarse.b.data());
  this->vcycle(index + 1, coarse.x.data(), coarse.b.data());
  prolongate(l, x, coarse, coarse.x.data());
  for (int s = 0; s < presmoothing; ++s)
  {
    sweep(l, x, b, 1);
  }
}
} // namespace parafluid::clouds::detail
