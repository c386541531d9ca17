#include "LongWork.h"

#include "vtkAlgorithm.h"
#include "vtkSetGet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace parafluid::vtk
{
std::string describeDuration(double seconds)
{
  struct Unit
  {
    double seconds;
    const char* name;
  };
  static const Unit units[] = {
    { 365.25 * 86400.0, "years" }, { 86400.0, "days" }, { 3600.0, "hours" }, { 60.0, "minutes" }
  };
  char text[64];
  for (const Unit& u : units)
  {
    if (seconds >= 2.0 * u.seconds)
    {
      const double count = seconds / u.seconds;
      std::snprintf(text, sizeof(text), count < 10.0 ? "%.1f %s" : (count < 1e4 ? "%.0f %s" : "%.1e %s"), count,
                    u.name);
      return text;
    }
  }
  std::snprintf(text, sizeof(text), "%.0f s", seconds);
  return text;
}

LongWork::LongWork(vtkAlgorithm* algorithm, std::string label, WorkEstimate estimate)
  : Algorithm(algorithm)
  , Label(std::move(label))
  , Estimate(std::move(estimate))
  , Start(std::chrono::steady_clock::now())
  , LastReport(Start)
{
  // A request made while the abort flag is still up (the executive's next port of an aborted
  // update) stops at its first report: no warning for it.
  this->Aborted = this->Algorithm->GetAbortExecute() != 0;
  const double seconds = this->Estimate.units * this->Estimate.secondsPerUnit;
  if (seconds > kWarnAbove && !this->Aborted)
  {
    this->warn(seconds, "at the speed of a 2-core machine");
  }
  this->Algorithm->UpdateProgress(0.0);
}

bool LongWork::advance(double done)
{
  const auto now = std::chrono::steady_clock::now();
  if (now - this->LastReport < std::chrono::milliseconds(100))
  {
    return !this->Aborted;
  }
  this->LastReport = now;
  const double elapsed = std::chrono::duration<double>(now - this->Start).count();
  const double units = this->Estimate.units;
  const double fraction = units > 0.0 ? std::clamp(done / units, 0.0, 1.0) : 1.0;
  // The rate measured over the first second and after says more than the nominal cost.
  if (!this->Warned && !this->Aborted && elapsed >= 1.0 && done > 0.0 && units > done)
  {
    const double total = elapsed * units / done;
    if (total > kWarnAbove)
    {
      this->warn(total, "at the rate it runs at here");
    }
  }
  this->Algorithm->UpdateProgress(fraction);
  this->Aborted = this->Aborted || this->Algorithm->CheckAbort() != 0;
  return !this->Aborted;
}

void LongWork::warn(double seconds, const char* basis)
{
  this->Warned = true;
  char count[32];
  std::snprintf(count, sizeof(count), "%.3g", this->Estimate.units);
  vtkAlgorithm* algorithm = this->Algorithm;
  vtkWarningWithObjectMacro(algorithm, << this->Label << ": " << this->Estimate.property << " asks for " << count << " "
                                       << this->Estimate.what << ", about " << describeDuration(seconds) << " ("
                                       << basis << "); lower " << this->Estimate.property << " for less"
                                       << (this->Estimate.advice.empty() ? "" : " (") << this->Estimate.advice
                                       << (this->Estimate.advice.empty() ? "" : ")")
                                       << ". Progress is reported; Abort stops it and keeps the filter usable.");
}
} // namespace parafluid::vtk
