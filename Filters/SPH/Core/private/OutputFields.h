#pragma once
// Internal to the SPH core: the optional output fields over a state sorted by a neighbour grid's
// cells (the CPU simulation's own grid, or one built for another backend's state: OutputFields.cxx).
#include "parafluid/common/NeighbourGrid.h"
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"

#include <cstdint>
#include <vector>

namespace parafluid::sph::detail
{
/// See SPHSolver::smoothedPressure; s in the grid's sorted order.
std::vector<float> smoothedPressureOnGrid(const NeighbourGrid& grid, const ParticleState& s, const SPHParameters& p);
/// See SPHSolver::neighbourCounts; s in the grid's sorted order.
std::vector<std::uint32_t> neighbourCountsOnGrid(const NeighbourGrid& grid, const ParticleState& s,
                                                 const SPHParameters& p);
} // namespace parafluid::sph::detail
