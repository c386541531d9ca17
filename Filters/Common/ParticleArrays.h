#pragma once
// Helpers for the particle data contract (ParticleContract.h): positions and arrays as flat floats,
// field-data scene constants, one vertex per particle, and the gather of all pieces under MPI.
#include "ParticleContract.h"

#include "vtkCellArray.h"
#include "vtkCommunicator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <string>
#include <type_traits>
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

/// The components of a numeric array as floats (x, y, z, ... per tuple).
inline std::vector<float> tuplesAsFloat(vtkDataArray* array)
{
  const vtkIdType n = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  std::vector<float> values(static_cast<std::size_t>(n) * components);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      values[static_cast<std::size_t>(i) * components + c] = static_cast<float>(array->GetComponent(i, c));
    }
  }
  return values;
}

/// The polydata itself, or the first polydata leaf of a composite dataset (what ParaView 5.11's
/// render view delivers to a representation); null when there is none.
inline vtkPolyData* firstPolyData(vtkDataObject* data)
{
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    return poly;
  }
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* poly = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        return poly;
      }
    }
  }
  return nullptr;
}

/// First value of a numeric field-data array, or `fallback` when it is absent.
inline double fieldValue(vtkFieldData* fieldData, const char* name, double fallback)
{
  vtkDataArray* array = fieldData ? vtkArrayDownCast<vtkDataArray>(fieldData->GetAbstractArray(name)) : nullptr;
  return array && array->GetNumberOfTuples() > 0 ? array->GetComponent(0, 0) : fallback;
}

/// The particle spacing d [m]: `property` when positive, else the particle_spacing field data;
/// 0 when neither gives one (then say missingSpacing(property name) to the user).
inline double particleSpacing(double property, vtkFieldData* fieldData)
{
  return property > 0.0 ? property : fieldValue(fieldData, contract::ParticleSpacing, 0.0);
}

/// Empty when a spacing property's value means something: 0 (take the input's particle_spacing)
/// or a finite spacing up to 1000 m; else a sentence naming the property.
inline std::string spacingPropertyProblem(double property, const char* propertyName)
{
  if (std::isfinite(property) && property >= 0.0 && property <= 1000.0)
  {
    return {};
  }
  return std::string(propertyName) + " = " + std::to_string(property) +
         " is not allowed: it must be 0 (take the input's particle_spacing) or a spacing up to 1000 m";
}

inline std::string missingSpacing(const char* propertyName)
{
  return std::string("set ") + propertyName +
         " (the distance between neighbouring particles, metres); the input has no particle_spacing field data to take "
         "it from";
}

inline void setFieldValue(vtkFieldData* fieldData, const char* name, const double* values, int count)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(count);
  std::copy(values, values + count, array->GetPointer(0));
  fieldData->AddArray(array);
}

/// One vertex cell per point, written straight into offsets and connectivity: 32-bit ones below
/// 2^31 points (vtkCellArray's own storage choice; half the bytes to write, a tenth of a second a
/// 10 M particle read).
inline void setOneVertexPerPoint(vtkPolyData* output, vtkIdType n)
{
  vtkNew<vtkCellArray> vertices;
  auto fill = [&](auto offsets, auto connectivity)
  {
    using Value = std::remove_pointer_t<decltype(offsets->GetPointer(0))>;
    offsets->SetNumberOfValues(n + 1);
    std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, Value(0));
    connectivity->SetNumberOfValues(n);
    std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, Value(0));
    vertices->SetData(offsets.GetPointer(), connectivity.GetPointer());
  };
  if (n < (vtkIdType(1) << 31) - 1)
  {
    fill(vtkSmartPointer<vtkTypeInt32Array>::New(), vtkSmartPointer<vtkTypeInt32Array>::New());
  }
  else
  {
    fill(vtkSmartPointer<vtkTypeInt64Array>::New(), vtkSmartPointer<vtkTypeInt64Array>::New());
  }
  output->SetVerts(vertices);
}
/// This process's index and the number of processes (0 and 1 in a serial session).
inline int processIndex()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetLocalProcessId() : 0;
}
inline int processCount()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? std::max(1, controller->GetNumberOfProcesses()) : 1;
}

/// Under MPI, true only when `ok` is true on every process (every process must call it, at the
/// same point): a failure on one process becomes a failure of all, before any of them goes on to
/// the next collective call. In a serial session, `ok` itself.
inline bool agreeOnAllProcesses(bool ok)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return ok;
  }
  const int local = ok ? 1 : 0;
  int all = 0;
  controller->AllReduce(&local, &all, 1, vtkCommunicator::MIN_OP);
  return all == 1;
}

/// The pieces of all processes as one point set on process 0 (the point arrays every piece has);
/// on other processes nothing. In a serial session the input itself.
inline vtkSmartPointer<vtkDataObject> gatherToFirstProcess(vtkDataObject* input, bool& writesHere)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    writesHere = true;
    return input;
  }
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(input, pieces, 0);
  writesHere = controller->GetLocalProcessId() == 0;
  if (!writesHere)
  {
    return nullptr;
  }
  std::vector<vtkPointSet*> sets;
  vtkIdType total = 0;
  for (const auto& piece : pieces)
  {
    if (auto* set = vtkPointSet::SafeDownCast(piece))
    {
      if (set->GetNumberOfPoints() > 0)
      {
        sets.push_back(set);
        total += set->GetNumberOfPoints();
      }
    }
  }
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  merged->GetFieldData()->ShallowCopy(input->GetFieldData());
  if (sets.empty())
  {
    return merged;
  }
  vtkDataSetAttributes::FieldList common(static_cast<int>(sets.size()));
  for (vtkPointSet* set : sets)
  {
    common.IntersectFieldList(set->GetPointData());
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(sets[0]->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  merged->GetPointData()->CopyAllocate(common, total);
  vtkIdType offset = 0;
  for (std::size_t k = 0; k < sets.size(); ++k)
  {
    const vtkIdType n = sets[k]->GetNumberOfPoints();
    for (vtkIdType i = 0; i < n; ++i)
    {
      points->SetPoint(offset + i, sets[k]->GetPoint(i));
      merged->GetPointData()->CopyData(common, sets[k]->GetPointData(), static_cast<int>(k), i, offset + i);
    }
    offset += n;
  }
  merged->SetPoints(points);
  return merged;
}
} // namespace parafluid::vtk
