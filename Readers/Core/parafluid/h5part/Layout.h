#pragma once
// What an H5Part file holds: its steps (groups "Step#<n>", with an optional time attribute) and,
// per step, the particle count, where the coordinates are and which datasets form point arrays.
// Everything a file declares is checked against what it can hold before a reader allocates for
// it: a dataset whose values were never written (unallocated chunks or storage), one that ends
// beyond the end of the file, a virtual or external dataset whose source file is missing, a
// shape no point array has. No VTK types; the VTK reader and the sanitizer corpus test use it.
#include "parafluid/h5part/Hdf5.h"

#include <cstdint>
#include <map>
#include <set>
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
  std::int64_t frame = -1; // the frame of F x N (x k) datasets (H5MD's time-dependent values); -1: none
  double scale = 1.0;      // the factor to SI the values are multiplied by (1: as stored)
  std::string unit;        // the unit of the values once scaled ("m s^-1"); empty when unknown
};

struct StepLayout
{
  std::uint64_t particles = 0;
  std::uint64_t firstRow = 0; // the datasets' row of the first particle (VTKHDF's steps share datasets)
  /// Either three datasets x, y, z or one N x 3 dataset ("position" / "positions"), with the
  /// frame, scale and unit they are read with (the `datasets` of an ArraySource of 3 components).
  std::vector<std::string> coordinateDatasets;
  ArraySource coordinates;
  /// Added to the coordinates once scaled (openPMD's positionOffset): a dataset per component
  /// ("" where none) scaled by its own factor, and a constant per axis [SI].
  ArraySource coordinateOffset;
  double coordinateShift[3] = { 0.0, 0.0, 0.0 };
  std::string idDataset; // empty when the file has no usable "id" dataset
  /// A dataset whose rows other than 0 are not real particles (PySPH's remote and ghost tags),
  /// left out by the readers; empty when every row is a particle.
  std::string realTagDataset;
  std::int64_t idFrame = -1; // the frame of a time-dependent F x N id dataset
  std::vector<ArraySource> arrays;
  std::string error;                 // empty when the step is readable
  std::vector<std::string> warnings; // datasets left out, and why
};

/// A point array of more components than this is refused (a 2-D dataset N x k with k in the
/// millions is a matrix, not a per-particle value).
constexpr std::uint64_t kMaxComponents = 1024;

/// Opens an HDF5 file for reading; -1 with `error` when it is missing, not a regular file (a
/// named pipe would block HDF5 forever), not HDF5 or unreadable. Close with H5Fclose.
/// `scatteredRows`: the reads will be many small row blocks (HDF5 reads no more than asked).
hid_t openForReading(const std::string& fileName, std::string& error, bool scatteredRows = false);

/// Steps sorted by index; steps whose time attribute is NaN/infinite or not increasing make every
/// step's time its position in the list (with a warning). On failure returns nothing and sets error.
std::vector<StepEntry> listSteps(hid_t file, std::string& error, std::vector<std::string>* warnings = nullptr);

/// What the datasets of a group of N-row datasets are called: the N x 3 coordinates (x, y, z are
/// always taken), the ids, and the point arrays' names in the particle contract (the rest keep
/// the dataset's name). H5Part's by default.
struct DatasetNames
{
  std::vector<std::string> coordinates{ "position", "positions" };
  std::vector<std::string> ids{ "id" };
  std::map<std::string, std::string> arrays;
  /// Vectors stored as three component datasets under names of the layout's own (PySPH's u, v,
  /// w), besides vx/vy/vz and <name>_x/_y/_z: the vector's name and its x, y, z datasets.
  std::vector<std::pair<std::string, std::vector<std::string>>> vectors;
  /// Datasets that are not point arrays (PySPH's arrays it did not store, of no values).
  std::set<std::string> skip;
};

/// The shape of a numeric dataset of rank 1 to 3 that holds what it declares; empty with `problem`
/// saying why not (a scalar is empty with no problem).
std::vector<std::uint64_t> datasetShape(hid_t group, const std::string& name, std::string& problem);

/// Reads the layout of one step group and checks that its datasets hold what they declare.
StepLayout describeStep(hid_t file, const std::string& group);
StepLayout describeStep(hid_t file, const std::string& group, const DatasetNames& names);

/// Reads a numeric attribute of at most `maxValues` values; false when absent, not numeric or larger.
bool readNumericAttribute(hid_t object, const char* name, std::vector<double>& values, std::size_t maxValues = 4096);

/// Empty when the dataset's values are all in the file; else why not ("never written", "ends
/// beyond the end of the file", "source file 'a.h5' of the virtual dataset is missing").
std::string checkStorage(hid_t dataset, const std::string& fileFolder);
} // namespace parafluid::h5
