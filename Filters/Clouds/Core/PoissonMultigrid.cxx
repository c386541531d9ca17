#include "PoissonMultigrid.h"

#include <algorithm>
#include <cstddef>

namespace parafluid::clouds::detail
{
namespace
{
using Level = PoissonMultigrid::Level;

inline std::size_t at(const std::array<int, 3>& n, int i, int j, int k)
{
  return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i;
}

std::vector<unsigned char> diagonalOf(const std::array<int, 3>& n, const std::array<bool, 6>& open)
{
  std::vector<unsigned char> d(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
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

// Sum of the neighbours' x (missing neighbours, closed or open, add nothing).
inline double neighbourSum(const std::array<int, 3>& n, const double* x, int i, int j, int k, std::size_t c)
{
  const std::size_t sy = static_cast<std::size_t>(n[0]), sz = sy * n[1];
  double sum = 0.0;
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

// One Gauss-Seidel half sweep over the cells of one colour ((i + j + k) % 2 == colour).
void smooth(Level& l, int colour)
{
  const auto& n = l.n;
  double* x = l.x.data();
#pragma omp parallel for schedule(static)
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = (j + k + colour) & 1; i < n[0]; i += 2)
      {
        const std::size_t c = at(n, i, j, k);
        x[c] = (l.b[c] + neighbourSum(n, x, i, j, k, c)) / l.diagonal[c];
      }
    }
  }
}

void multiplyLevel(const Level& l, const double* x, double* y)
{
  const auto& n = l.n;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i)
      {
        const std::size_t c = at(n, i, j, k);
        y[c] = l.diagonal[c] * x[c] - neighbourSum(n, x, i, j, k, c);
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
    const std::size_t cells = static_cast<std::size_t>(n[0]) * n[1] * n[2];
    l.x.assign(cells, 0.0);
    l.b.assign(cells, 0.0);
    l.r.assign(cells, 0.0);
    l.diagonal = diagonalOf(n, open);
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
  multiplyLevel(this->Levels.front(), x.data(), y.data());
}

void PoissonMultigrid::apply(const std::vector<double>& r, std::vector<double>& z)
{
  Level& top = this->Levels.front();
  top.b = r;
  this->vcycle(0);
  z = top.x;
}

void PoissonMultigrid::vcycle(std::size_t index)
{
  Level& l = this->Levels[index];
  std::fill(l.x.begin(), l.x.end(), 0.0);
  if (index + 1 == this->Levels.size())
  {
    // The coarsest level: symmetric sweeps until the slowest mode has had time to settle.
    const int longest = std::max({ l.n[0], l.n[1], l.n[2] });
    const int sweeps = std::clamp(longest * longest, 4, 2000);
    for (int s = 0; s < sweeps; ++s)
    {
      smooth(l, 0);
      smooth(l, 1);
      smooth(l, 1);
      smooth(l, 0);
    }
    return;
  }
  constexpr int presmoothing = 2;
  for (int s = 0; s < presmoothing; ++s)
  {
    smooth(l, 0);
    smooth(l, 1);
  }
  multiplyLevel(l, l.x.data(), l.r.data());
  for (std::size_t c = 0; c < l.r.size(); ++c)
  {
    l.r[c] = l.b[c] - l.r[c];
  }
  // Restriction: the coarse equation is (2h)^2 times the Laplacian, so its right-hand side is
  // 4 times the children's mean, half their sum (missing children at odd edges count as zero,
  // which keeps restriction a multiple of prolongation's transpose and the cycle symmetric).
  Level& coarse = this->Levels[index + 1];
  const auto& n = l.n;
  const auto& m = coarse.n;
#pragma omp parallel for schedule(static)
  for (int K = 0; K < m[2]; ++K)
  {
    for (int J = 0; J < m[1]; ++J)
    {
      for (int I = 0; I < m[0]; ++I)
      {
        double sum = 0.0;
        for (int k = 2 * K; k < std::min(2 * K + 2, n[2]); ++k)
          for (int j = 2 * J; j < std::min(2 * J + 2, n[1]); ++j)
            for (int i = 2 * I; i < std::min(2 * I + 2, n[0]); ++i)
            {
              sum += l.r[at(n, i, j, k)];
            }
        coarse.b[at(m, I, J, K)] = 0.5 * sum;
      }
    }
  }
  this->vcycle(index + 1);
#pragma omp parallel for schedule(static)
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i)
      {
        l.x[at(n, i, j, k)] += coarse.x[at(m, i / 2, j / 2, k / 2)];
      }
    }
  }
  for (int s = 0; s < presmoothing; ++s)
  {
    smooth(l, 1);
    smooth(l, 0);
  }
}
} // namespace parafluid::clouds::detail
