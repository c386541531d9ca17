#pragma once
// A procedural start for the stable-fluids grid: cumulus-like shapes from gradient noise (the
// terrain concern's Perlin noise and fractal sums). Density rises smoothly with
// dome(x, y, z) - 0.35 (1 - puff(x, y, z)):
//  - cover: 2-D fBm, 0 at the quantile of its values over the grid's columns that leaves
//    `coverage` of them above it, 1 at its largest value: how far inside a covered patch;
//  - dome: a cumulus profile between the base and a local top that rises with sqrt(cover) to
//    `top` (a quick step up at the flat base, a long rounded fall over the upper half);
//  - puff: 1 - turbulence (sum of |noise|) at a third of the size, round puffs with creases
//    between them, as Worley noise would make them; they eat into the rim.
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
