#pragma once
// The slabs of a distributed run (DistributedSimulation.h): cuts along one axis, placed so that
// each process's slab holds about as many particles, and who owns and who needs a coordinate.
#include "parafluid/common/Communicator.h"
#include "parafluid/sph/SPHParameters.h"

#include <utility>
#include <vector>

namespace parafluid::sph::detail
{
class SlabDecomposition
{
public:
  /// The cut axis: the longest extent of the particles (every process's `x`, `y`, `z`) across
  /// gravity among the axes that are not periodic, else the longest non-periodic one. Collective.
  /// Throws std::invalid_argument when every axis is periodic.
  SlabDecomposition(const SPHParameters& p, const std::vector<float>* position[3], Communicator& communicator);
  int axis() const { return this->Axis; }
  /// Places the cuts so that each slab holds as many of the particles at `coordinate` (this
  /// process's, along the axis) as a histogram of 4096 bins over their range allows. Collective.
  void balance(const std::vector<float>& coordinate, Communicator& communicator);
  /// The process whose slab holds `c`.
  int owner(float c) const;
  /// The processes (first, last + 1) whose slab is within `reach` of `c`.
  std::pair<int, int> within(float c, float reach) const;

private:
  int Axis = 0;
  // Cuts[r], Cuts[r + 1]: process r's slab (the first and last open towards infinity).
  std::vector<float> Cuts;
};
} // namespace parafluid::sph::detail
