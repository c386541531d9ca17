#pragma once
// Shading aids of a height field: slope and curvature per sample, and the surface normal.
#include "parafluid/terrain/ElevationGrid.h"

#include <vector>

namespace parafluid::terrain
{
/// Gradient (dh/dx, dh/dy) at sample (i, j): central differences, one-sided at the edges.
void terrainGradient(const ElevationGrid& grid, int i, int j, double gradient[2]);

/// Slope [degrees from horizontal] per sample.
std::vector<float> terrainSlope(const ElevationGrid& grid);

/// Curvature [1/m] per sample: the Laplacian of the elevation (d2h/dx2 + d2h/dy2), positive in
/// hollows and valleys, negative on ridges and peaks (zero-flux mirror at the edges).
std::vector<float> terrainCurvature(const ElevationGrid& grid);

/// Unit upward normals (3 per sample) of the height field.
std::vector<float> terrainNormals(const ElevationGrid& grid);
} // namespace parafluid::terrain
