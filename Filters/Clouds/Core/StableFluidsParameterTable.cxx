#include "parafluid/clouds/StableFluidsParameterTable.h"

#include <algorithm>

namespace parafluid::clouds
{
StableFluidsParameters sourceDefaults()
{
  StableFluidsParameters p;
  p.vorticity = 0.3;
  p.open[5] = true;
  p.emitter = true;
  const double box[6] = { 0.8, 1.2, 0.8, 1.2, 0.0, 0.2 };
  std::copy(box, box + 6, p.emitterBox);
  p.emitterSpeed = 1.0;
  return p;
}

const std::vector<ParameterDeclaration<StableFluidsParameters>>& stableFluidsParameterTable()
{
  using P = StableFluidsParameters;
  static const std::vector<ParameterDeclaration<StableFluidsParameters>> table = {
    declare<P>("Viscosity", "Viscosity", "m^2/s", 0.0, 100.0, &P::viscosity,
               "the air's kinematic viscosity (air: 1.5e-5); 0 leaves only the grid's own smoothing"),
    declare<P>("Diffusivity", "Diffusivity", "m^2/s", 0.0, 100.0, &P::diffusivity, "of density and heat"),
    declare<P>("BuoyancyDensity", "Buoyancy Density", "m/s^2 per unit density", -100.0, 100.0, &P::buoyancyDensity,
               "how much density weighs the air down (alpha of Fedkiw, Stam & Jensen 2001)"),
    declare<P>("BuoyancyHeat", "Buoyancy Heat", "m/s^2 per K", -100.0, 100.0, &P::buoyancyHeat,
               "how much heat lifts the air (beta; g / T0 is 0.034 for air at 290 K)"),
    declare<P>("AmbientTemperature", "Ambient Temperature", "K", -1e30, 1e30, &P::ambientTemperature,
               "the surrounding air's temperature; only differences from it lift"),
    declare<P>("Vorticity", "Vorticity", "", 0.0, 10.0, &P::vorticity,
               "vorticity confinement's strength epsilon (0: off)"),
    declare<P>("EmitterDensity", "Emitter Density", "", 0.0, 1e6, &P::emitterDensity,
               "the density the emitter keeps its cells at"),
    declare<P>("EmitterTemperature", "Emitter Temperature", "K", -1000.0, 1000.0, &P::emitterTemperature,
               "the temperature the emitter keeps its cells at, above ambient"),
    declare<P>("EmitterSpeed", "Emitter Speed", "m/s", -1000.0, 1000.0, &P::emitterSpeed,
               "the speed the emitter blows at, against gravity"),
    declare<P>("ProjectionTolerance", "Projection Tolerance", "", 1e-14, 0.5, &P::projectionTolerance,
               "the pressure solve's relative residual: the divergence left, as a fraction of what the step made"),
  };
  return table;
}
} // namespace parafluid::clouds
