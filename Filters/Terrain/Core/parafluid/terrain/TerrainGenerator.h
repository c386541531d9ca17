#pragma once
// A procedural terrain: a height field from fractal gradient noise (optionally domain-warped) or
// from diamond-square, scaled to metres.
#include "parafluid/terrain/ElevationGrid.h"
#include "parafluid/terrain/FractalNoise.h"

#include <cstdint>
#include <functional>

namespace parafluid::terrain
{
enum class TerrainMethod
{
  FractalNoise = 0,
  DiamondSquare = 1
};

struct TerrainSettings
{
  TerrainMethod method = TerrainMethod::FractalNoise;
  FractalSettings fractal;
  std::uint64_t seed = 0;
  double featureSize = 250.0; // wavelength of the first octave [m]
  // Domain warping (Quilez 2002): the sample point moves by warpStrength [m] times a 2-D fBm of
  // first wavelength warpScale [m] and warpOctaves octaves before the terrain noise is read there.
  double warpStrength = 0.0;
  double warpScale = 250.0;
  int warpOctaves = 4;
  double roughness = 0.8;   // diamond-square's H
  double heightScale = 100; // [m] per unit of the normalised fractal value
  double baseHeight = 0.0;  // [m]

  /// Empty when usable; else one sentence naming the setting (as the GUI calls it).
  std::string problem() const;
};

/// Fills grid.elevation (grid.nx, ny, x0, y0, dx, dy set by the caller) with
/// baseHeight + heightScale * value. Rows run in parallel; every value is a function of the seed
/// and the position only, so any thread count gives the same terrain. `progress(fraction)`
/// returning false stops early (the grid is then incomplete, and the function returns false).
bool generateTerrain(const TerrainSettings& settings, ElevationGrid& grid,
                     const std::function<bool(double)>& progress = {});
} // namespace parafluid::terrain
