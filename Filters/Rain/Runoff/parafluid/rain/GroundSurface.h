#pragma once
// The ground as the SPH sees it: a height field's grid cut into two triangles per cell (diagonal
// from (i, j) to (i+1, j+1)), the boundary the water cannot cross, and the height of that
// triangulated surface anywhere (which differs from the bilinear height inside a cell).
#include "parafluid/common/HeightField.h"
#include "parafluid/common/TriangleBoundary.h"

#include <memory>

namespace parafluid::rain
{
/// The triangulated ground as a boundary for SPH.
std::shared_ptr<const TriangleBoundary> groundBoundary(const HeightField& ground);
/// The height of the triangulated ground at (x, y) [m] (clamped to the grid like the height field).
double triangulatedHeight(const HeightField& ground, double x, double y);
} // namespace parafluid::rain
