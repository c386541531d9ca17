#pragma once
// Shared by the surface filters: particle positions in, a Core SurfaceMesh out as vtkPolyData.
#include "parafluid/SurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"

#include <cstring>
#include <limits>
#include <vector>

namespace parafluid::vtk
{
/// The points of a point set as x, y, z floats (a copy only when they are not floats already).
inline const float* positionsAsFloat(vtkPointSet* input, std::vector<float>& storage)
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType n = input->GetNumberOfPoints();
  if (!points || n == 0)
  {
    return nullptr;
  }
  if (auto* floats = vtkFloatArray::SafeDownCast(points->GetData()))
  {
    return floats->GetPointer(0);
  }
  storage.resize(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int a = 0; a < 3; ++a)
    {
      storage[3 * static_cast<std::size_t>(i) + a] = static_cast<float>(p[a]);
    }
  }
  return storage.data();
}

inline vtkSmartPointer<vtkFloatArray> floatArray(const char* name, int components, const std::vector<float>& values)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  if (!values.empty())
  {
    std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(float));
  }
  return array;
}

/// Points, triangles (32-bit cell storage) and, when present, "Normals" into `output`.
inline void meshToPolyData(const parafluid::surface::SurfaceMesh& mesh, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetData(floatArray("Points", 3, mesh.points));
  output->SetPoints(points);
  const vtkIdType nt = static_cast<vtkIdType>(mesh.triangleCount());
  vtkNew<vtkTypeInt32Array> offsets, connectivity;
  offsets->SetNumberOfValues(nt + 1);
  for (vtkIdType t = 0; t <= nt; ++t)
  {
    offsets->SetValue(t, static_cast<vtkTypeInt32>(3 * t));
  }
  connectivity->SetNumberOfValues(3 * nt);
  if (nt > 0)
  {
    std::memcpy(connectivity->GetPointer(0), mesh.triangles.data(), mesh.triangles.size() * sizeof(std::uint32_t));
  }
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(offsets, connectivity);
  output->SetPolys(triangles);
  if (!mesh.normals.empty())
  {
    auto normals = floatArray("Normals", 3, mesh.normals);
    output->GetPointData()->SetNormals(normals);
  }
}
} // namespace parafluid::vtk
