// Particles between VTK and the cores' ParticleState (Filters/Common/ParticleStateArrays): what is
// read, and that writing puts every particle back in its original place whatever order the
// solver keeps them in.
#include "ParticleStateArrays.h"
#include "ParticleContract.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt64Array.h"

#include <gtest/gtest.h>

namespace contract = parafluid::contract;

namespace
{
/// Five particles at (i, 2i, 3i) with velocity (i, -i, 0.5 i), ids 100 + i and a "colour" array.
vtkNew<vtkPolyData> fiveParticles(bool withVelocity, bool withIds)
{
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> velocity, colour;
  vtkNew<vtkTypeInt64Array> ids;
  velocity->SetName(contract::Velocity);
  velocity->SetNumberOfComponents(3);
  ids->SetName(contract::Id);
  colour->SetName("colour");
  for (int i = 0; i < 5; ++i)
  {
    points->InsertNextPoint(i, 2 * i, 3 * i);
    velocity->InsertNextTuple3(i, -i, 0.5 * i);
    ids->InsertNextValue(100 + i);
    colour->InsertNextValue(10.0f * i);
  }
  data->SetPoints(points);
  if (withVelocity)
  {
    data->GetPointData()->AddArray(velocity);
  }
  if (withIds)
  {
    data->GetPointData()->AddArray(ids);
  }
  data->GetPointData()->AddArray(colour);
  return data;
}
} // namespace

TEST(ParticleStateArrays, ReadsPositionsVelocityAndIds)
{
  auto input = fiveParticles(true, true);
  const parafluid::ParticleState s = parafluid::vtk::readParticleState(input);
  ASSERT_EQ(s.size(), 5u);
  for (int i = 0; i < 5; ++i)
  {
    EXPECT_EQ(s.x[i], i);
    EXPECT_EQ(s.y[i], 2 * i);
    EXPECT_EQ(s.z[i], 3 * i);
    EXPECT_EQ(s.vx[i], i);
    EXPECT_EQ(s.vy[i], -i);
    EXPECT_EQ(s.vz[i], 0.5f * i);
    EXPECT_EQ(s.id[i], 100 + i);
  }
}

TEST(ParticleStateArrays, MissingVelocityAndIdsStayEmptyForTheSolver)
{
  auto input = fiveParticles(false, false);
  const parafluid::ParticleState s = parafluid::vtk::readParticleState(input);
  EXPECT_EQ(s.size(), 5u);
  EXPECT_TRUE(s.vx.empty() && s.vy.empty() && s.vz.empty());
  EXPECT_TRUE(s.id.empty());
}

TEST(ParticleStateArrays, WritesEachParticleBackToItsOriginalPlace)
{
  // The state as a solver keeps it: reordered (originalIndex), moved on.
  parafluid::ParticleState s;
  s.resize(5);
  const std::uint32_t order[5] = { 3, 0, 4, 1, 2 };
  std::vector<float> pressure(5);
  std::vector<std::uint32_t> neighbours(5);
  for (int k = 0; k < 5; ++k)
  {
    const std::uint32_t i = order[k];
    s.originalIndex[k] = i;
    s.x[k] = 1.0f + i, s.y[k] = 2.0f + i, s.z[k] = 3.0f + i;
    s.vx[k] = 10.0f * i, s.vy[k] = 20.0f * i, s.vz[k] = 30.0f * i;
    s.ax[k] = -1.0f * i, s.ay[k] = -2.0f * i, s.az[k] = -3.0f * i;
    s.density[k] = 1000.0f + i;
    s.id[k] = 100 + i;
    pressure[k] = 5.0f * i;
    neighbours[k] = 7 * i;
  }
  auto output = fiveParticles(true, true); // the input's arrays, as SPH Step copies them
  vtkNew<vtkFloatArray> stale;
  stale->SetName(contract::Pressure);
  stale->SetNumberOfValues(5);
  output->GetPointData()->AddArray(stale);

  parafluid::vtk::ParticleOutputArrays extra;
  extra.acceleration = true;
  extra.neighbourCount = &neighbours;
  parafluid::vtk::writeParticleState(s, extra, output);

  vtkPointData* pd = output->GetPointData();
  EXPECT_EQ(pd->GetArray(contract::Pressure), nullptr) << "a pressure array not asked for describes another time";
  ASSERT_NE(pd->GetArray("colour"), nullptr) << "other arrays are kept";
  ASSERT_EQ(output->GetNumberOfVerts(), 5);
  auto* velocity = pd->GetArray(contract::Velocity);
  auto* acceleration = pd->GetArray(contract::Acceleration);
  auto* density = pd->GetArray(contract::Density);
  auto* ids = pd->GetArray(contract::Id);
  auto* count = vtkIntArray::SafeDownCast(pd->GetArray(contract::NeighbourCount));
  ASSERT_TRUE(velocity && acceleration && density && ids && count);
  EXPECT_EQ(pd->GetVectors(), velocity);
  for (int i = 0; i < 5; ++i)
  {
    double x[3];
    output->GetPoint(i, x);
    EXPECT_EQ(x[0], 1.0 + i);
    EXPECT_EQ(x[1], 2.0 + i);
    EXPECT_EQ(x[2], 3.0 + i);
    EXPECT_EQ(velocity->GetComponent(i, 1), 20.0 * i);
    EXPECT_EQ(acceleration->GetComponent(i, 2), -3.0 * i);
    EXPECT_EQ(density->GetComponent(i, 0), 1000.0 + i);
    EXPECT_EQ(ids->GetComponent(i, 0), 100 + i);
    EXPECT_EQ(count->GetValue(i), 7 * i);
  }

  extra = {};
  extra.pressure = &pressure;
  parafluid::vtk::writeParticleState(s, extra, output);
  ASSERT_NE(pd->GetArray(contract::Pressure), nullptr);
  EXPECT_EQ(pd->GetArray(contract::Acceleration), nullptr);
  for (int i = 0; i < 5; ++i)
  {
    EXPECT_EQ(pd->GetArray(contract::Pressure)->GetComponent(i, 0), 5.0 * i);
  }
}
