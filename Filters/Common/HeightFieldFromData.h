#pragma once
// A height field from a VTK data object: a 2D vtkImageData whose elevation [m] is read as
// HeightImage.h says (`elevation`, else the scalars, else the first point or cell array), or a surface vtkPolyData (a
// terrain) rasterised onto a grid. The ocean's sea floor and the carpet surface's terrain both come through here.
#include "ParaFluidFiltersCommonModule.h"

#include <memory>
#include <string>

class vtkDataObject;
namespace parafluid
{
class HeightField;
}

namespace parafluid::vtk
{
/// Returns the height field, or null with `error` set to a message for the user (no scalars, a 3D
/// image, a surface without polygons, ...). `resolution`: raster points per side for a surface.
PARAFLUIDFILTERSCOMMON_EXPORT std::shared_ptr<HeightField> heightFieldFrom(vtkDataObject* data, double seaLevel,
                                                                           int resolution, std::string& error);
} // namespace parafluid::vtk
