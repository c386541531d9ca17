#include "TriangleBoundaryFromSurface.h"

#include "GuardedRequest.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <exception>

namespace parafluid::vtk
{
std::shared_ptr<const TriangleBoundary> makeTriangleBoundary(vtkPolyData* surface, std::string& error)
{
  if (!surface || surface->GetNumberOfPoints() == 0)
  {
    error = "the Boundary input has no points";
    return nullptr;
  }
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassLinesOff();
  triangulate->PassVertsOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();
  const vtkIdType points = triangles->GetNumberOfPoints();
  if (triangles->GetNumberOfPolys() == 0)
  {
    error = "the Boundary input has no polygons (give a surface: a terrain, a container, an obstacle)";
    return nullptr;
  }
  std::vector<float> coordinates(3 * static_cast<std::size_t>(points));
  for (vtkIdType i = 0; i < points; ++i)
  {
    double x[3];
    triangles->GetPoint(i, x);
    for (int a = 0; a < 3; ++a)
    {
      coordinates[3 * i + a] = static_cast<float>(x[a]);
    }
  }
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * static_cast<std::size_t>(triangles->GetNumberOfPolys()));
  vtkCellArray* polys = triangles->GetPolys();
  vtkIdType count;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count == 3)
    {
      for (int k = 0; k < 3; ++k)
      {
        indices.push_back(static_cast<std::uint32_t>(ids[k]));
      }
    }
  }
  std::vector<float> normals;
  vtkDataArray* given = triangles->GetPointData()->GetNormals();
  if (!given)
  {
    given = triangles->GetPointData()->GetArray("Normals");
  }
  if (given && given->GetNumberOfComponents() == 3 && given->GetNumberOfTuples() == points)
  {
    normals.resize(3 * static_cast<std::size_t>(points));
    for (vtkIdType i = 0; i < points; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        normals[3 * i + a] = static_cast<float>(given->GetComponent(i, a));
      }
    }
  }
  try
  {
    return std::make_shared<const TriangleBoundary>(std::move(coordinates), std::move(indices), std::move(normals));
  }
  catch (const std::exception& e)
  {
    error = parafluid::vtk::exceptionText(e);
    return nullptr;
  }
}
} // namespace parafluid::vtk
