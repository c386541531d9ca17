#include "H5PartLayout.h"

#include "H5Handle.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

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

/// Dimensions of a dataset; empty when it is not a numeric dataset.
std::vector<hsize_t> numericShape(hid_t group, const std::string& name)
{
  H5O_info_t info;
  if (H5Oget_info_by_name2(group, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0 ||
      info.type != H5O_TYPE_DATASET)
  {
    return {};
  }
  Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
  {
    return {};
  }
  Handle type(H5Dget_type(dataset), H5Tclose);
  const H5T_class_t typeClass = H5Tget_class(type);
  if (typeClass != H5T_FLOAT && typeClass != H5T_INTEGER)
  {
    return {};
  }
  Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > 2)
  {
    return {};
  }
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return dims;
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
} // namespace

bool readNumericAttribute(hid_t object, const char* name, std::vector<double>& values)
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
  if (count <= 0 || count > 4096)
  {
    return false;
  }
  values.resize(static_cast<std::size_t>(count));
  return H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()) >= 0;
}

std::vector<StepEntry> listSteps(hid_t file, std::string& error)
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
  std::sort(steps.begin(), steps.end(), [](const StepEntry& a, const StepEntry& b) { return a.index < b.index; });
  if (steps.empty())
  {
    error = "the file has no H5Part step groups (\"Step#0\", \"Step#1\", ...)";
  }
  return steps;
}

StepLayout describeStep(hid_t file, const std::string& groupName)
{
  StepLayout layout;
  Handle group(H5Gopen2(file, groupName.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid())
  {
    layout.error = "cannot open group " + groupName;
    return layout;
  }
  const std::vector<std::string> names = childNames(group);
  std::map<std::string, std::vector<hsize_t>> shapes;
  for (const std::string& name : names)
  {
    auto shape = numericShape(group, name);
    if (!shape.empty())
    {
      shapes[name] = shape;
    }
  }
  if (shapes.empty())
  {
    layout.error = groupName + " holds no numeric datasets (an empty step)";
    return layout;
  }

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
                       std::to_string(shapes[axis][0]) + ")";
        return layout;
      }
    }
  }
  else if (isVector3("position") || isVector3("positions"))
  {
    const std::string name = isVector3("position") ? "position" : "positions";
    layout.coordinateDatasets = { name };
    layout.particles = shapes[name][0];
  }
  else
  {
    layout.error = groupName + " has no particle coordinates: expected datasets x, y, z or an N x 3 \"position\"";
    return layout;
  }

  std::set<std::string> used(layout.coordinateDatasets.begin(), layout.coordinateDatasets.end());
  if (shapes.count("id"))
  {
    if (shapes["id"].size() != 1 || shapes["id"][0] != layout.particles)
    {
      layout.error = groupName + ": dataset id has " + std::to_string(shapes["id"][0]) + " values for " +
                     std::to_string(layout.particles) + " particles";
      return layout;
    }
    layout.idDataset = "id";
    used.insert("id");
  }
  // Component triples first, so vx/vy/vz do not also show up as three scalars.
  for (const auto& [name, shape] : shapes)
  {
    const std::string base = vectorBaseOfX(name);
    if (base.empty() || used.count(name))
    {
      continue;
    }
    const std::string yName = componentName(name, 'y');
    const std::string zName = componentName(name, 'z');
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
    layout.arrays.push_back({ base, { name, yName, zName }, 3 });
    used.insert({ name, yName, zName });
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
    const int components = shape.size() == 2 ? static_cast<int>(shape[1]) : 1;
    layout.arrays.push_back({ name, { name }, components });
  }
  return layout;
}
} // namespace parafluid::h5
