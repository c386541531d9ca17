#include "OutputTimes.h"

#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>

namespace parafluid::vtk
{
void setOutputTimes(vtkInformation* outInfo, double start, double interval, int count)
{
  std::vector<double> times(static_cast<std::size_t>(std::max(count, 0)) + 1);
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    times[k] = start + static_cast<double>(k) * interval;
  }
  const double range[2] = { times.front(), times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
}

long long requestedOutput(vtkInformation* outInfo, double start, double interval, int count)
{
  const double requested = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                             ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                             : start;
  const double steps = (requested - start) / interval;
  if (!std::isfinite(steps))
  {
    return 0;
  }
  return std::clamp<long long>(std::llround(std::clamp(steps, -1.0, 1e15)), 0, std::max(count, 0));
}
} // namespace parafluid::vtk
