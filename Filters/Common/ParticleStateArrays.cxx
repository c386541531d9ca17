#include "ParticleStateArrays.h"

#include "ParticleArrays.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt64Array.h"

namespace parafluid::vtk
{
ParticleState readParticleState(vtkPointSet* input)
{
  ParticleState state;
  const vtkIdType n = input->GetNumberOfPoints();
  const auto count = static_cast<std::size_t>(n);
  state.x.resize(count);
  state.y.resize(count);
  state.z.resize(count);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    state.x[i] = static_cast<float>(x[0]);
    state.y[i] = static_cast<float>(x[1]);
    state.z[i] = static_cast<float>(x[2]);
  }
  vtkDataArray* velocity = input->GetPointData()->GetArray(contract::Velocity);
  if (velocity && velocity->GetNumberOfComponents() == 3)
  {
    std::vector<float>* components[3] = { &state.vx, &state.vy, &state.vz };
    for (int c = 0; c < 3; ++c)
    {
      components[c]->resize(static_cast<std::size_t>(velocity->GetNumberOfTuples()));
      for (vtkIdType i = 0; i < velocity->GetNumberOfTuples(); ++i)
      {
        (*components[c])[static_cast<std::size_t>(i)] = static_cast<float>(velocity->GetComponent(i, c));
      }
    }
  }
  if (vtkDataArray* ids = input->GetPointData()->GetArray(contract::Id))
  {
    state.id.resize(count);
    for (vtkIdType i = 0; i < n; ++i)
    {
      state.id[i] = static_cast<std::int64_t>(ids->GetComponent(i, 0));
    }
  }
  return state;
}

namespace
{
/// A new float point array of n tuples in `output`; returns its storage.
float* addFloatArray(vtkPolyData* output, const char* name, int components, vtkIdType n)
{
  vtkNew<vtkFloatArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  output->GetPointData()->AddArray(array);
  return array->GetPointer(0);
}
} // namespace

void writeParticleState(const ParticleState& s, const ParticleOutputArrays& extra, vtkPolyData* output)
{
  const auto n = static_cast<vtkIdType>(s.size());
  vtkPointData* pointData = output->GetPointData();
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(n);
  float* position = coordinates->GetPointer(0);
  float* velocity = addFloatArray(output, contract::Velocity, 3, n);
  float* density = addFloatArray(output, contract::Density, 1, n);
  // Optional arrays: without them the input's arrays of that name (if any) are dropped too, as
  // they would describe another time.
  pointData->RemoveArray(contract::Acceleration);
  pointData->RemoveArray(contract::Pressure);
  float* acceleration = extra.acceleration ? addFloatArray(output, contract::Acceleration, 3, n) : nullptr;
  float* pressure = extra.pressure ? addFloatArray(output, contract::Pressure, 1, n) : nullptr;
  vtkNew<vtkIntArray> neighbourCount;
  if (extra.neighbourCount)
  {
    neighbourCount->SetName(contract::NeighbourCount);
    neighbourCount->SetNumberOfValues(n);
    pointData->AddArray(neighbourCount);
  }
  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName(contract::Id);
  ids->SetNumberOfValues(n);
  pointData->AddArray(ids);
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType i = s.originalIndex[k];
    position[3 * i + 0] = s.x[k];
    position[3 * i + 1] = s.y[k];
    position[3 * i + 2] = s.z[k];
    velocity[3 * i + 0] = s.vx[k];
    velocity[3 * i + 1] = s.vy[k];
    velocity[3 * i + 2] = s.vz[k];
    if (acceleration)
    {
      acceleration[3 * i + 0] = s.ax[k];
      acceleration[3 * i + 1] = s.ay[k];
      acceleration[3 * i + 2] = s.az[k];
    }
    if (pressure)
    {
      pressure[i] = (*extra.pressure)[k];
    }
    if (extra.neighbourCount)
    {
      neighbourCount->SetValue(i, static_cast<int>((*extra.neighbourCount)[k]));
    }
    density[i] = s.density[k];
    ids->SetValue(i, s.id[k]);
  }
  pointData->SetActiveVectors(contract::Velocity);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  setOneVertexPerPoint(output, n);
}
} // namespace parafluid::vtk
