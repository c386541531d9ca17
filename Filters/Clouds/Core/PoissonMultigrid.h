#pragma once
// A geometric multigrid V-cycle for the pressure's Poisson equation on a box of cells, used as
// the preconditioner of conjugate gradients (MGPCG, McAdams, Sifakis & Teran 2010): red-black
// Gauss-Seidel smoothing (red then black before the coarse correction, black then red after, so
// the cycle is a symmetric operator), cells merged 2 x 2 x 2 per level down to 4 per axis,
// piecewise-constant transfer. The operator on every level is h^2 times the negative Laplacian:
// (A x)_c = sum over the neighbours n of (x_c - x_n), plus x_c per open face (zero pressure
// beyond it); closed faces add nothing (zero normal derivative).
//
// Precision: the cycle runs in single precision (it is a preconditioner: CG's own vectors and
// residual stay in double, so the solve still reaches double-precision tolerances), which halves
// the memory each sweep streams.
//
// Speed: the cycle's arrays carry a layer of ghost cells that stay 0, so every cell takes one
// branch-free stencil; a sweep runs both colours in one pass over the planes; the small levels
// run on one thread (forking costs more than they do).
#include <array>
#include <vector>

namespace parafluid::clouds::detail
{
class PoissonMultigrid
{
public:
  /// `maxLevels` 1 builds the operator alone (no cycle), as the diffusion solve needs.
  PoissonMultigrid(const std::array<int, 3>& dims, const std::array<bool, 6>& open, int maxLevels = 32);
  /// z = one V-cycle from zero applied to r.
  void apply(const std::vector<double>& r, std::vector<double>& z);
  /// y = A x on the finest level.
  void multiply(const std::vector<double>& x, std::vector<double>& y) const;
  /// y = A x and the dot product x . y, in one pass.
  double multiplyDot(const std::vector<double>& x, std::vector<double>& y) const;
  const std::vector<unsigned char>& diagonal() const { return this->Levels.front().diagonal; }
  int levels() const { return static_cast<int>(this->Levels.size()); }
  /// Whether this hierarchy is the one for `dims` and `open` (a solver keeps it between steps).
  bool matches(const std::array<int, 3>& dims, const std::array<bool, 6>& open) const
  {
    return this->Levels.front().n == dims && this->Open == open;
  }

  using Real = float;
  struct Level
  {
    std::array<int, 3> n;
    std::vector<Real> x, b;
    std::vector<unsigned char> diagonal; // A's diagonal (neighbours + open faces), 1 to 6
    // The cycle's arrays: (n + 2)^3, with a layer of ghost cells that stay 0.
    std::vector<Real> inverseDiagonal, paddedDiagonal; // the diagonal and its inverse
  };

private:
  void vcycle(std::size_t level, Real* x, const Real* b);
  std::array<bool, 6> Open;
  std::vector<Level> Levels;
};
} // namespace parafluid::clouds::detail
