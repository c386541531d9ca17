#include "HeightFieldFromData.h"

#include "parafluid/common/HeightField.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <stdexcept>
#include <vector>

namespace parafluid::vtk
{
std::shared_ptr<HeightField> heightFieldFrom(vtkDataObject* data, double seaLevel, int resolution, std::string& error)
{
  try
  {
    if (auto* image = vtkImageData::SafeDownCast(data))
    {
      int dims[3];
      image->GetDimensions(dims);
      if (dims[2] != 1)
      {
        error = "the image must be 2D (one layer of points in z), got " + std::to_string(dims[2]) + " layers";
        return nullptr;
      }
      vtkDataArray* scalars = image->GetPointData()->GetScalars();
      if (!scalars)
      {
        scalars = image->GetPointData()->GetNumberOfArrays() > 0 ? image->GetPointData()->GetArray(0) : nullptr;
      }
      if (!scalars)
      {
        error = "the image has no point array to read the floor elevation from";
        return nullptr;
      }
      std::vector<float> elevation(static_cast<std::size_t>(scalars->GetNumberOfTuples()));
      for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
      {
        elevation[static_cast<std::size_t>(i)] = static_cast<float>(scalars->GetComponent(i, 0));
      }
      const double* origin = image->GetOrigin();
      const double* spacing = image->GetSpacing();
      return std::make_shared<HeightField>(std::move(elevation), dims[0], dims[1], origin[0], origin[1], spacing[0],
                                           spacing[1], seaLevel);
    }
    if (auto* surface = vtkPolyData::SafeDownCast(data))
    {
      if (surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
      {
        error = "the surface has no polygons (give a terrain surface or a height-field image)";
        return nullptr;
      }
      vtkNew<vtkTriangleFilter> triangulate;
      triangulate->SetInputData(surface);
      triangulate->PassVertsOff();
      triangulate->PassLinesOff();
      triangulate->Update();
      vtkPolyData* mesh = triangulate->GetOutput();
      std::vector<float> points(3 * static_cast<std::size_t>(mesh->GetNumberOfPoints()));
      for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
      {
        double x[3];
        mesh->GetPoint(p, x);
        for (int c = 0; c < 3; ++c)
        {
          points[3 * static_cast<std::size_t>(p) + c] = static_cast<float>(x[c]);
        }
      }
      std::vector<std::uint32_t> triangles;
      vtkCellArray* polys = mesh->GetPolys();
      vtkIdType count;
      const vtkIdType* ids;
      for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
      {
        if (count == 3)
        {
          triangles.insert(triangles.end(), { static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
                                              static_cast<std::uint32_t>(ids[2]) });
        }
      }
      return std::make_shared<HeightField>(
        HeightField::fromTriangles(points, triangles, resolution, resolution, seaLevel));
    }
    error =
      std::string("it must be an image (height field) or a surface, got ") + (data ? data->GetClassName() : "nothing");
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  return nullptr;
}
} // namespace parafluid::vtk
