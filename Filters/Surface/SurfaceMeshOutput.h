#pragma once
// Shared by the surface filters: particle positions in, a Core SurfaceMesh out as vtkPolyData.
#include "ParticleArrays.h"
#include "parafluid/surface/SurfaceMesh.h"

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
