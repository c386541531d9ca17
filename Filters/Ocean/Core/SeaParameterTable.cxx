#include "parafluid/ocean/SeaParameterTable.h"

namespace parafluid::ocean
{
const std::vector<ParameterDeclaration<SeaSettings>>& seaParameterTable()
{
  // Distances up to 1e7 m (a sea 10000 km across) and angles up to 1e6 degrees: beyond them float
  // phases lose every digit.
  using P = SeaSettings;
  static const std::vector<ParameterDeclaration<SeaSettings>> table = {
    declare<P>("SeaLevel", "Sea Level", "m", -1e7, 1e7, &P::seaLevel,
               "the height of the still water, from which the sea floor's depth is measured"),
    declare<P>("WindDirection", "Wind Direction", "degrees", -1e6, 1e6, &P::windDirection,
               "the direction the wind blows towards, counter-clockwise from +x"),
    declare<P>("WindLean", "Wind Lean", "", 0.0, 0.5, &P::windLean, "how far crests lean downwind (0: upright)"),
    declare<P>("WaterDepth", "Water Depth", "m", 0.0, 1e5, &P::waterDepth,
               "the uniform depth without a sea floor (0: deep water)"),
    declare<P>("MaxSteepness", "Max Steepness", "", 0.01, 1.0, &P::maxSteepness,
               "the cap on the summed steepness Q k A of the waves (1: where the surface folds)"),
    declare<P>("BreakingDepthRatio", "Breaking Depth Ratio", "", 0.01, 10.0, &P::breakingDepthRatio,
               "wave height over depth at which a wave breaks (0.78: McCowan 1894)"),
    declare<P>("BreakingStretch", "Breaking Stretch", "", 0.0, 10.0, &P::breakingStretch,
               "a breaking crest is raised by this fraction of its amplitude"),
    declare<P>("BreakingLean", "Breaking Lean", "rad", 0.0, 1.4, &P::breakingLean,
               "the forward tilt of a breaking crest"),
    declare<P>("BreakingShift", "Breaking Shift", "", 0.0, 10.0, &P::breakingShift,
               "a breaking crest is thrown forward by this many amplitudes"),
    declare<P>("BathymetryResolution", "Bathymetry Resolution", "", 2, 8192, &P::bathymetryResolution,
               "points per side when a terrain surface is rasterised into the sea floor"),
  };
  return table;
}
} // namespace parafluid::ocean
