#include "parafluid/rain/RainParameterTable.h"

namespace parafluid::rain
{
const std::vector<ParameterDeclaration<RainParameters>>& rainParameterTable()
{
  using P = RainParameters;
  static const std::vector<ParameterDeclaration<RainParameters>> table = {
    declare<P>("RainfallRate", "Rainfall Rate", "mm/h", 0.01, 1e4, &P::rainfallRate,
               "the rain's intensity (light 1, heavy 10-50, a cloudburst 100 and more)"),
    declare<P>(
      "DropsPerRealDrop", "Drops Per Real Drop", "", 1e-9, 1.0, &P::dropsPerRealDrop,
      "the fraction of the real drops in the air that are drawn; each carries the water of those it stands for"),
    declare<P>("PrecipitationHeight", "Precipitation Height", "m", -1e7, 1e7, &P::height,
               "the height the drops start from", "the terrain's top plus its relief"),
    declare<P>("VelocityJitter", "Velocity Jitter", "m/s", 0.0, 10.0, &P::velocityJitter,
               "each drop's random horizontal speed on top of the wind"),
    declare<P>("InitialSpeed", "Initial Speed", "m/s", 0.0, 100.0, &P::initialSpeed,
               "the downward speed drops start with when TerminalVelocity is off"),
    declare<P>("RainDuration", "Rain Duration", "s", 0.0, 1e9, &P::duration, "how long the shower lasts (0: for ever)"),
    coreOnly(declare<P>("Gravity", "Gravity", "m/s^2", 1e-3, 1e3, &P::gravity, "the ballistic drops' gravity")),
  };
  return table;
}
} // namespace parafluid::rain
