// The output a requested time falls on, shared by SPH Step, Rain and Stable Fluids: past the end
// (infinity included) is the last output, before the start the first, NaN none.
#include "OutputTimes.h"

#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
std::optional<long long> at(double t, double start = 1.0, double interval = 0.5, int count = 10)
{
  vtkNew<vtkInformation> info;
  info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), t);
  return parafluid::vtk::requestedOutput(info, start, interval, count);
}
} // namespace

TEST(OutputTimes, TimesInsideTheRangeGoToTheNearestOutput)
{
  EXPECT_EQ(at(1.0), 0);
  EXPECT_EQ(at(2.2), 2); // 2.4 intervals
  EXPECT_EQ(at(2.3), 3); // 2.6 intervals
  EXPECT_EQ(at(5.99), 10);
  vtkNew<vtkInformation> none;
  EXPECT_EQ(parafluid::vtk::requestedOutput(none, 1.0, 0.5, 10), 0) << "no time asked: the first output";
}

TEST(OutputTimes, PastTheEndIsTheLastOutputAndBeforeTheStartTheFirst)
{
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(at(inf), 10);
  EXPECT_EQ(at(1e30), 10);
  EXPECT_EQ(at(7.0), 10);
  EXPECT_EQ(at(-inf), 0);
  EXPECT_EQ(at(-1e30), 0);
  EXPECT_EQ(at(0.0), 0);
  EXPECT_EQ(at(inf, 0.0, 1.0, 0), 0) << "a filter with one output";
}

TEST(OutputTimes, NaNIsNoTime)
{
  EXPECT_FALSE(at(std::nan("")).has_value());
  EXPECT_NE(parafluid::vtk::notATimeError("Rain").find("Rain"), std::string::npos);
}
