#pragma once
// A request's work made visible: estimated before it starts, a warning once when it will take
// over a minute (naming the property that drives it), progress several times a second, and
// ParaView's Abort honoured at every report.
#include <chrono>
#include <string>

class vtkAlgorithm;

namespace parafluid::vtk
{
/// What a request will do, known before it starts: `units` of work (drops, cell updates, steps),
/// each costing about `secondsPerUnit` on the 2-core machine the project is tested on, and the
/// property a user would lower to do less.
struct WorkEstimate
{
  double units = 0.0;
  double secondsPerUnit = 0.0;
  std::string what;     // the units in words, plural: "drops", "cell updates"
  std::string property; // the property that drives the count: "Drops"
  std::string advice;   // optional: what else makes the work long
};

/// "45 s", "12 minutes", "3.5 hours", "2.1e+04 years".
std::string describeDuration(double seconds);

class LongWork
{
public:
  /// Work above this many seconds is announced with a warning.
  static constexpr double kWarnAbove = 60.0;

  /// Warns at once if the estimate is over a minute.
  LongWork(vtkAlgorithm* algorithm, std::string label, WorkEstimate estimate);

  /// After `done` of the estimate's units: reports the progress (at most ten times a second),
  /// warns once if the rate so far says the whole will take over a minute, and returns false
  /// once the user has asked to abort.
  bool advance(double done);
  bool aborted() const { return this->Aborted; }
  bool warned() const { return this->Warned; }

private:
  void warn(double seconds, const char* basis);

  vtkAlgorithm* Algorithm;
  std::string Label;
  WorkEstimate Estimate;
  std::chrono::steady_clock::time_point Start, LastReport;
  bool Warned = false;
  bool Aborted = false;
};
} // namespace parafluid::vtk
