#pragma once
// The time steps a time-aware source or simulation filter offers: start + k x interval for k = 0
// .. count (TIME_STEPS and TIME_RANGE of an output), and the output a requested time falls on.
#include <vector>

class vtkInformation;

namespace parafluid::vtk
{
/// Sets TIME_STEPS and TIME_RANGE of `outInfo` to start + k interval, k = 0 .. count.
void setOutputTimes(vtkInformation* outInfo, double start, double interval, int count);
/// The output nearest to `outInfo`'s UPDATE_TIME_STEP (0 without one), clamped to 0 .. count.
long long requestedOutput(vtkInformation* outInfo, double start, double interval, int count);
} // namespace parafluid::vtk
