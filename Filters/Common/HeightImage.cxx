#include "HeightImage.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>

namespace parafluid::vtk
{
namespace
{
vtkDataArray* pickArray(vtkDataSetAttributes* attributes, const std::string& name)
{
  if (!name.empty())
  {
    return attributes->GetArray(name.c_str());
  }
  if (vtkDataArray* elevation = attributes->GetArray(kElevationArray))
  {
    return elevation;
  }
  if (vtkDataArray* scalars = attributes->GetScalars())
  {
    return scalars;
  }
  for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = attributes->GetArray(a))
    {
      return array;
    }
  }
  return nullptr;
}
} // namespace

bool readHeightImage(vtkImageData* image, const std::string& arrayName, HeightImage& result, std::string& error)
{
  if (!image)
  {
    error = "no image";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (image->GetNumberOfPoints() == 0)
  {
    error = "the image is empty (did the reader or filter before this one fail?)";
    return false;
  }
  if (dims[2] != 1)
  {
    error = "the image must be 2D (one layer of points in z), got " + std::to_string(dims[2]) + " layers";
    return false;
  }
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  vtkDataArray* array = pickArray(image->GetPointData(), arrayName);
  result.fromCellData = false;
  int nx = dims[0], ny = dims[1];
  result.origin[0] = origin[0], result.origin[1] = origin[1];
  if (!array)
  {
    // A raster of cells (GDAL): one height per cell, placed at the cell's centre.
    array = pickArray(image->GetCellData(), arrayName);
    if (array)
    {
      result.fromCellData = true;
      nx = dims[0] > 1 ? dims[0] - 1 : 1, ny = dims[1] > 1 ? dims[1] - 1 : 1;
      result.origin[0] += 0.5 * spacing[0], result.origin[1] += 0.5 * spacing[1];
    }
  }
  if (!array)
  {
    error = arrayName.empty() ? "the image has no point or cell array to read the elevation from"
                              : "the image has no array named '" + arrayName + "'";
    return false;
  }
  if (nx < 2 || ny < 2)
  {
    error = "the image needs at least 2 x 2 elevation samples, got " + std::to_string(nx) + " x " + std::to_string(ny);
    return false;
  }
  if (array->GetNumberOfTuples() != static_cast<vtkIdType>(nx) * ny)
  {
    error = "the array '" + std::string(array->GetName() ? array->GetName() : "") + "' has " +
            std::to_string(array->GetNumberOfTuples()) + " values for " + std::to_string(nx) + " x " +
            std::to_string(ny) + " samples";
    return false;
  }
  if (!(spacing[0] > 0.0 && spacing[1] > 0.0))
  {
    error = "the image's spacing must be positive in x and y";
    return false;
  }
  result.nx = nx, result.ny = ny;
  result.spacing[0] = spacing[0], result.spacing[1] = spacing[1];
  result.z = origin[2];
  result.arrayName = array->GetName() ? array->GetName() : "";
  result.heights.resize(static_cast<std::size_t>(nx) * ny);
  for (vtkIdType k = 0; k < array->GetNumberOfTuples(); ++k)
  {
    result.heights[static_cast<std::size_t>(k)] = static_cast<float>(array->GetComponent(k, 0));
  }
  return true;
}

vtkSmartPointer<vtkPolyData> heightSurface(const std::vector<float>& heights, int nx, int ny, const double origin[2],
                                           const double spacing[2], const std::vector<vtkDataArray*>& pointArrays)
{
  const vtkIdType n = static_cast<vtkIdType>(nx) * ny;
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  float* xyz = coordinates->GetPointer(0);
  float* nxyz = normals->GetPointer(0);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      xyz[3 * k] = static_cast<float>(origin[0] + i * spacing[0]);
      xyz[3 * k + 1] = static_cast<float>(origin[1] + j * spacing[1]);
      xyz[3 * k + 2] = heights[k];
      const int i0 = i > 0 ? i - 1 : i, i1 = i < nx - 1 ? i + 1 : i;
      const int j0 = j > 0 ? j - 1 : j, j1 = j < ny - 1 ? j + 1 : j;
      const double gx =
        (heights[static_cast<std::size_t>(j) * nx + i1] - heights[static_cast<std::size_t>(j) * nx + i0]) /
        (spacing[0] * (i1 - i0));
      const double gy =
        (heights[static_cast<std::size_t>(j1) * nx + i] - heights[static_cast<std::size_t>(j0) * nx + i]) /
        (spacing[1] * (j1 - j0));
      const double length = std::sqrt(gx * gx + gy * gy + 1.0);
      nxyz[3 * k] = static_cast<float>(-gx / length);
      nxyz[3 * k + 1] = static_cast<float>(-gy / length);
      nxyz[3 * k + 2] = static_cast<float>(1.0 / length);
    }
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  // Two counter-clockwise (seen from above) triangles per cell, in VTK's offsets/connectivity form.
  const vtkIdType cells = 2 * static_cast<vtkIdType>(nx - 1) * (ny - 1);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(cells + 1);
  connectivity->SetNumberOfTuples(3 * cells);
  vtkIdType* o = offsets->GetPointer(0);
  vtkIdType* c = connectivity->GetPointer(0);
  vtkIdType t = 0;
  for (int j = 0; j < ny - 1; ++j)
  {
    for (int i = 0; i < nx - 1; ++i)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * nx + i, b = a + 1, d = a + nx, e = d + 1;
      const vtkIdType tri[6] = { a, b, e, a, e, d };
      for (int v = 0; v < 6; ++v)
      {
        c[3 * t + v] = tri[v];
      }
      o[t] = 3 * t;
      o[t + 1] = 3 * t + 3;
      t += 2;
    }
  }
  o[cells] = 3 * cells;
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  surface->GetPointData()->SetNormals(normals);
  for (vtkDataArray* array : pointArrays)
  {
    if (array && array->GetNumberOfTuples() == n)
    {
      surface->GetPointData()->AddArray(array);
    }
  }
  return surface;
}
} // namespace parafluid::vtk
