#pragma once
// The time steps a time-aware source or simulation filter offers: start + k x interval for k = 0
// .. count (TIME_STEPS and TIME_RANGE of an output), and the output a requested time falls on.
#include <optional>
#include <string>
#include <vector>

class vtkInformation;

namespace parafluid::vtk
{
/// Sets TIME_STEPS and TIME_RANGE of `outInfo` to start + k interval, k = 0 .. count.
void setOutputTimes(vtkInformation* outInfo, double start, double interval, int count);
/// The output nearest to `outInfo`'s UPDATE_TIME_STEP (the first without one): a time past the
/// end (+inf too) is the last output, one before the start (-inf too) the first; empty for NaN.
std::optional<long long> requestedOutput(vtkInformation* outInfo, double start, double interval, int count);
/// What a filter says when asked for a time that is not a number.
std::string notATimeError(const std::string& filter);
} // namespace parafluid::vtk
