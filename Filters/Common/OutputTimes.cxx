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

std::optional<long long> requestedOutput(vtkInformation* outInfo, double start, double interval, int count)
{
  const double requested = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                             ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                             : start;
  if (std::isnan(requested))
  {
    return std::nullopt;
  }
  const long long last = std::max(count, 0);
  const double steps = (requested - start) / interval;
  if (!(steps > 0.0))
  {
    return 0; // before the start, -inf, or an interval that makes no steps
  }
  if (!(steps < static_cast<double>(last)))
  {
    return last; // past the end, +inf
  }
  return std::clamp<long long>(std::llround(steps), 0, last);
}

std::string notATimeError(const std::string& filter)
{
  return filter + ": the requested time is not a number (NaN); ask for a time in its TimestepValues";
}
} // namespace parafluid::vtk
