#include "parafluid/h5part/ParticleLayouts.h"

#include "parafluid/h5part/Attributes.h"
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <algorithm>

namespace parafluid::h5
{
std::uint64_t ParticleBlock::particles() const
{
  std::uint64_t total = 0;
  for (const BlockPart& part : this->parts)
  {
    total += part.layout.particles;
  }
  return total;
}

namespace detail
{
namespace
{
herr_t collect(hid_t, const char* name, const H5L_info_t*, void* data)
{
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}
} // namespace

std::vector<std::string> linkNames(hid_t group)
{
  std::vector<std::string> names;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names);
  return names;
}

bool hasObject(hid_t group, const std::string& name, H5O_type_t type)
{
  if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0)
  {
    return false;
  }
  H5O_info_t info;
  return H5Oget_info_by_name(group, name.c_str(), &info, H5P_DEFAULT) >= 0 && info.type == type;
}

bool readSmallDataset(hid_t group, const std::string& name, std::vector<double>& values, std::size_t maxValues)
{
  if (!hasObject(group, name, H5O_TYPE_DATASET))
  {
    return false;
  }
  Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  Handle type(dataset.valid() ? H5Dget_type(dataset) : -1, H5Tclose);
  Handle space(dataset.valid() ? H5Dget_space(dataset) : -1, H5Sclose);
  if (!type.valid() || !space.valid() || (H5Tget_class(type) != H5T_FLOAT && H5Tget_class(type) != H5T_INTEGER))
  {
    return false;
  }
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count < 1 || static_cast<std::size_t>(count) > maxValues)
  {
    return false;
  }
  values.resize(static_cast<std::size_t>(count));
  return H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
}

std::vector<std::string> stringAttribute(hid_t object, const char* name)
{
  std::vector<std::string> ignored;
  for (const Attribute& attribute : readAttributes(object, ignored))
  {
    if (attribute.name == name && attribute.text)
    {
      return attribute.strings;
    }
  }
  return {};
}
} // namespace detail

ParticleLayout detectLayout(hid_t file)
{
  if (H5Aexists(file, "openPMD") > 0 && H5Aexists(file, "basePath") > 0)
  {
    return ParticleLayout::OpenPMD;
  }
  if (detail::hasObject(file, "VTKHDF", H5O_TYPE_GROUP))
  {
    return ParticleLayout::VTKHDF;
  }
  if (detail::hasObject(file, "h5md", H5O_TYPE_GROUP) && detail::hasObject(file, "particles", H5O_TYPE_GROUP))
  {
    return ParticleLayout::H5MD;
  }
  if (detail::isPySphFile(file))
  {
    return ParticleLayout::PySPH;
  }
  if (detail::hasObject(file, "Header", H5O_TYPE_GROUP))
  {
    for (const std::string& name : detail::linkNames(file))
    {
      if (name.rfind("PartType", 0) == 0)
      {
        return ParticleLayout::Gadget;
      }
    }
  }
  for (const std::string& name : detail::linkNames(file))
  {
    if (name.rfind("Step#", 0) == 0)
    {
      return ParticleLayout::H5Part;
    }
  }
  return ParticleLayout::Unknown;
}

const char* layoutName(ParticleLayout layout)
{
  switch (layout)
  {
    case ParticleLayout::H5Part:
      return "H5Part";
    case ParticleLayout::H5MD:
      return "H5MD";
    case ParticleLayout::Gadget:
      return "Gadget-style snapshot";
    case ParticleLayout::OpenPMD:
      return "openPMD";
    case ParticleLayout::VTKHDF:
      return "VTKHDF";
    case ParticleLayout::PySPH:
      return "PySPH output";
    default:
      return "unknown";
  }
}

namespace
{
/// Makes `info`, of a file of one time, the first of the numbered series its name is in: the
/// members of the same layout and of one time each, with their times (members that are not are
/// left out, with a warning).
void gatherSeries(const std::string& fileName, ParticleFileInfo& info)
{
  const std::vector<std::string> members = detail::numberedSeries(fileName, info.files.size() > 1);
  std::vector<std::string> kept;
  std::vector<double> times;
  std::vector<std::string> warnings;
  for (const std::string& member : members)
  {
    const ParticleFileInfo other = member == fileName ? info : describeParticleFile(member, false);
    const std::string why = !other.error.empty()          ? other.error
                            : other.layout != info.layout ? std::string("it is ") + layoutName(other.layout)
                            : other.times.size() != 1     ? std::to_string(other.times.size()) + " times"
                                                          : "";
    if (why.empty())
    {
      kept.push_back(member);
      times.push_back(other.times.front());
    }
    else if (warnings.size() < 3)
    {
      warnings.push_back("'" + member + "' is left out of the series: " + why);
    }
  }
  if (kept.size() < 2)
  {
    return;
  }
  if (std::adjacent_find(times.begin(), times.end(), [](double a, double b) { return !(a < b); }) != times.end())
  {
    warnings.push_back("the series' times do not increase with the files' numbers; each file's time is its "
                       "position in the series");
    for (std::size_t k = 0; k < times.size(); ++k)
    {
      times[k] = static_cast<double>(k);
    }
  }
  info.seriesFiles = kept;
  info.times = times;
  info.description += ", series of " + std::to_string(kept.size()) + " files";
  info.warnings.insert(info.warnings.end(), warnings.begin(), warnings.end());
}
} // namespace

ParticleFileInfo describeParticleFile(const std::string& fileName, bool findSeries)
{
  ParticleFileInfo info;
  std::string error;
  Handle file(openForReading(fileName, error), H5Fclose);
  if (!file.valid())
  {
    info.error = error;
    return info;
  }
  info.layout = detectLayout(file);
  info.files = { fileName };
  switch (info.layout)
  {
    case ParticleLayout::H5MD:
      detail::describeH5mdFile(file, info);
      break;
    case ParticleLayout::Gadget:
      detail::describeGadgetFile(file, fileName, info);
      break;
    case ParticleLayout::OpenPMD:
      detail::describeOpenPmdFile(file, fileName, info);
      break;
    case ParticleLayout::VTKHDF:
      detail::describeVtkHdfFile(file, info);
      break;
    case ParticleLayout::PySPH:
      detail::describePySphFile(file, info);
      break;
    case ParticleLayout::H5Part:
      info.description = "H5Part";
      for (const StepEntry& step : listSteps(file, info.error, &info.warnings))
      {
        info.times.push_back(step.time);
      }
      break;
    default:
      info.error = "'" + fileName +
                   "' is HDF5 but none of the particle layouts read here: looked for an /h5md group with "
                   "/particles (H5MD), /Header with /PartType<n> groups (Gadget, SWIFT, GIZMO, AREPO), the "
                   "root attributes openPMD and basePath (openPMD), a /VTKHDF group (VTKHDF), /particles/<name>/arrays "
                   "with /solver_data (PySPH) and \"Step#<n>\" groups (H5Part)";
  }
  if (info.error.empty() && info.times.empty())
  {
    info.error = "'" + fileName + "': the " + std::string(layoutName(info.layout)) + " file has no particles";
  }
  if (findSeries && info.error.empty() && info.times.size() == 1 && info.layout != ParticleLayout::OpenPMD)
  {
    gatherSeries(fileName, info);
  }
  return info;
}

ParticleFrame describeFrame(const ParticleFileInfo& info, std::size_t timeIndex)
{
  ParticleFrame frame;
  if (!info.error.empty() || timeIndex >= info.times.size())
  {
    frame.error = info.error.empty() ? "no such time" : info.error;
    return frame;
  }
  if (!info.seriesFiles.empty())
  {
    const ParticleFileInfo member = describeParticleFile(info.seriesFiles[timeIndex], false);
    if (!member.error.empty())
    {
      frame.error = member.error;
      return frame;
    }
    frame = describeFrame(member, 0);
    frame.time = info.times[timeIndex];
    return frame;
  }
  if (info.layout == ParticleLayout::Gadget)
  {
    return detail::describeGadgetFrame(info);
  }
  if (info.layout == ParticleLayout::OpenPMD)
  {
    return detail::describeOpenPmdFrame(info, timeIndex);
  }
  std::string error;
  Handle file(openForReading(info.files.front(), error), H5Fclose);
  if (!file.valid())
  {
    frame.error = error;
    return frame;
  }
  if (info.layout == ParticleLayout::H5MD)
  {
    return detail::describeH5mdFrame(file, info, timeIndex);
  }
  if (info.layout == ParticleLayout::VTKHDF)
  {
    return detail::describeVtkHdfFrame(file, info, timeIndex);
  }
  if (info.layout == ParticleLayout::PySPH)
  {
    return detail::describePySphFrame(file, info);
  }
  // H5Part: one block, the step at this time.
  std::vector<std::string> ignored;
  const std::vector<StepEntry> steps = listSteps(file, error, &ignored);
  if (timeIndex >= steps.size())
  {
    frame.error = error.empty() ? "the file changed since it was opened" : error;
    return frame;
  }
  ParticleBlock block{ "particles",
                       { { info.files.front(), steps[timeIndex].group, describeStep(file, steps[timeIndex].group) } },
                       {} };
  frame.time = steps[timeIndex].time;
  frame.error = block.parts.front().layout.error;
  frame.warnings = block.parts.front().layout.warnings;
  frame.blocks.push_back(std::move(block));
  return frame;
}
} // namespace parafluid::h5
