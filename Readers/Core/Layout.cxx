#include "parafluid/h5part/Layout.h"

#include "parafluid/h5part/Handle.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

namespace parafluid::h5
{
namespace
{
herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* data)
{
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

std::vector<std::string> childNames(hid_t group)
{
  std::vector<std::string> names;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collectName, &names);
  return names;
}

const char* className(H5T_class_t typeClass)
{
  switch (typeClass)
  {
    case H5T_STRING:
      return "strings";
    case H5T_COMPOUND:
      return "a compound type";
    case H5T_ENUM:
      return "an enumeration (bool?)";
    case H5T_BITFIELD:
      return "a bit field";
    case H5T_OPAQUE:
      return "opaque bytes";
    case H5T_REFERENCE:
      return "references";
    case H5T_VLEN:
      return "variable-length sequences";
    case H5T_ARRAY:
      return "an array type";
    default:
      return "a type that is not a number";
  }
}

/// Dimensions of a numeric dataset of one or two dimensions; empty (with `why` set when the
/// object is a dataset the user may have meant as an array) otherwise.
/// The dataset `name` of `group` when it holds numbers; an invalid handle with `why` otherwise.
Handle openNumeric(hid_t group, const std::string& name, std::string& why)
{
  Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
  {
    why = "HDF5 cannot open it";
    return dataset;
  }
  Handle type(H5Dget_type(dataset), H5Tclose);
  const H5T_class_t typeClass = H5Tget_class(type);
  if (typeClass != H5T_FLOAT && typeClass != H5T_INTEGER)
  {
    why = std::string("it holds ") + className(typeClass);
    return Handle();
  }
  return dataset;
}

std::vector<std::uint64_t> numericShape(hid_t group, const std::string& name, std::string& why)
{
  H5O_info_t info;
  if (H5Oget_info_by_name(group, name.c_str(), &info, H5P_DEFAULT) < 0)
  {
    why = "it is a link to nothing (dangling, or to a missing file)";
    return {};
  }
  if (info.type != H5O_TYPE_DATASET)
  {
    return {};
  }
  Handle dataset = openNumeric(group, name, why);
  if (!dataset.valid())
  {
    return {};
  }
  Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > 2)
  {
    why = rank < 1 ? "it is a single value, not one per particle" : std::to_string(rank) + "-dimensional";
    return {};
  }
  hsize_t dims[2] = { 0, 1 };
  H5Sget_simple_extent_dims(space, dims, nullptr);
  if (rank == 2 && dims[1] == 0)
  {
    why = "it has no columns (N x 0)";
    return {};
  }
  if (rank == 2 && dims[1] > kMaxComponents)
  {
    why = "it has " + std::to_string(dims[1]) + " columns; a point array has at most " + std::to_string(kMaxComponents);
    return {};
  }
  return std::vector<std::uint64_t>(dims, dims + rank);
}

/// "vx" -> "velocity", "velocity_x" -> "velocity"; empty when the name is no x component.
std::string vectorBaseOfX(const std::string& name)
{
  static const std::map<std::string, std::string> shortNames = { { "vx", "velocity" },
                                                                 { "ax", "acceleration" },
                                                                 { "fx", "force" } };
  const auto found = shortNames.find(name);
  if (found != shortNames.end())
  {
    return found->second;
  }
  if (name.size() > 2 && name.compare(name.size() - 2, 2, "_x") == 0)
  {
    return name.substr(0, name.size() - 2);
  }
  return {};
}

std::string componentName(const std::string& xName, char axis)
{
  std::string n = xName;
  n.back() = axis;
  return n;
}

std::string folderOf(hid_t object)
{
  const ssize_t length = H5Fget_name(object, nullptr, 0);
  if (length <= 0)
  {
    return ".";
  }
  std::string name(static_cast<std::size_t>(length) + 1, '\0');
  H5Fget_name(object, name.data(), name.size());
  name.resize(static_cast<std::size_t>(length));
  const auto slash = name.rfind('/');
  return slash == std::string::npos ? "." : name.substr(0, slash);
}

bool readable(const std::string& name, const std::string& folder)
{
  const std::string path = !name.empty() && name[0] == '/' ? name : folder + "/" + name;
  return ::access(path.c_str(), R_OK) == 0;
}

std::string checkVirtual(hid_t properties, hssize_t points, const std::string& folder)
{
  std::size_t mappings = 0;
  if (H5Pget_virtual_count(properties, &mappings) < 0)
  {
    return "HDF5 cannot read the mappings of the virtual dataset";
  }
  hssize_t mapped = 0;
  for (std::size_t k = 0; k < mappings; ++k)
  {
    const ssize_t length = H5Pget_virtual_filename(properties, k, nullptr, 0);
    if (length < 0)
    {
      return "HDF5 cannot read the source of the virtual dataset";
    }
    std::string source(static_cast<std::size_t>(length) + 1, '\0');
    H5Pget_virtual_filename(properties, k, source.data(), source.size());
    source.resize(static_cast<std::size_t>(length));
    if (source != "." && !readable(source, folder))
    {
      return "its source file '" + source + "' (it is a virtual dataset) is missing or unreadable";
    }
    Handle space(H5Pget_virtual_vspace(properties, k), H5Sclose);
    mapped += space.valid() ? H5Sget_select_npoints(space) : 0;
  }
  if (mapped < points)
  {
    return "only " + std::to_string(mapped) + " of its " + std::to_string(points) +
           " values map to a source (it is a virtual dataset)";
  }
  return {};
}
} // namespace

std::string checkStorage(hid_t dataset, const std::string& folder)
{
  Handle properties(H5Dget_create_plist(dataset), H5Pclose);
  Handle space(H5Dget_space(dataset), H5Sclose);
  const hssize_t points = H5Sget_simple_extent_npoints(space);
  if (!properties.valid() || points <= 0)
  {
    return {};
  }
  switch (H5Pget_layout(properties))
  {
    case H5D_VIRTUAL:
      return checkVirtual(properties, points, folder);
    case H5D_CHUNKED:
    {
      const int rank = H5Sget_simple_extent_ndims(space);
      if (rank < 1 || rank > 8)
      {
        return {};
      }
      hsize_t dims[8], chunk[8];
      H5Sget_simple_extent_dims(space, dims, nullptr);
      if (H5Pget_chunk(properties, rank, chunk) != rank)
      {
        return "HDF5 cannot read its chunk layout";
      }
      hsize_t expected = 1;
      for (int a = 0; a < rank; ++a)
      {
        expected *= chunk[a] > 0 ? (dims[a] + chunk[a] - 1) / chunk[a] : 0;
      }
      hsize_t written = 0;
      if (H5Dget_num_chunks(dataset, space, &written) < 0 || written < expected)
      {
        return "only " + std::to_string(written) + " of its " + std::to_string(expected) +
               " chunks were ever written (the rest would be fill values, not data)";
      }
      return {};
    }
    case H5D_CONTIGUOUS:
    {
      const int external = H5Pget_external_count(properties);
      if (external > 0)
      {
        for (int k = 0; k < external; ++k)
        {
          char name[4096] = { 0 };
          off_t offset = 0;
          hsize_t size = 0;
          if (H5Pget_external(properties, static_cast<unsigned>(k), sizeof(name) - 1, name, &offset, &size) < 0 ||
              !readable(name, folder))
          {
            return std::string("its external storage file '") + name + "' is missing or unreadable";
          }
        }
        return {};
      }
      const haddr_t offset = H5Dget_offset(dataset);
      if (offset == HADDR_UNDEF)
      {
        return "its values were never written";
      }
      Handle file(H5Iget_file_id(dataset), H5Fclose);
      hsize_t fileSize = 0;
      const hsize_t bytes = H5Dget_storage_size(dataset);
      if (file.valid() && H5Fget_filesize(file, &fileSize) >= 0 && offset + bytes > fileSize)
      {
        return "its values end beyond the end of the file (a truncated file?)";
      }
      return {};
    }
    default:
      return {}; // compact: the values are in the object header, which HDF5 has read
  }
}

bool readNumericAttribute(hid_t object, const char* name, std::vector<double>& values, std::size_t maxValues)
{
  if (H5Aexists(object, name) <= 0)
  {
    return false;
  }
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid())
  {
    return false;
  }
  Handle type(H5Aget_type(attribute), H5Tclose);
  const H5T_class_t typeClass = H5Tget_class(type);
  if (typeClass != H5T_FLOAT && typeClass != H5T_INTEGER)
  {
    return false;
  }
  Handle space(H5Aget_space(attribute), H5Sclose);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count <= 0 || static_cast<std::size_t>(count) > maxValues)
  {
    return false;
  }
  values.resize(static_cast<std::size_t>(count));
  return H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()) >= 0;
}

hid_t openForReading(const std::string& fileName, std::string& error, bool scatteredRows)
{
  if (fileName.empty())
  {
    error = "no file name was given";
    return -1;
  }
  // H5Fis_hdf5 blocks forever on a named pipe and fails oddly on folders and devices: only
  // regular files (or links to one) go to HDF5.
  struct stat status;
  if (::stat(fileName.c_str(), &status) != 0 || ::access(fileName.c_str(), R_OK) != 0)
  {
    error = "cannot open '" + fileName + "' (missing or unreadable)";
    return -1;
  }
  if (!S_ISREG(status.st_mode))
  {
    error = "'" + fileName + "' is not a regular file (a folder, pipe or device)";
    return -1;
  }
  QuietErrors quiet;
  if (H5Fis_hdf5(fileName.c_str()) <= 0)
  {
    error = "'" + fileName + "' is not an HDF5 file";
    return -1;
  }
  // Without a sieve buffer for reads of scattered row blocks: HDF5's 64 KiB read-ahead read 90 %
  // of a small cell-indexed snapshot for a 1.2 % box; whole-array reads keep it (0.39 s against
  // 0.92 s for a 10 M snapshot, though that pair was measured on a noisy machine).
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (access.valid() && scatteredRows)
  {
    H5Pset_sieve_buf_size(access, 0);
  }
  const hid_t file = H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, access.valid() ? access.get() : H5P_DEFAULT);
  if (file < 0)
  {
    error = "HDF5 could not open '" + fileName + "'";
  }
  return file;
}

namespace
{
/// The file address of the object `name` in `group` (0 when it cannot be read).
haddr_t objectAddress(hid_t group, const std::string& name)
{
  H5O_info_t info;
  return H5Oget_info_by_name(group, name.c_str(), &info, H5P_DEFAULT) < 0 ? 0 : info.addr;
}

/// Steps that are not what their names say: two groups numbering the same step (the second is
/// dropped), and step groups or datasets that are one object in the file (a damaged or copied
/// link would show one step's particles as another's), named in warnings.
void checkDistinctSteps(hid_t file, std::vector<StepEntry>& steps, std::vector<std::string>* warnings)
{
  std::map<long, std::string> byIndex;
  std::map<haddr_t, std::string> owners;
  std::vector<StepEntry> kept;
  std::vector<std::string> found;
  for (const StepEntry& entry : steps)
  {
    const auto [first, fresh] = byIndex.emplace(entry.index, entry.group);
    if (!fresh)
    {
      found.push_back(entry.group + " and " + first->second + " both number step " + std::to_string(entry.index) +
                      "; " + entry.group + " is left out");
      continue;
    }
    kept.push_back(entry);
    const haddr_t groupAddress = objectAddress(file, entry.group);
    if (groupAddress != 0)
    {
      const auto [owner, own] = owners.emplace(groupAddress, entry.group);
      if (!own)
      {
        found.push_back(entry.group + " is the same group in the file as " + owner->second + ": step " +
                        std::to_string(entry.index) + " shows the particles of " + owner->second +
                        " (a damaged or hard link?)");
        continue;
      }
    }
    Handle group(H5Gopen2(file, entry.group.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.valid())
    {
      continue;
    }
    for (const std::string& child : childNames(group))
    {
      const haddr_t address = objectAddress(group, child);
      if (address == 0)
      {
        continue;
      }
      const std::string path = entry.group + "/" + child;
      const auto [owner, own] = owners.emplace(address, path);
      if (!own)
      {
        found.push_back(path + " is the same dataset in the file as " + owner->second + ": step " +
                        std::to_string(entry.index) + " shows its values (a damaged or hard link?)");
      }
    }
  }
  steps = std::move(kept);
  // A few named, the rest counted: a file that hard-links one array into every step says so once.
  for (std::size_t k = 0; warnings && k < found.size() && k < 3; ++k)
  {
    warnings->push_back(found[k]);
  }
  if (warnings && found.size() > 3)
  {
    warnings->push_back("and " + std::to_string(found.size() - 3) + " more steps or datasets shared like these");
  }
}
} // namespace

std::vector<StepEntry> listSteps(hid_t file, std::string& error, std::vector<std::string>* warnings)
{
  std::vector<StepEntry> steps;
  for (const std::string& name : childNames(file))
  {
    if (name.rfind("Step#", 0) != 0)
    {
      continue;
    }
    char* end = nullptr;
    const long index = std::strtol(name.c_str() + 5, &end, 10);
    if (end == name.c_str() + 5 || *end != '\0')
    {
      continue;
    }
    StepEntry entry;
    entry.group = name;
    entry.index = index;
    entry.time = static_cast<double>(index);
    H5O_info_t info;
    if (H5Oget_info_by_name(file, name.c_str(), &info, H5P_DEFAULT) < 0 || info.type != H5O_TYPE_GROUP)
    {
      continue;
    }
    Handle group(H5Gopen2(file, name.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.valid())
    {
      continue;
    }
    for (const char* attribute : { "time", "Time", "TimeValue" })
    {
      std::vector<double> value;
      if (readNumericAttribute(group, attribute, value))
      {
        entry.time = value[0];
        break;
      }
    }
    steps.push_back(entry);
  }
  // Of two groups numbering one step, the one named as H5Part names it ("Step#1", not "Step#01")
  // comes first and is kept, else the first in the file's order.
  const auto canonical = [](const StepEntry& e) { return e.group == "Step#" + std::to_string(e.index); };
  std::stable_sort(steps.begin(), steps.end(),
                   [&canonical](const StepEntry& a, const StepEntry& b)
                   { return a.index < b.index || (a.index == b.index && canonical(a) && !canonical(b)); });
  checkDistinctSteps(file, steps, warnings);
  if (steps.empty())
  {
    error = "the file has no H5Part step groups (\"Step#0\", \"Step#1\", ...)";
    return steps;
  }
  // Times must be finite and increasing for the pipeline to reach every step; otherwise each
  // step's time is its position, and the user is told which step broke the order.
  std::string broken;
  for (std::size_t k = 0; k < steps.size() && broken.empty(); ++k)
  {
    if (!std::isfinite(steps[k].time))
    {
      broken = steps[k].group + " has a NaN or infinite time";
    }
    else if (k > 0 && !(steps[k].time > steps[k - 1].time))
    {
      broken = "the time of " + steps[k].group + " is not after that of " + steps[k - 1].group;
    }
  }
  if (!broken.empty())
  {
    for (std::size_t k = 0; k < steps.size(); ++k)
    {
      steps[k].time = static_cast<double>(k);
    }
    if (warnings)
    {
      warnings->push_back(broken + "; the steps are offered at times 0, 1, 2, ... in file order");
    }
  }
  return steps;
}

std::vector<std::uint64_t> datasetShape(hid_t group, const std::string& name, std::string& problem)
{
  Handle dataset = openNumeric(group, name, problem);
  if (!dataset.valid())
  {
    return {};
  }
  problem = checkStorage(dataset, folderOf(group));
  if (!problem.empty())
  {
    return {};
  }
  Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  if (rank < 0 || rank > 3 || H5Sget_simple_extent_dims(space, dims.data(), nullptr) < 0)
  {
    problem = "it has " + std::to_string(rank) + " dimensions";
    return {};
  }
  return std::vector<std::uint64_t>(dims.begin(), dims.end()); // a scalar: empty, no problem
}

StepLayout describeStep(hid_t file, const std::string& groupName)
{
  return describeStep(file, groupName, DatasetNames{});
}

StepLayout describeStep(hid_t file, const std::string& groupName, const DatasetNames& names)
{
  StepLayout layout;
  Handle group(H5Gopen2(file, groupName.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid())
  {
    layout.error = "cannot open group " + groupName;
    return layout;
  }
  const std::string folder = folderOf(file);
  std::map<std::string, std::vector<std::uint64_t>> shapes;
  for (const std::string& name : childNames(group))
  {
    if (names.skip.count(name))
    {
      continue;
    }
    std::string why;
    auto shape = numericShape(group, name, why);
    if (!shape.empty())
    {
      shapes[name] = shape;
    }
    else if (!why.empty())
    {
      layout.warnings.push_back(groupName + "/" + name + " is not read: " + why);
    }
  }
  if (shapes.empty())
  {
    layout.error = groupName + " holds no numeric datasets (an empty step)";
    for (const std::string& warning : layout.warnings)
    {
      layout.error += "; " + warning;
    }
    return layout;
  }
  // A dataset that does not hold what it declares: an error for coordinates, left out otherwise.
  auto storageProblem = [&](const std::string& name)
  {
    Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
    return dataset.valid() ? checkStorage(dataset, folder) : std::string("HDF5 cannot open it");
  };

  auto isVector3 = [&](const std::string& n)
  {
    const auto s = shapes.find(n);
    return s != shapes.end() && s->second.size() == 2 && s->second[1] == 3;
  };
  if (shapes.count("x") && shapes.count("y") && shapes.count("z"))
  {
    layout.coordinateDatasets = { "x", "y", "z" };
    layout.particles = shapes["x"][0];
    for (const char* axis : { "x", "y", "z" })
    {
      if (shapes[axis].size() != 1 || shapes[axis][0] != layout.particles)
      {
        layout.error = groupName + ": coordinate datasets x, y, z must be 1-D and of equal length (x has " +
                       std::to_string(layout.particles) + " values, " + axis + " has " +
                       std::to_string(shapes[axis][0]) + (shapes[axis].size() == 1 ? ")" : " rows of 2-D values)");
        return layout;
      }
    }
  }
  else if (const auto vector = std::find_if(names.coordinates.begin(), names.coordinates.end(),
                                            [&](const std::string& n) { return isVector3(n); });
           vector != names.coordinates.end())
  {
    layout.coordinateDatasets = { *vector };
    layout.particles = shapes[*vector][0];
  }
  else
  {
    layout.error = groupName + " has no particle coordinates: expected datasets x, y, z or an N x 3 \"" +
                   names.coordinates.front() + "\"";
    return layout;
  }
  for (const std::string& name : layout.coordinateDatasets)
  {
    const std::string problem = storageProblem(name);
    if (!problem.empty())
    {
      layout.error = groupName + "/" + name + ": " + problem;
      return layout;
    }
  }

  std::set<std::string> used(layout.coordinateDatasets.begin(), layout.coordinateDatasets.end());
  const auto idName =
    std::find_if(names.ids.begin(), names.ids.end(), [&](const std::string& n) { return shapes.count(n) > 0; });
  if (idName != names.ids.end())
  {
    const std::string id = *idName;
    used.insert(id);
    const auto& shape = shapes[id];
    std::string problem = storageProblem(id);
    if (problem.empty() && (shape.size() != 1 || shape[0] != layout.particles))
    {
      problem = shape.size() != 1 ? "it has " + std::to_string(shape[1]) + " values per particle, not one"
                                  : "it has " + std::to_string(shape[0]) + " values for " +
                                      std::to_string(layout.particles) + " particles";
    }
    if (problem.empty())
    {
      layout.idDataset = id;
    }
    else
    {
      layout.warnings.push_back(groupName + "/" + id + " is not used (" + problem +
                                "); each particle's id is its index in the file");
    }
  }
  // Component triples first, so vx/vy/vz do not also show up as three scalars: the layout's own
  // named triples, then the ones found by name.
  std::vector<std::pair<std::string, std::vector<std::string>>> triples = names.vectors;
  for (const auto& entry : shapes)
  {
    const std::string base = vectorBaseOfX(entry.first);
    if (!base.empty())
    {
      triples.push_back({ base, { entry.first, componentName(entry.first, 'y'), componentName(entry.first, 'z') } });
    }
  }
  for (const auto& [base, components] : triples)
  {
    const std::string& name = components[0];
    const auto x = shapes.find(name);
    if (x == shapes.end() || used.count(name))
    {
      continue;
    }
    const auto& shape = x->second;
    const std::string& yName = components[1];
    const std::string& zName = components[2];
    const auto y = shapes.find(yName);
    const auto z = shapes.find(zName);
    if (y == shapes.end() || z == shapes.end() || shape != y->second || shape != z->second || shape.size() != 1)
    {
      continue;
    }
    if (shape[0] != layout.particles)
    {
      layout.error = groupName + ": datasets " + name + ", " + yName + ", " + zName + " have " +
                     std::to_string(shape[0]) + " values for " + std::to_string(layout.particles) + " particles";
      return layout;
    }
    used.insert({ name, yName, zName });
    std::string problem;
    for (const std::string& component : { name, yName, zName })
    {
      problem = problem.empty() ? storageProblem(component) : problem;
    }
    if (!problem.empty())
    {
      layout.warnings.push_back(groupName + ": " + base + " (" + name + ", " + yName + ", " + zName +
                                ") is not read: " + problem);
      continue;
    }
    layout.arrays.push_back({ base, { name, yName, zName }, 3 });
  }
  for (const auto& [name, shape] : shapes)
  {
    if (used.count(name))
    {
      continue;
    }
    if (shape[0] != layout.particles)
    {
      layout.error = groupName + ": dataset " + name + " has " + std::to_string(shape[0]) + " values for " +
                     std::to_string(layout.particles) + " particles";
      return layout;
    }
    const std::string problem = storageProblem(name);
    if (!problem.empty())
    {
      layout.warnings.push_back(groupName + "/" + name + " is not read: " + problem);
      continue;
    }
    const int components = shape.size() == 2 ? static_cast<int>(shape[1]) : 1;
    const auto renamed = names.arrays.find(name);
    layout.arrays.push_back({ renamed != names.arrays.end() ? renamed->second : name, { name }, components });
  }
  layout.coordinates = { "", layout.coordinateDatasets, 3 };
  return layout;
}
} // namespace parafluid::h5
