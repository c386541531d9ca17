#pragma once
// Particles on a cubic lattice filling a box: how SPH scenes (dam-break blocks, resting pools) are
// seeded. Points sit at cell centres, so a box of size L along an axis holds floor(L/spacing) layers.
#include <array>
#include <vector>

namespace parafluid
{
struct ParticleLattice
{
  std::vector<float> x, y, z;
  std::array<int, 3> counts = { 0, 0, 0 };
};

/// bounds = xmin,xmax,ymin,ymax,zmin,zmax [m]. Throws std::invalid_argument for a non-positive
/// spacing, inverted bounds, or more than maxParticles particles.
ParticleLattice fillBoxWithLattice(const std::array<double, 6>& bounds, double spacing,
                                   std::size_t maxParticles = 200'000'000);
} // namespace parafluid
