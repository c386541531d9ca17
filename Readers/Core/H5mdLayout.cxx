// H5MD 1.x (de Buyl, Colberg & Höfling 2014, "H5MD: a structured, efficient, and portable file
// format for molecular data"): /particles/<group>/<element>, an element either a dataset (time
// independent) or a group of `value` (a leading frame axis), `step` and `time` (one per frame, or
// scalars for a fixed interval, with an optional `offset` attribute); the group's `box` gives the
// domain and its periodicity. One block per particle group.
#include "parafluid/h5part/Attributes.h"
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <algorithm>
#include <cmath>

namespace parafluid::h5::detail
{
namespace
{
// More frames than this in one element is a damaged file, not a run (a frame a second for 4 months).
constexpr std::uint64_t kMaxFrames = 10000000;

const std::map<std::string, std::string> kContractNames = { { "velocity", "velocity" },
                                                            { "force", "force" },
                                                            { "mass", "mass" } };

/// The times of a time-dependent element's `frames` frames: its `time` values (or, fixed
/// interval, offset + k x time), else its `step` values the same way, else the frame index.
std::vector<double> frameTimes(hid_t element, std::uint64_t frames)
{
  std::vector<double> times(static_cast<std::size_t>(frames));
  for (const char* name : { "time", "step" })
  {
    std::vector<double> values;
    if (!readSmallDataset(element, name, values, static_cast<std::size_t>(std::max<std::uint64_t>(frames, 1))))
    {
      continue;
    }
    Handle dataset(H5Dopen2(element, name, H5P_DEFAULT), H5Dclose);
    Handle space(H5Dget_space(dataset), H5Sclose);
    if (H5Sget_simple_extent_ndims(space) == 0)
    {
      std::vector<double> offset;
      const double start = readNumericAttribute(dataset, "offset", offset, 1) ? offset[0] : 0.0;
      for (std::size_t k = 0; k < times.size(); ++k)
      {
        times[k] = start + static_cast<double>(k) * values[0];
      }
      return times;
    }
    if (values.size() == times.size())
    {
      return values;
    }
  }
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    times[k] = static_cast<double>(k);
  }
  return times;
}

struct Element
{
  std::string dataset;              // relative to the particle group: "position/value" or "species"
  std::vector<std::uint64_t> shape; // without the frame axis
  std::vector<double> times;        // empty when time independent
  std::string unit;
  std::string problem;
};

Element readElement(hid_t group, const std::string& name)
{
  Element e;
  const bool timed = hasObject(group, name, H5O_TYPE_GROUP);
  e.dataset = timed ? name + "/value" : name;
  std::vector<std::uint64_t> shape = datasetShape(group, e.dataset, e.problem);
  if (!e.problem.empty())
  {
    return e;
  }
  Handle dataset(H5Dopen2(group, e.dataset.c_str(), H5P_DEFAULT), H5Dclose);
  const std::vector<std::string> unit = stringAttribute(dataset, "unit");
  e.unit = unit.empty() ? "" : unit.front();
  if (timed)
  {
    if (shape.empty())
    {
      e.problem = "its value has no frame axis";
      return e;
    }
    if (shape.front() > kMaxFrames)
    {
      e.problem = "it declares " + std::to_string(shape.front()) + " frames, more than " + std::to_string(kMaxFrames);
      return e;
    }
    Handle element(H5Gopen2(group, name.c_str(), H5P_DEFAULT), H5Gclose);
    e.times = frameTimes(element, shape.front());
    shape.erase(shape.begin());
  }
  e.shape = shape;
  return e;
}

/// The frame of `times` nearest `t`.
std::int64_t nearestFrame(const std::vector<double>& times, double t)
{
  std::size_t best = 0;
  for (std::size_t k = 1; k < times.size(); ++k)
  {
    if (std::fabs(times[k] - t) < std::fabs(times[best] - t))
    {
      best = k;
    }
  }
  return static_cast<std::int64_t>(best);
}

std::vector<std::string> particleGroups(hid_t file)
{
  std::vector<std::string> groups;
  Handle particles(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose);
  for (const std::string& name : linkNames(particles))
  {
    if (hasObject(particles, name, H5O_TYPE_GROUP))
    {
      groups.push_back(name);
    }
  }
  return groups;
}

void readBox(hid_t group, double t, ParticleFrame& frame)
{
  if (!hasObject(group, "box", H5O_TYPE_GROUP))
  {
    return;
  }
  Handle box(H5Gopen2(group, "box", H5P_DEFAULT), H5Gclose);
  const Element edges = readElement(box, "edges");
  std::vector<double> values;
  if (edges.problem.empty() && !edges.shape.empty())
  {
    const std::int64_t f = edges.times.empty() ? -1 : nearestFrame(edges.times, t);
    const std::size_t d = static_cast<std::size_t>(edges.shape.back());
    std::vector<double> all;
    if (readSmallDataset(box, edges.dataset, all, 1 << 20) && d >= 1 && d <= 3)
    {
      const std::size_t first = f < 0 ? 0 : static_cast<std::size_t>(f) * (all.size() / edges.times.size());
      // Edges as a vector per axis, or (triclinic) a d x d matrix whose diagonal is used.
      const bool matrix = edges.shape.size() == 2;
      for (std::size_t a = 0; a < d; ++a)
      {
        values.push_back(all[first + (matrix ? a * d + a : a)]);
      }
    }
  }
  if (!values.empty())
  {
    std::vector<double> bounds;
    for (std::size_t a = 0; a < 3; ++a)
    {
      bounds.push_back(0.0);
      bounds.push_back(a < values.size() ? values[a] : 0.0);
    }
    frame.fields.push_back({ "domain_bounds", bounds });
  }
  const std::vector<std::string> boundary = stringAttribute(box, "boundary");
  if (!boundary.empty())
  {
    std::vector<double> periodic;
    for (const std::string& b : boundary)
    {
      periodic.push_back(b == "periodic" ? 1.0 : 0.0);
    }
    frame.fields.push_back({ "domain_periodic", periodic });
  }
}
} // namespace

void describeH5mdFile(hid_t file, ParticleFileInfo& info)
{
  Handle meta(H5Gopen2(file, "h5md", H5P_DEFAULT), H5Gclose);
  std::vector<double> version;
  info.description = "H5MD";
  if (readNumericAttribute(meta, "version", version, 2) && version.size() == 2)
  {
    info.description +=
      " " + std::to_string(static_cast<int>(version[0])) + "." + std::to_string(static_cast<int>(version[1]));
  }
  if (hasObject(meta, "creator", H5O_TYPE_GROUP))
  {
    Handle creator(H5Gopen2(meta, "creator", H5P_DEFAULT), H5Gclose);
    const std::vector<std::string> name = stringAttribute(creator, "name");
    if (!name.empty())
    {
      info.description += " (" + name.front() + ")";
    }
  }
  Handle particles(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose);
  std::vector<double> times;
  for (const std::string& name : particleGroups(file))
  {
    Handle group(H5Gopen2(particles, name.c_str(), H5P_DEFAULT), H5Gclose);
    if (!hasObject(group, "position", H5O_TYPE_GROUP) && !hasObject(group, "position", H5O_TYPE_DATASET))
    {
      info.warnings.push_back("/particles/" + name + " has no position element and is left out");
      continue;
    }
    const Element position = readElement(group, "position");
    if (!position.problem.empty())
    {
      info.error = "/particles/" + name + "/" + position.dataset + ": " + position.problem;
      return;
    }
    times.insert(times.end(), position.times.begin(), position.times.end());
    if (position.times.empty())
    {
      times.push_back(0.0);
    }
  }
  if (times.empty())
  {
    info.error = "the H5MD file has no /particles/<group>/position element";
    return;
  }
  for (double t : times)
  {
    if (!std::isfinite(t))
    {
      info.error = "the H5MD file has a NaN or infinite time";
      return;
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  info.times = times;
}

ParticleFrame describeH5mdFrame(hid_t file, const ParticleFileInfo& info, std::size_t timeIndex)
{
  ParticleFrame frame;
  const double t = info.times[timeIndex];
  frame.time = t;
  frame.fields.push_back({ "time", { t } });
  Handle particles(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose);
  bool boxRead = false;
  for (const std::string& name : particleGroups(file))
  {
    Handle group(H5Gopen2(particles, name.c_str(), H5P_DEFAULT), H5Gclose);
    if (!hasObject(group, "position", H5O_TYPE_GROUP) && !hasObject(group, "position", H5O_TYPE_DATASET))
    {
      continue;
    }
    const std::string where = "/particles/" + name + "/";
    const Element position = readElement(group, "position");
    if (!position.problem.empty() || position.shape.size() != 2 || position.shape[1] != 3)
    {
      frame.error =
        where + position.dataset + ": " +
        (position.problem.empty() ? "expected N x 3 positions (frames x N x 3 when time dependent)" : position.problem);
      return frame;
    }
    ParticleBlock block;
    block.name = name;
    BlockPart part{ info.files.front(), where, {} };
    StepLayout& layout = part.layout;
    layout.particles = position.shape[0];
    layout.coordinateDatasets = { position.dataset };
    layout.coordinates = { "",
                           { position.dataset },
                           static_cast<int>(position.shape[1]),
                           position.times.empty() ? -1 : nearestFrame(position.times, t),
                           1.0,
                           position.unit };
    for (const std::string& element : linkNames(group))
    {
      if (element == "position" || element == "box")
      {
        continue;
      }
      const Element e = readElement(group, element);
      if (!e.problem.empty())
      {
        frame.warnings.push_back(where + e.dataset + " is not read: " + e.problem);
        continue;
      }
      const std::int64_t f = e.times.empty() ? -1 : nearestFrame(e.times, t);
      if (e.shape.empty())
      {
        std::vector<double> values;
        if (readSmallDataset(group, e.dataset, values, std::max<std::size_t>(e.times.size(), 1)))
        {
          block.constants.push_back(
            { element, values[static_cast<std::size_t>(std::max<std::int64_t>(f, 0))], e.unit });
        }
        continue;
      }
      if (e.shape[0] != layout.particles || e.shape.size() > 2)
      {
        frame.warnings.push_back(where + e.dataset + " is not read: it has " + std::to_string(e.shape[0]) +
                                 " rows for " + std::to_string(layout.particles) + " particles");
        continue;
      }
      if (element == "id" && e.shape.size() == 1)
      {
        layout.idDataset = e.dataset;
        layout.idFrame = f;
        continue;
      }
      const auto contract = kContractNames.find(element);
      layout.arrays.push_back({ contract != kContractNames.end() ? contract->second : element,
                                { e.dataset },
                                e.shape.size() == 2 ? static_cast<int>(e.shape[1]) : 1,
                                f,
                                1.0,
                                e.unit });
    }
    if (!boxRead)
    {
      readBox(group, t, frame);
      boxRead = true;
    }
    block.parts.push_back(std::move(part));
    frame.blocks.push_back(std::move(block));
  }
  return frame;
}
} // namespace parafluid::h5::detail
