#include "HeightFieldFromData.h"

#include "GuardedRequest.h"
#include "HeightImage.h"

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
      HeightImage heights;
      if (!readHeightImage(image, "", heights, error))
      {
        return nullptr;
      }
      return std::make_shared<HeightField>(std::move(heights.heights), heights.nx, heights.ny, heights.origin[0],
                                           heights.origin[1], heights.spacing[0], heights.spacing[1], seaLevel);
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
    error = parafluid::vtk::exceptionText(e);
  }
  return nullptr;
}
} // namespace parafluid::vtk
