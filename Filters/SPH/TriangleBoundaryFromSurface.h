#pragma once
// Converts a surface (any vtkPolyData: polygons, strips) into the core's triangle boundary.
#include "parafluid/common/TriangleBoundary.h"

#include <memory>
#include <string>

class vtkPolyData;

namespace parafluid::vtk
{
/// Triangulates the polygons and strips of `surface` (lines and vertices are ignored) and keeps
/// its point normals when it has them. Returns null and sets `error` when the surface has no
/// triangles or bad coordinates.
std::shared_ptr<const TriangleBoundary> makeTriangleBoundary(vtkPolyData* surface, std::string& error);
}
