#pragma once
// A procedural start for the stable-fluids grid: cumulus-like shapes from 3-D gradient noise
// (the terrain concern's Perlin noise and fractal sums). Density = coverage(x, y) x height
// profile(z) x billows(x, y, z), each factor in [0, 1]:
//  - coverage: 2-D fBm, cloud where it exceeds the quantile of its values over the grid's
//    columns that leaves `coverage` of them above it;
//  - height profile: a cumulus base and top, rounded at both (a smooth step up over the lowest
//    fifth, a longer fall over the upper half, so the tops are domes and the bases flat);
//  - billows: 1 - turbulence (sum of |noise|), cells of round puffs with creases between them,
//    as Worley noise would make them.
// The temperature inside a cloud is raised in proportion (latent heat: the cloud keeps rising).
#include "parafluid/clouds/StaggeredGrid.h"

#include <cstdint>

namespace parafluid::clouds
{
struct CloudShapeParameters
{
  double coverage = 0.4;    // fraction of the sky covered, 0..1
  double featureSize = 1.0; // [m] wavelength of the coverage's first octave
  double base = 0.2;        // cloud base height above the grid's bottom, fraction of its height
  double top = 0.8;         // cloud tops, fraction of the height
  double density = 1.0;     // peak density
  double temperature = 2.0; // [K] over ambient, times the density
  std::uint64_t seed = 1;
};

/// Fills grid.density (and adds to grid.temperature) with the shapes; throws
/// std::invalid_argument naming the parameter when one is out of range.
void fillCloudShapes(StaggeredGrid& grid, const CloudShapeParameters& parameters);
} // namespace parafluid::clouds
