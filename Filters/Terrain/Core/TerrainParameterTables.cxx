#include "parafluid/terrain/TerrainParameterTables.h"

namespace parafluid::terrain
{
TerrainSettings proceduralTerrainDefaults()
{
  TerrainSettings s;
  s.featureSize = 500.0;
  s.heightScale = 150.0;
  s.warpScale = 400.0;
  return s;
}

const std::vector<ParameterDeclaration<FractalSettings>>& fractalParameterTable()
{
  using P = FractalSettings;
  static const std::vector<ParameterDeclaration<FractalSettings>> table = {
    declare<P>("Octaves", "Octaves", "", 1, 24, &P::octaves, "noise layers summed"),
    declare<P>("Lacunarity", "Lacunarity", "", 1.01, 16.0, &P::lacunarity, "the frequency ratio between octaves"),
    declare<P>("Persistence", "Persistence", "", 0.001, 1.0, &P::persistence,
               "the amplitude ratio between octaves (the gain)"),
  };
  return table;
}

const std::vector<ParameterDeclaration<TerrainSettings>>& terrainParameterTable()
{
  using P = TerrainSettings;
  static const std::vector<ParameterDeclaration<TerrainSettings>> table = {
    declare<P>("FeatureSize", "Feature Size", "m", 1e-6, 1e9, &P::featureSize,
               "the wavelength of the first (largest) octave"),
    declare<P>("WarpStrength", "Warp Strength", "m", -1e9, 1e9, &P::warpStrength,
               "domain warping: how far each sample point moves before the noise is read"),
    declare<P>("WarpScale", "Warp Scale", "m", 1e-6, 1e9, &P::warpScale,
               "the wavelength of the warp noise's first octave"),
    declare<P>("WarpOctaves", "Warp Octaves", "", 1, 24, &P::warpOctaves, "octaves of the warp noise"),
    declare<P>("Roughness", "Roughness", "", 0.0, 2.0, &P::roughness,
               "diamond-square's Hurst exponent H: displacements shrink by 2^-H per level"),
    declare<P>("HeightScale", "Height Scale", "m", -1e7, 1e7, &P::heightScale,
               "the height of one unit of the normalised fractal"),
    declare<P>("BaseHeight", "Base Height", "m", -1e7, 1e7, &P::baseHeight, "the height added everywhere"),
  };
  return table;
}

const std::vector<ParameterDeclaration<DropletSettings>>& dropletParameterTable()
{
  using P = DropletSettings;
  static const std::vector<ParameterDeclaration<DropletSettings>> table = {
    declare<P>("Drops", "Drops", "", 0, 2e9, &P::drops, "the number of drops"),
    declare<P>("Inertia", "Inertia", "", 0.0, 1.0, &P::inertia, "how much of its direction a drop keeps each step"),
    declare<P>("Capacity", "Capacity", "", 0.0, 1e9, &P::capacity,
               "sediment a drop can carry per unit of slope x speed x water"),
    declare<P>("ErodeRate", "Erode Rate", "", 0.0, 1.0, &P::erodeRate,
               "the fraction of its spare capacity a drop takes from the ground per step"),
    declare<P>("DepositRate", "Deposit Rate", "", 0.0, 1.0, &P::depositRate,
               "the fraction of its surplus sediment a drop lays down per step"),
    declare<P>("Evaporation", "Evaporation", "", 0.0, 1.0, &P::evaporation,
               "the fraction of its water a drop loses per step"),
    declare<P>("Radius", "Radius", "samples", 1.0, 32.0, &P::radius, "the radius of the erosion brush"),
    declare<P>("MaxLifetime", "Max Lifetime", "", 1, 1e5, &P::maxSteps,
               "steps (samples travelled) before a drop stops"),
    coreOnly(declare<P>("Gravity", "Gravity", "", 0.0, 1e3, &P::gravity,
                        "speed a drop gains per unit drop in height (Beyer's 4)")),
    coreOnly(declare<P>("MinSlope", "Min Slope", "", 0.0, 10.0, &P::minSlope,
                        "the slope below which a drop's capacity stops falling")),
    coreOnly(declare<P>("BatchSize", "Batch Size", "", 1, 1 << 20, &P::batchSize,
                        "drops traced against one snapshot of the terrain")),
  };
  return table;
}

const std::vector<ParameterDeclaration<PipeSettings>>& pipeParameterTable()
{
  using P = PipeSettings;
  static const std::vector<ParameterDeclaration<PipeSettings>> table = {
    declare<P>("TimeStep", "Time Step", "s", 1e-6, 10.0, &P::timeStep, "the virtual pipes' time step"),
    declare<P>("RainRate", "Rain Rate", "m/s", 0.0, 10.0, &P::rainRate, "rain on every cell"),
    declare<P>("SedimentCapacity", "Sediment Capacity", "", 0.0, 1e6, &P::capacity,
               "Kc, sediment carried per unit of sin(tilt) x speed"),
    declare<P>("DissolveRate", "Dissolve Rate", "1/s", 0.0, 1e6, &P::dissolveRate,
               "Ks, how fast water takes up ground below its capacity"),
    declare<P>("PipeDepositRate", "Pipe Deposit Rate", "1/s", 0.0, 1e6, &P::depositRate,
               "Kd, how fast water lays down sediment above its capacity"),
    declare<P>("PipeEvaporation", "Pipe Evaporation", "1/s", 0.0, 1e6, &P::evaporation,
               "Ke, the fraction of the water evaporated per second"),
    coreOnly(declare<P>("Gravity", "Gravity", "m/s^2", 0.0, 1e3, &P::gravity, "the pipes' gravity")),
    coreOnly(declare<P>("MinTilt", "Min Tilt", "", 0.0, 1.0, &P::minTilt,
                        "the lower bound of sin(tilt) in the capacity, so flat water still carries")),
    coreOnly(declare<P>("CapacityDepth", "Capacity Depth", "m", 1e-6, 1e6, &P::capacityDepth,
                        "the water depth from which the capacity is full")),
  };
  return table;
}
} // namespace parafluid::terrain
