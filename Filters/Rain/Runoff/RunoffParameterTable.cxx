#include "parafluid/rain/RunoffParameterTable.h"

namespace parafluid::rain
{
const std::vector<ParameterDeclaration<RunoffParameters>>& runoffParameterTable()
{
  using P = RunoffParameters;
  static const std::vector<ParameterDeclaration<RunoffParameters>> table = {
    declare<P>("ParticleSpacing", "Particle Spacing", "m", 1e-5, 1e5, &P::particleSpacing,
               "the SPH water's spacing d: each particle carries d^3 of water"),
    declare<P>("RainScale", "Rain Scale", "", 1, 1e6, &P::rainScale,
               "impacts in a cell per inserted particle when ConserveVolume is off"),
    declare<P>("RainTimeStep", "Rain Time Step", "s", 1e-6, 1.0, &P::rainStep,
               "the step at which impacts are gathered into particles"),
    declare<P>("SPHEvery", "SPH Every", "", 1, 1000, &P::sphEvery, "rain steps per SPH advance"),
    declare<P>("Infiltration", "Infiltration", "mm/h", 0.0, 1e4, &P::infiltration,
               "the rate at which wet ground soaks up water"),
  };
  return table;
}
} // namespace parafluid::rain
