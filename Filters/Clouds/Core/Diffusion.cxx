// Implicit diffusion (backward Euler) of a field on its own samples, by Jacobi-preconditioned CG:
// the system I + a L (a = coefficient dt / h^2) is diagonally dominant, so few iterations do.
#include "ConjugateGradients.h"
#include "PoissonMultigrid.h"
#include "parafluid/clouds/GridSolvers.h"

namespace parafluid::clouds
{
SolveReport diffuse(GridArray& field, double h, double coefficient, double dt, double tolerance, int maxIterations)
{
  const double a = coefficient * dt / (h * h);
  if (!(a > 0.0))
  {
    return {};
  }
  // Neumann ends: the Poisson operator with every face closed.
  const detail::PoissonMultigrid laplacian(field.dims, { false, false, false, false, false, false }, 1);
  std::vector<double> diagonal(laplacian.diagonal().begin(), laplacian.diagonal().end());
  for (double& value : diagonal)
  {
    value = 1.0 + a * value;
  }
  std::vector<double> x = field.values;
  const SolveReport report = detail::conjugateGradients(
    [&](const std::vector<double>& in, std::vector<double>& out)
    {
      laplacian.multiply(in, out);
      for (std::size_t i = 0; i < in.size(); ++i)
      {
        out[i] = in[i] + a * out[i];
      }
    },
    [&](const std::vector<double>& r, std::vector<double>& z)
    {
      for (std::size_t i = 0; i < r.size(); ++i)
      {
        z[i] = r[i] / diagonal[i];
      }
    },
    field.values, x, tolerance, maxIterations, false);
  field.values = std::move(x);
  return report;
}
} // namespace parafluid::clouds
