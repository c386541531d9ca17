// Runs the H5Part core over every file of a folder (the reader's fuzz corpus, see
// corpus/make_corpus.py) the way the VTK reader does: open, list steps, describe each step, read
// its coordinates, ids, arrays and the root attributes into memory sized from what the file
// declares, within the memory budget. Built with AddressSanitizer and UndefinedBehaviorSanitizer
// (scripts/sanitize.sh) any out-of-bounds access, overflow or leak aborts it; otherwise it prints
// one line per file, "ok" or the clean error, and exits 0.
#include "parafluid/common/MemoryBudget.h"
#include "parafluid/h5part/Attributes.h"
#include "parafluid/h5part/Datasets.h"
#include "parafluid/h5part/Handle.h"
#include "parafluid/h5part/Layout.h"

#include <algorithm>
#include <cstdio>
#include <dirent.h>
#include <string>
#include <vector>

namespace
{
using namespace parafluid::h5;

std::string readStep(hid_t file, const StepEntry& step)
{
  const StepLayout layout = describeStep(file, step.group);
  if (!layout.error.empty())
  {
    return layout.error;
  }
  Handle group(H5Gopen2(file, step.group.c_str(), H5P_DEFAULT), H5Gclose);
  const std::uint64_t n = layout.particles;
  double bytes = static_cast<double>(n) * 32.0;
  for (const ArraySource& source : layout.arrays)
  {
    bytes += static_cast<double>(n) * source.components * 8.0;
  }
  const std::string tooLarge = parafluid::checkMemoryBudget(bytes, step.group);
  if (!tooLarge.empty())
  {
    return tooLarge;
  }
  std::string error;
  const ValueType coordinateType = commonValueType(group, layout.coordinateDatasets);
  std::vector<unsigned char> coordinates(static_cast<std::size_t>(n) * 3 * valueBytes(coordinateType));
  for (std::size_t c = 0; c < layout.coordinateDatasets.size(); ++c)
  {
    if (!readSlice(group, layout.coordinateDatasets[c], coordinateType, 0, n, coordinates.data(), 3,
                   layout.coordinateDatasets.size() > 1 ? c : 0, error))
    {
      return error;
    }
  }
  std::vector<std::int64_t> ids(static_cast<std::size_t>(n));
  if (!layout.idDataset.empty())
  {
    readIds(group, layout.idDataset, 0, n, ids.data(), error); // a bad id falls back to the index
  }
  for (const ArraySource& source : layout.arrays)
  {
    const ValueType type = commonValueType(group, source.datasets);
    std::vector<unsigned char> values(static_cast<std::size_t>(n) * source.components * valueBytes(type));
    for (std::size_t c = 0; c < source.datasets.size(); ++c)
    {
      if (!readSlice(group, source.datasets[c], type, 0, n, values.data(), source.components,
                     source.datasets.size() > 1 ? c : 0, error))
      {
        return error;
      }
    }
  }
  return {};
}

std::string check(const std::string& path)
{
  std::string error;
  Handle file(openForReading(path, error), H5Fclose);
  if (!file.valid())
  {
    return error;
  }
  QuietErrors quiet;
  std::vector<std::string> warnings;
  const std::vector<StepEntry> steps = listSteps(file, error, &warnings);
  if (steps.empty())
  {
    return error;
  }
  readAttributes(file, warnings);
  // The first and the last step (a corpus file with 200 steps need not be read 200 times).
  for (const StepEntry* step : { &steps.front(), &steps.back() })
  {
    const std::string problem = readStep(file, *step);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return {};
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s <corpus folder>\n", argv[0]);
    return 2;
  }
  const std::string folder = argv[1];
  std::vector<std::string> files;
  if (DIR* directory = ::opendir(folder.c_str()))
  {
    while (const dirent* entry = ::readdir(directory))
    {
      const std::string name = entry->d_name;
      if (name.size() > 7 && name.compare(name.size() - 7, 7, ".h5part") == 0)
      {
        files.push_back(name);
      }
    }
    ::closedir(directory);
  }
  std::sort(files.begin(), files.end());
  for (const std::string& name : files)
  {
    const std::string problem = check(folder + "/" + name);
    std::printf("%s: %s\n", name.c_str(), problem.empty() ? "ok" : problem.c_str());
  }
  std::printf("H5Part corpus: %zu files, no memory error\n", files.size());
  return files.empty() ? 1 : 0;
}
