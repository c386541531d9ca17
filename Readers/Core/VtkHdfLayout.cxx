// VTKHDF PolyData as VTK 9.3 writes it (the "VTKHDF File Format" of VTK's documentation): a
// /VTKHDF group with Version and Type "PolyData", Points (N x 3, every partition's after the
// other; NumberOfPoints per partition) and PointData/<array>; the vertices, lines and polygons
// are not needed for particles. With a /VTKHDF/Steps group (VTKHDF 2), each step's points start
// at PointOffsets[step] and its point data at PointDataOffsets/<array>[step], of NumberOfParts
// partitions from PartOffsets[step]; Values are the times. One block.
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <cmath>
#include <numeric>

namespace parafluid::h5::detail
{
namespace
{
/// The values of a 1-D integer dataset of at most `limit` values (offsets and counts).
bool readCounts(hid_t group, const std::string& name, std::vector<double>& values, std::size_t limit)
{
  if (!readSmallDataset(group, name, values, limit))
  {
    return false;
  }
  for (double v : values)
  {
    if (!(v >= 0.0 && v < 9.2e18 && v == std::floor(v)))
    {
      return false;
    }
  }
  return true;
}

constexpr std::size_t kMaxParts = std::size_t(1) << 24;
} // namespace

void describeVtkHdfFile(hid_t file, ParticleFileInfo& info)
{
  Handle root(H5Gopen2(file, "VTKHDF", H5P_DEFAULT), H5Gclose);
  const std::vector<std::string> type = stringAttribute(root, "Type");
  if (type.empty() || type.front() != "PolyData")
  {
    info.error = "the VTKHDF file holds " + (type.empty() ? std::string("no Type") : type.front()) +
                 ", not PolyData: only point clouds are read as particles";
    return;
  }
  std::vector<double> version;
  info.description = "VTKHDF PolyData";
  if (readNumericAttribute(root, "Version", version, 2) && version.size() == 2)
  {
    info.description +=
      " " + std::to_string(static_cast<int>(version[0])) + "." + std::to_string(static_cast<int>(version[1]));
  }
  if (!hasObject(root, "Steps", H5O_TYPE_GROUP))
  {
    info.times = { 0.0 };
    return;
  }
  Handle steps(H5Gopen2(root, "Steps", H5P_DEFAULT), H5Gclose);
  std::vector<double> values;
  if (!readSmallDataset(steps, "Values", values, kMaxParts))
  {
    info.error = "/VTKHDF/Steps has no Values (the times of its steps)";
    return;
  }
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    if (!std::isfinite(values[k]) || (k > 0 && !(values[k] > values[k - 1])))
    {
      info.warnings.push_back(
        "/VTKHDF/Steps/Values are not finite and increasing; the steps are offered at 0, 1, 2, ...");
      std::iota(values.begin(), values.end(), 0.0);
      break;
    }
  }
  info.times = values;
}

ParticleFrame describeVtkHdfFrame(hid_t file, const ParticleFileInfo& info, std::size_t timeIndex)
{
  ParticleFrame frame;
  frame.time = info.times[timeIndex];
  frame.fields.push_back({ "time", { frame.time } });
  Handle root(H5Gopen2(file, "VTKHDF", H5P_DEFAULT), H5Gclose);
  std::vector<double> counts;
  if (!readCounts(root, "NumberOfPoints", counts, kMaxParts))
  {
    frame.error = "/VTKHDF/NumberOfPoints is missing or not whole, non-negative counts";
    return frame;
  }
  // The step's partitions and where its points and each array's values start.
  std::size_t firstPart = 0, parts = counts.size();
  std::uint64_t firstPoint = 0;
  const bool temporal = hasObject(root, "Steps", H5O_TYPE_GROUP);
  Handle steps(temporal ? H5Gopen2(root, "Steps", H5P_DEFAULT) : -1, H5Gclose);
  if (temporal)
  {
    std::vector<double> partOffsets, partCounts, pointOffsets;
    if (!readCounts(steps, "PartOffsets", partOffsets, kMaxParts) ||
        !readCounts(steps, "NumberOfParts", partCounts, kMaxParts) ||
        !readCounts(steps, "PointOffsets", pointOffsets, kMaxParts) || partOffsets.size() <= timeIndex ||
        partCounts.size() <= timeIndex || pointOffsets.size() <= timeIndex)
    {
      frame.error =
        "/VTKHDF/Steps lacks PartOffsets, NumberOfParts or PointOffsets for step " + std::to_string(timeIndex);
      return frame;
    }
    firstPart = static_cast<std::size_t>(partOffsets[timeIndex]);
    parts = static_cast<std::size_t>(partCounts[timeIndex]);
    firstPoint = static_cast<std::uint64_t>(pointOffsets[timeIndex]);
    if (firstPart + parts > counts.size())
    {
      frame.error = "/VTKHDF/Steps: step " + std::to_string(timeIndex) + " has partitions beyond NumberOfPoints";
      return frame;
    }
  }
  std::uint64_t particles = 0;
  for (std::size_t p = firstPart; p < firstPart + parts; ++p)
  {
    particles += static_cast<std::uint64_t>(counts[p]);
  }
  std::string problem;
  const std::vector<std::uint64_t> shape = datasetShape(root, "Points", problem);
  if (!problem.empty() || shape.size() != 2 || shape[1] != 3 || firstPoint + particles > shape[0])
  {
    frame.error =
      "/VTKHDF/Points: " + (problem.empty()
                              ? "expected at least " + std::to_string(firstPoint + particles) + " rows of 3 coordinates"
                              : problem);
    return frame;
  }
  ParticleBlock block;
  block.name = "particles";
  BlockPart part{ info.files.front(), "/VTKHDF", {} };
  StepLayout& layout = part.layout;
  layout.particles = particles;
  layout.firstRow = firstPoint;
  layout.coordinateDatasets = { "Points" };
  layout.coordinates = { "", { "Points" }, 3 };
  if (hasObject(root, "PointData", H5O_TYPE_GROUP))
  {
    Handle pointData(H5Gopen2(root, "PointData", H5P_DEFAULT), H5Gclose);
    for (const std::string& name : linkNames(pointData))
    {
      const std::vector<std::uint64_t> values = datasetShape(pointData, name, problem);
      std::uint64_t first = firstPoint;
      if (temporal)
      {
        std::vector<double> offsets;
        if (!readCounts(steps, "PointDataOffsets/" + name, offsets, kMaxParts) || offsets.size() <= timeIndex)
        {
          frame.warnings.push_back("/VTKHDF/PointData/" + name +
                                   " has no PointDataOffsets for its steps and is not read");
          continue;
        }
        first = static_cast<std::uint64_t>(offsets[timeIndex]);
      }
      if (!problem.empty() || values.empty() || values.size() > 2 || first + particles > values[0])
      {
        frame.warnings.push_back("/VTKHDF/PointData/" + name +
                                 " is not read: " + (problem.empty() ? "it does not hold a value per point" : problem));
        problem.clear();
        continue;
      }
      if (first != firstPoint)
      {
        frame.warnings.push_back("/VTKHDF/PointData/" + name + " starts elsewhere than the points in step " +
                                 std::to_string(timeIndex) + " and is not read");
        continue;
      }
      const int components = values.size() == 2 ? static_cast<int>(values[1]) : 1;
      if (name == "id" && components == 1)
      {
        layout.idDataset = "PointData/" + name;
        continue;
      }
      layout.arrays.push_back({ name, { "PointData/" + name }, components });
    }
  }
  block.parts.push_back(std::move(part));
  frame.blocks.push_back(std::move(block));
  return frame;
}
} // namespace parafluid::h5::detail
