#pragma once
// The particle data contract shared by readers and filters: scene constants in field data and
// particle polydata with one vertex per particle.
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <numeric>

namespace parafluid::vtk
{
/// First value of a numeric field-data array, or `fallback` when it is absent.
inline double fieldValue(vtkFieldData* fieldData, const char* name, double fallback)
{
  vtkDataArray* array = fieldData ? vtkArrayDownCast<vtkDataArray>(fieldData->GetAbstractArray(name)) : nullptr;
  return array && array->GetNumberOfTuples() > 0 ? array->GetComponent(0, 0) : fallback;
}

inline void setFieldValue(vtkFieldData* fieldData, const char* name, const double* values, int count)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(count);
  std::copy(values, values + count, array->GetPointer(0));
  fieldData->AddArray(array);
}

/// One vertex cell per point, written straight into offsets and connectivity.
inline void setOneVertexPerPoint(vtkPolyData* output, vtkIdType n)
{
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(n + 1);
  std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, vtkIdType(0));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(n);
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, vtkIdType(0));
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(offsets, connectivity);
  output->SetVerts(vertices);
}
} // namespace parafluid::vtk
