#pragma once
// Preconditioned conjugate gradients, matrix-free: the operator and the preconditioner are
// callables y = f(x) over std::vector<double>. The projection (multigrid or Jacobi
// preconditioner) and the implicit diffusion (Jacobi) use it.
#include "parafluid/clouds/GridSolvers.h"

#include <array>
#include <functional>
#include <vector>

namespace parafluid::clouds::detail
{
using LinearMap = std::function<void(const std::vector<double>&, std::vector<double>&)>;
/// y = A x, returning x . y (one pass instead of two).
using LinearMapDot = std::function<double(const std::vector<double>&, std::vector<double>&)>;

/// Solves A x = b from the x given to a relative residual |b - A x| / max(|b|, scale) <=
/// tolerance (`scale` keeps a right-hand side at rounding level from asking the impossible). With
/// `removeMean` (a singular A whose null space is the constants, e.g. closed walls) the
/// preconditioned residual's mean is removed each iteration. `ADot`, when given, is A fused with
/// the dot product the iteration needs. `scratch`, when given, holds the four work vectors between
/// calls.
SolveReport conjugateGradients(const LinearMap& A, const LinearMap& preconditioner, const std::vector<double>& b,
                               std::vector<double>& x, double tolerance, int maxIterations, bool removeMean,
                               double scale = 0.0, const LinearMapDot& ADot = nullptr,
                               std::array<std::vector<double>, 4>* scratch = nullptr);
} // namespace parafluid::clouds::detail
