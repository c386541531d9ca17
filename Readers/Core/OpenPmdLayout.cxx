// openPMD 1.x particles (Huebl et al., "openPMD: A meta data standard for particle and mesh based
// data", doi 10.5281/zenodo.591699): /<basePath with %T>/<particlesPath>/<species>/<record>/
// <component>, a record either one dataset (a scalar record) or x, y, z components, each a
// dataset or a constant (a group with `value` and `shape`); values times each component's unitSI
// are SI, the record's unitDimension names the unit; position + positionOffset is the point.
// Iterations in one file ("groupBased") or one file each ("fileBased", the iterationFormat's %T
// a number in the name); each iteration's time x timeUnitSI is its time. One block per species.
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>

namespace parafluid::h5::detail
{
namespace
{
const char* const kAxes[3] = { "x", "y", "z" };

std::string rootString(hid_t file, const char* name, const std::string& fallback)
{
  const std::vector<std::string> value = stringAttribute(file, name);
  return value.empty() ? fallback : value.front();
}

double numberAttribute(hid_t object, const char* name, double fallback)
{
  std::vector<double> value;
  return readNumericAttribute(object, name, value, 1) ? value[0] : fallback;
}

/// "kg m s^-2" from openPMD's unitDimension (powers of L, M, T, I, theta, N, J).
std::string unitOf(hid_t record)
{
  std::vector<double> powers;
  if (!readNumericAttribute(record, "unitDimension", powers, 7) || powers.size() != 7)
  {
    return "";
  }
  static const char* const si[7] = { "m", "kg", "s", "A", "K", "mol", "cd" };
  static const int order[7] = { 1, 0, 2, 3, 4, 5, 6 }; // kg before m, as units are written
  std::string unit;
  for (int k : order)
  {
    if (powers[k] == 0.0)
    {
      continue;
    }
    char part[32];
    std::snprintf(part, sizeof(part), powers[k] == 1.0 ? "%s" : "%s^%g", si[k], powers[k]);
    unit += (unit.empty() ? "" : " ") + std::string(part);
  }
  return unit;
}

/// One component of a record: a dataset (its path relative to the species), or a constant.
struct Component
{
  std::string dataset;
  bool constant = false;
  double value = 0.0;
  double unitSI = 1.0;
  std::uint64_t rows = 0;
  int columns = 1;
  std::string problem;
};

Component readComponent(hid_t species, const std::string& path)
{
  Component c;
  if (hasObject(species, path, H5O_TYPE_DATASET))
  {
    Handle dataset(H5Dopen2(species, path.c_str(), H5P_DEFAULT), H5Dclose);
    c.unitSI = numberAttribute(dataset, "unitSI", 1.0);
    std::vector<double> unitSI;
    if (H5Aexists(dataset, "unitSI") > 0 && !readNumericAttribute(dataset, "unitSI", unitSI, 1))
    {
      c.problem = "its unitSI attribute is not a number";
      return c;
    }
    const std::vector<std::uint64_t> shape = datasetShape(species, path, c.problem);
    if (c.problem.empty() && (shape.empty() || shape.size() > 2))
    {
      c.problem = "expected one value per particle";
    }
    c.dataset = path;
    c.rows = shape.empty() ? 0 : shape[0];
    c.columns = shape.size() == 2 ? static_cast<int>(shape[1]) : 1;
    return c;
  }
  Handle group(H5Gopen2(species, path.c_str(), H5P_DEFAULT), H5Gclose);
  std::vector<double> value, shape;
  if (!group.valid() || !readNumericAttribute(group, "value", value, 1) ||
      !readNumericAttribute(group, "shape", shape, 1))
  {
    c.problem = "neither a dataset nor a constant (attributes value and shape)";
    return c;
  }
  c.constant = true;
  c.value = value[0];
  c.unitSI = numberAttribute(group, "unitSI", 1.0);
  c.rows = shape[0] >= 0.0 && shape[0] < 9.2e18 ? static_cast<std::uint64_t>(shape[0]) : 0;
  return c;
}

/// The components of a record: x, y, z where it has them, else the record itself (a scalar).
std::vector<std::string> componentNames(hid_t species, const std::string& record)
{
  if (hasObject(species, record, H5O_TYPE_DATASET))
  {
    return { record };
  }
  Handle group(H5Gopen2(species, record.c_str(), H5P_DEFAULT), H5Gclose);
  std::vector<double> value;
  if (readNumericAttribute(group, "value", value, 1))
  {
    return { record }; // a constant scalar record
  }
  std::vector<std::string> names;
  for (const std::string& child : linkNames(group))
  {
    names.push_back(record + "/" + child);
  }
  return names;
}

/// The iteration number of a file of a fileBased series: the digits where the format has %T.
bool iterationOfFile(const std::string& name, const std::string& prefix, const std::string& suffix, long& iteration)
{
  if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
  {
    return false;
  }
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.empty() || digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  iteration = std::strtol(digits.c_str(), nullptr, 10);
  return true;
}

/// The iterations of one file: (number, its group path, its time in seconds).
struct Iteration
{
  long number = 0;
  std::string file, group;
  double time = 0.0;
};

void iterationsOf(hid_t file, const std::string& fileName, const std::string& basePath, std::vector<Iteration>& found)
{
  const std::size_t mark = basePath.find("%T");
  const std::string parent = basePath.substr(0, mark); // "/data/"
  Handle data(H5Gopen2(file, parent.c_str(), H5P_DEFAULT), H5Gclose);
  if (!data.valid())
  {
    return;
  }
  for (const std::string& name : linkNames(data))
  {
    char* end = nullptr;
    const long number = std::strtol(name.c_str(), &end, 10);
    if (end == name.c_str() || *end != '\0' || !hasObject(data, name, H5O_TYPE_GROUP))
    {
      continue;
    }
    Handle iteration(H5Gopen2(data, name.c_str(), H5P_DEFAULT), H5Gclose);
    const double time =
      numberAttribute(iteration, "time", static_cast<double>(number)) * numberAttribute(iteration, "timeUnitSI", 1.0);
    found.push_back({ number, fileName, parent + name + "/", time });
  }
}
} // namespace

void describeOpenPmdFile(hid_t file, const std::string& fileName, ParticleFileInfo& info)
{
  const std::string version = rootString(file, "openPMD", "1");
  const std::string basePath = rootString(file, "basePath", "/data/%T/");
  const std::string encoding = rootString(file, "iterationEncoding", "groupBased");
  info.description = "openPMD " + version + (encoding == "fileBased" ? ", a file per iteration" : "");
  std::vector<Iteration> iterations;
  if (encoding == "fileBased")
  {
    // The files of the series: the iterationFormat's name with a number for %T, in this folder.
    const std::string format = rootString(file, "iterationFormat", "");
    const std::size_t slash = fileName.rfind('/');
    const std::string folder = slash == std::string::npos ? "." : fileName.substr(0, slash);
    const std::string leaf = format.substr(format.rfind('/') == std::string::npos ? 0 : format.rfind('/') + 1);
    const std::size_t mark = leaf.find("%");
    const std::size_t letter = leaf.find('T', mark == std::string::npos ? 0 : mark);
    if (mark == std::string::npos || letter == std::string::npos)
    {
      info.error = "'" + fileName + "': iterationEncoding is fileBased but iterationFormat '" + format +
                   "' has no %T to find the other files by";
      return;
    }
    const std::string prefix = leaf.substr(0, mark), suffix = leaf.substr(letter + 1);
    std::vector<std::string> files;
    if (DIR* dir = ::opendir(folder.c_str()))
    {
      while (const dirent* entry = ::readdir(dir))
      {
        long number = 0;
        if (iterationOfFile(entry->d_name, prefix, suffix, number))
        {
          files.push_back(folder + "/" + entry->d_name);
        }
      }
      ::closedir(dir);
    }
    for (const std::string& path : files)
    {
      std::string error;
      Handle other(openForReading(path, error), H5Fclose);
      if (other.valid())
      {
        iterationsOf(other, path, basePath, iterations);
      }
      else
      {
        info.warnings.push_back(error + "; that iteration is left out");
      }
    }
  }
  else
  {
    iterationsOf(file, fileName, basePath, iterations);
  }
  if (iterations.empty())
  {
    info.error = "'" + fileName + "': the openPMD file has no iterations under '" + basePath + "'";
    return;
  }
  std::sort(iterations.begin(), iterations.end(),
            [](const Iteration& a, const Iteration& b) { return a.number < b.number; });
  for (const Iteration& it : iterations)
  {
    if (!std::isfinite(it.time) || (!info.times.empty() && !(it.time > info.times.back())))
    {
      info.warnings.push_back("iteration " + std::to_string(it.number) +
                              "'s time is not after the one before; the iterations are offered at their numbers");
      info.times.clear();
      for (const Iteration& each : iterations)
      {
        info.times.push_back(static_cast<double>(each.number));
      }
      break;
    }
    info.times.push_back(it.time);
  }
  info.files.clear();
  for (const Iteration& it : iterations)
  {
    info.frameFiles.push_back(it.file);
    info.frameGroups.push_back(it.group);
    if (std::find(info.files.begin(), info.files.end(), it.file) == info.files.end())
    {
      info.files.push_back(it.file);
    }
  }
}

ParticleFrame describeOpenPmdFrame(const ParticleFileInfo& info, std::size_t timeIndex)
{
  ParticleFrame frame;
  frame.time = info.times[timeIndex];
  frame.fields.push_back({ "time", { frame.time } });
  const std::string& fileName = info.frameFiles[timeIndex];
  std::string error;
  Handle file(openForReading(fileName, error), H5Fclose);
  if (!file.valid())
  {
    frame.error = error;
    return frame;
  }
  const std::string particlesPath = info.frameGroups[timeIndex] + rootString(file, "particlesPath", "particles/");
  Handle particles(H5Gopen2(file, particlesPath.c_str(), H5P_DEFAULT), H5Gclose);
  if (!particles.valid())
  {
    return frame; // an iteration of meshes only: no particles at this time
  }
  for (const std::string& name : linkNames(particles))
  {
    Handle species(H5Gopen2(particles, name.c_str(), H5P_DEFAULT), H5Gclose);
    const std::string where = particlesPath + name;
    if (!species.valid() || !hasObject(species, "position", H5O_TYPE_GROUP))
    {
      frame.warnings.push_back(where + " has no position record and is left out");
      continue;
    }
    ParticleBlock block;
    block.name = name;
    BlockPart part{ fileName, where, {} };
    StepLayout& layout = part.layout;
    // position + positionOffset, per axis: datasets scaled by unitSI, constants shifted.
    layout.coordinates.datasets.assign(3, "");
    layout.coordinateOffset.datasets.assign(3, "");
    layout.coordinates.components = layout.coordinateOffset.components = 3;
    bool haveRows = false;
    for (int a = 0; a < 3; ++a)
    {
      for (const char* record : { "position", "positionOffset" })
      {
        const std::string path = std::string(record) + "/" + kAxes[a];
        if (H5Lexists(species, record, H5P_DEFAULT) <= 0 || H5Lexists(species, path.c_str(), H5P_DEFAULT) <= 0)
        {
          continue;
        }
        const Component c = readComponent(species, path);
        if (!c.problem.empty() || c.columns != 1)
        {
          frame.error = where + "/" + path + ": " + (c.problem.empty() ? "expected one value per particle" : c.problem);
          return frame;
        }
        if (haveRows && c.rows != layout.particles)
        {
          frame.error = where + "/" + path + " has " + std::to_string(c.rows) + " values for " +
                        std::to_string(layout.particles) + " particles";
          return frame;
        }
        layout.particles = c.rows;
        haveRows = true;
        ArraySource& target = std::string(record) == "position" ? layout.coordinates : layout.coordinateOffset;
        if (c.constant)
        {
          layout.coordinateShift[a] += c.value * c.unitSI;
          continue;
        }
        if (!target.datasets[0].empty() || !target.datasets[1].empty() || !target.datasets[2].empty())
        {
          if (target.scale != c.unitSI)
          {
            frame.error = where + "/" + record + ": its components have different unitSI";
            return frame;
          }
        }
        target.scale = c.unitSI;
        target.datasets[a] = c.dataset;
      }
    }
    if (!haveRows)
    {
      frame.error = where + "/position has no x, y or z component";
      return frame;
    }
    Handle position(H5Gopen2(species, "position", H5P_DEFAULT), H5Gclose);
    layout.coordinates.unit = unitOf(position);
    if (std::all_of(layout.coordinateOffset.datasets.begin(), layout.coordinateOffset.datasets.end(),
                    [](const std::string& d) { return d.empty(); }))
    {
      layout.coordinateOffset.datasets.clear();
    }
    layout.coordinateDatasets = layout.coordinates.datasets;
    for (const std::string& record : linkNames(species))
    {
      if (record == "position" || record == "positionOffset")
      {
        continue;
      }
      Handle recordObject(H5Oopen(species, record.c_str(), H5P_DEFAULT), H5Oclose);
      const std::string unit = recordObject.valid() ? unitOf(recordObject) : "";
      const std::vector<std::string> components = componentNames(species, record);
      std::vector<Component> read;
      for (const std::string& component : components)
      {
        read.push_back(readComponent(species, component));
        if (!read.back().problem.empty() || read.back().rows != layout.particles || read.back().columns != 1)
        {
          frame.warnings.push_back(
            where + "/" + component + " is not read: " +
            (read.back().problem.empty() ? "its length is not the particles'" : read.back().problem));
          read.clear();
          break;
        }
      }
      if (read.empty())
      {
        continue;
      }
      const bool allDatasets = std::none_of(read.begin(), read.end(), [](const Component& c) { return c.constant; });
      const bool sameScale =
        std::all_of(read.begin(), read.end(), [&](const Component& c) { return c.unitSI == read[0].unitSI; });
      if (record == "id" && read.size() == 1 && !read[0].constant)
      {
        layout.idDataset = read[0].dataset;
        continue;
      }
      if (allDatasets && sameScale)
      {
        std::vector<std::string> datasets;
        for (const Component& c : read)
        {
          datasets.push_back(c.dataset);
        }
        layout.arrays.push_back({ record, datasets, static_cast<int>(read.size()), -1, read[0].unitSI, unit });
        continue;
      }
      // Mixed constants and datasets, or components of different factors: each on its own.
      for (std::size_t k = 0; k < read.size(); ++k)
      {
        const std::string label = read.size() == 1 ? record : record + "_" + components[k].substr(record.size() + 1);
        if (read[k].constant)
        {
          block.constants.push_back({ label, read[k].value * read[k].unitSI, unit });
        }
        else
        {
          layout.arrays.push_back({ label, { read[k].dataset }, 1, -1, read[k].unitSI, unit });
        }
      }
    }
    block.parts.push_back(std::move(part));
    frame.blocks.push_back(std::move(block));
  }
  return frame;
}
} // namespace parafluid::h5::detail
