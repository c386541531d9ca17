#pragma once
// What an H5Part file holds: its steps (groups "Step#<n>", with an optional time attribute) and,
// per step, the particle count, where the coordinates are and which datasets form point arrays.
// Shared by the reader (to read) and its tests' error paths; no VTK types.
#include "vtk_hdf5.h"

#include <string>
#include <vector>

namespace parafluid::h5
{
struct StepEntry
{
  std::string group; // "Step#12"
  long index = 0;    // 12
  double time = 0.0; // from the time/Time/TimeValue attribute, else the index
};

/// One point array and the datasets it is read from: a single dataset (N or N x k values) or
/// three component datasets (vx, vy, vz or velocity_x, ...) combined into one vector.
struct ArraySource
{
  std::string name;
  std::vector<std::string> datasets;
  int components = 1;
};

struct StepLayout
{
  hsize_t particles = 0;
  /// Either three datasets x, y, z or one N x 3 dataset ("position" / "positions").
  std::vector<std::string> coordinateDatasets;
  std::string idDataset; // empty when the file has no "id" dataset
  std::vector<ArraySource> arrays;
  std::string error; // empty when the step is readable
};

/// Steps sorted by index. On failure returns nothing and sets error.
std::vector<StepEntry> listSteps(hid_t file, std::string& error);

/// Reads the layout of one step group.
StepLayout describeStep(hid_t file, const std::string& group);

/// Reads a numeric scalar attribute; false when absent or not numeric.
bool readNumericAttribute(hid_t object, const char* name, std::vector<double>& values);
} // namespace parafluid::h5
