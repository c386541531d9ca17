#include "parafluid/common/ParticleLattice.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace parafluid
{
ParticleLattice fillBoxWithLattice(const std::array<double, 6>& bounds, double spacing, std::size_t maxParticles)
{
  if (!std::isfinite(spacing) || !(spacing > 0.0))
  {
    throw std::invalid_argument("particle lattice: Spacing must be positive, got " + std::to_string(spacing));
  }
  ParticleLattice lattice;
  double total = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    const double lo = bounds[2 * a];
    const double hi = bounds[2 * a + 1];
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo)
    {
      throw std::invalid_argument("particle lattice: bounds must give min <= max on every axis");
    }
    // The tolerance keeps a box of exactly k spacings from losing its last layer to rounding; it is
    // wide enough for sizes that passed through single precision (relative error 6e-8 each).
    const double layers = std::floor((hi - lo) / spacing + 1e-5);
    total *= layers;
    lattice.counts[a] = static_cast<int>(std::min(layers, 2e9));
  }
  if (total > static_cast<double>(maxParticles))
  {
    throw std::invalid_argument("particle lattice: " + std::to_string(total) + " particles exceed the limit of " +
                                std::to_string(maxParticles) + "; increase Spacing or shrink the block");
  }
  const std::size_t n = static_cast<std::size_t>(total);
  lattice.x.reserve(n);
  lattice.y.reserve(n);
  lattice.z.reserve(n);
  for (int k = 0; k < lattice.counts[2]; ++k)
  {
    for (int j = 0; j < lattice.counts[1]; ++j)
    {
      for (int i = 0; i < lattice.counts[0]; ++i)
      {
        lattice.x.push_back(static_cast<float>(bounds[0] + (i + 0.5) * spacing));
        lattice.y.push_back(static_cast<float>(bounds[2] + (j + 0.5) * spacing));
        lattice.z.push_back(static_cast<float>(bounds[4] + (k + 0.5) * spacing));
      }
    }
  }
  return lattice;
}
} // namespace parafluid
