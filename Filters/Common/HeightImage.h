#pragma once
// The terrain contract on the VTK side: a 2-D vtkImageData whose elevation [m] is the point array
// `elevation` (else the active scalars, else the first array; cell data when the image has no
// point arrays, e.g. what ParaView's GDAL Raster Reader gives, with nodes at the cell centres),
// with any origin and spacing. Every terrain consumer reads it through here, and the warped
// surface of such an image is made here too (SPH Step's Boundary, the terrain sources' second
// output).
#include "ParaFluidFiltersCommonModule.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkPolyData;
class vtkDataArray;

namespace parafluid::vtk
{
/// The name of the terrain's elevation array.
constexpr const char* kElevationArray = "elevation";

struct HeightImage
{
  std::vector<float> heights; // nx * ny, x fastest (NaN where the input was NaN)
  int nx = 0, ny = 0;
  double origin[2] = { 0.0, 0.0 }, spacing[2] = { 1.0, 1.0 };
  double z = 0.0;            // the image's z origin
  std::string arrayName;     // where the heights came from
  bool fromCellData = false; // true: nodes are the input's cell centres
};

/// Reads the heights of a 2-D image (`arrayName` empty: elevation / active scalars / first
/// array). Returns false with `error` naming the problem (3-D image, no array, too small).
PARAFLUIDFILTERSCOMMON_EXPORT bool readHeightImage(vtkImageData* image, const std::string& arrayName,
                                                   HeightImage& result, std::string& error);

/// A triangulated surface z = h(x, y) over the grid of `heights` (two triangles per cell), with
/// upward point `Normals`; `pointArrays` (each nx * ny tuples) are attached as they are (shared,
/// not copied).
PARAFLUIDFILTERSCOMMON_EXPORT vtkSmartPointer<vtkPolyData> heightSurface(
  const std::vector<float>& heights, int nx, int ny, const double origin[2], const double spacing[2],
  const std::vector<vtkDataArray*>& pointArrays = {});
} // namespace parafluid::vtk
