/**
 * Sea floor from a VTK data object for the ocean model: a 2D vtkImageData whose first point
 * scalar array is the floor elevation [m], or a surface vtkPolyData (a terrain) rasterised onto a
 * grid. Shared by the Gerstner Ocean source and representation.
 */
#ifndef vtkPFBathymetry_h
#define vtkPFBathymetry_h

#include "ParaFluidOceanFiltersModule.h"

#include <memory>
#include <string>

class vtkDataObject;
namespace parafluid
{
class HeightField;
namespace ocean
{
using Bathymetry = parafluid::HeightField;
}
}

/// Returns the bathymetry, or null with `error` set to a message for the user (no scalars, a 3D
/// image, a surface without polygons, ...). `resolution`: raster points per side for a surface.
PARAFLUIDOCEANFILTERS_EXPORT std::shared_ptr<parafluid::ocean::Bathymetry> vtkPFBathymetryFrom(
  vtkDataObject* data, double seaLevel, int resolution, std::string& error);

#endif
