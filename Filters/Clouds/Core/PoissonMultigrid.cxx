#include "PoissonMultigrid.h"

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

// One colour's Gauss-Seidel update ((i + j + k) % 2 == colour) on plane k: a colour reads only
// the other, so its cells can be updated in any order.
void smoothPlane(const Level& l, Real* x, const Real* b, int k, int colour)
{
  const auto& n = l.n;
  const Real* inverse = l.inverseDiagonal.data();
  for (int j = 0; j < n[1]; ++j)
  {
    forRow(n, x, j, k, (j + k + colour) & 1, 2,
           [&](std::size_t c, Real sum, bool inner) { x[c] = (b[c] + sum) * (inner ? Real(1) / 6 : inverse[c]); });
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
    const int begin = static_cast<int>(static_cast<long long>(nz) * thread / threads);
    const int end = static_cast<int>(static_cast<long long>(nz) * (thread + 1) / threads);
    for (int k = begin; k < end; ++k)
    {
      smoothPlane(l, x, b, k, first);
      if (k - 1 > begin)
      {
        smoothPlane(l, x, b, k - 1, second);
      }
    }
#pragma omp barrier
    if (begin < end)
    {
      smoothPlane(l, x, b, begin, second);
    }
    if (end - 1 > begin)
    {
      smoothPlane(l, x, b, end - 1, second);
    }
  }
}

// The coarse right-hand side from the residual r = b - A x, a row at a time (r is never stored):
// the coarse equation is (2h)^2 times the Laplacian, so it is 4 times the children's mean, half
// their sum (missing children at odd edges count as zero, which keeps restriction a multiple of
// prolongation's transpose and the cycle symmetric).
void restrictResidual(const Level& l, const Real* x, const Real* b, const std::array<int, 3>& m, Real* coarse)
{
  const auto& n = l.n;
  const unsigned char* d = l.diagonal.data();
#pragma omp parallel if (cellsOf(n) >= parallelCells)
  {
    std::vector<Real> r(static_cast<std::size_t>(n[0]));
#pragma omp for schedule(static)
    for (int K = 0; K < m[2]; ++K)
    {
      Real* plane = coarse + at(m, 0, 0, K);
      std::fill(plane, plane + static_cast<std::size_t>(m[0]) * m[1], Real(0));
      for (int k = 2 * K; k < std::min(2 * K + 2, n[2]); ++k)
      {
        for (int j = 0; j < n[1]; ++j)
        {
          const std::size_t row = at(n, 0, j, k);
          forRow(n, x, j, k, 0, 1,
                 [&](std::size_t c, Real sum, bool inner)
                 { r[c - row] = b[c] + sum - (inner ? Real(6) : static_cast<Real>(d[c])) * x[c]; });
          Real* out = plane + static_cast<std::size_t>(j / 2) * m[0];
          const int pairs = n[0] / 2;
          for (int I = 0; I < pairs; ++I)
          {
            out[I] += r[2 * I] + r[2 * I + 1];
          }
          if (n[0] & 1)
          {
            out[m[0] - 1] += r[n[0] - 1];
          }
        }
      }
      for (std::size_t c = 0; c < static_cast<std::size_t>(m[0]) * m[1]; ++c)
      {
        plane[c] *= Real(0.5);
      }
    }
  }
}

// x += the coarse correction, constant over each cell's children.
void prolongate(const std::array<int, 3>& n, Real* x, const std::array<int, 3>& m, const Real* coarse)
{
#pragma omp parallel for schedule(static) if (cellsOf(n) >= parallelCells)
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      Real* row = x + at(n, 0, j, k);
      const Real* parent = coarse + at(m, 0, j / 2, k / 2);
      for (int i = 0; i < n[0]; ++i)
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
    const std::size_t cells = cellsOf(n);
    l.x.assign(cells, Real(0));
    l.b.assign(cells, Real(0));
    l.diagonal = diagonalOf(n, open);
    l.inverseDiagonal.resize(cells);
    for (std::size_t c = 0; c < cells; ++c)
    {
      l.inverseDiagonal[c] = Real(1) / l.diagonal[c];
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
  const long long n = static_cast<long long>(r.size());
#pragma omp parallel for schedule(static)
  for (long long c = 0; c < n; ++c)
  {
    top.b[c] = static_cast<Real>(r[c]);
  }
  this->vcycle(0, top.x.data(), top.b.data());
  z.resize(r.size());
#pragma omp parallel for schedule(static)
  for (long long c = 0; c < n; ++c)
  {
    z[c] = top.x[c];
  }
}

void PoissonMultigrid::vcycle(std::size_t index, Real* x, const Real* b)
{
  Level& l = this->Levels[index];
  std::fill(x, x + cellsOf(l.n), Real(0));
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
  restrictResidual(l, x, b, coarse.n, coarse.b.data());
  this->vcycle(index + 1, coarse.x.data(), coarse.b.data());
  prolongate(l.n, x, coarse.n, coarse.x.data());
  for (int s = 0; s < presmoothing; ++s)
  {
    sweep(l, x, b, 1);
  }
}
} // namespace parafluid::clouds::detail
