#pragma once
// Particles between VTK and the cores' structure-of-arrays ParticleState: what a particle filter
// reads from its input and writes to its output, in the contract's array names.
#include "ParaFluidFiltersCommonModule.h"

#include "parafluid/common/ParticleState.h"

#include <cstdint>
#include <vector>

class vtkPointSet;
class vtkPolyData;

namespace parafluid::vtk
{
/// Positions, the `velocity` array and the `id` array of a point set, as floats and int64; the
/// velocity (absent or not 3 components) and the ids (absent) stay empty for the solver to fill
/// (at rest; the index), as does the rest of the state.
PARAFLUIDFILTERSCOMMON_EXPORT ParticleState readParticleState(vtkPointSet* input);

/// What writeParticleState adds besides positions, velocity, density and id.
struct ParticleOutputArrays
{
  bool acceleration = false;
  /// Per-particle values in the state's order; written when not null.
  const std::vector<float>* pressure = nullptr;
  const std::vector<std::uint32_t>* neighbourCount = nullptr;
};

/// Writes the state into `output` in the order the particles had when the state was made
/// (state.originalIndex): points, one vertex per particle, `velocity` (active vectors), `density`,
/// `id` and the arrays `extra` asks for. Arrays of the output of other names are kept; an
/// `acceleration` or `pressure` array not asked for is removed (it would describe another time).
PARAFLUIDFILTERSCOMMON_EXPORT void writeParticleState(const ParticleState& state, const ParticleOutputArrays& extra,
                                                      vtkPolyData* output);
} // namespace parafluid::vtk
