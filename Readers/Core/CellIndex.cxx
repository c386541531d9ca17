// SWIFT's spatial index of a snapshot (the top-level cells, /Cells): per particle type and cell,
// the file holding its particles (Files), their first row there (OffsetsInFile; Offsets in older
// snapshots, rows of the whole snapshot) and count (Counts), and the cell's centre (Centres) and
// width (Meta-data's size), or its particles' bounds (MinPositions, MaxPositions), in the
// snapshot's length unit. Particles drift out of their cell by at most one cell-length between
// the code's tree rebuilds (SWIFT's snapshot documentation), hence the widening without bounds.
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <algorithm>
#include <cmath>

namespace parafluid::h5::detail
{
namespace
{
// More cells than this is not a top-level grid (SWIFT's are at most a few million).
constexpr std::size_t kMaxCells = std::size_t(1) << 24;
} // namespace
} // namespace parafluid::h5::detail

namespace parafluid::h5
{
std::vector<RowRange> rowsNearBox(const BlockPart& part, const double box[6], std::string& warning)
{
  using namespace detail;
  const std::vector<RowRange> every{ { 0, part.layout.particles } };
  if (part.cellIndexType.empty())
  {
    return every;
  }
  std::string error;
  Handle file(openForReading(part.file, error), H5Fclose);
  Handle cells(file.valid() ? H5Gopen2(file, "Cells", H5P_DEFAULT) : -1, H5Gclose);
  const std::string& type = part.cellIndexType;
  std::vector<double> counts, offsets, files, lower, upper;
  const bool inFile = hasObject(cells, "OffsetsInFile/" + type, H5O_TYPE_DATASET);
  if (!cells.valid() || !readSmallDataset(cells, "Counts/" + type, counts, kMaxCells) ||
      !readSmallDataset(cells, (inFile ? "OffsetsInFile/" : "Offsets/") + type, offsets, kMaxCells) ||
      offsets.size() != counts.size())
  {
    warning = "'" + part.file + "': /Cells has no usable Counts and offsets of " + type + "; every particle is read";
    return every;
  }
  const std::size_t n = counts.size();
  if (!readSmallDataset(cells, "Files/" + type, files, kMaxCells) || files.size() != n)
  {
    files.assign(n, 0.0);
  }
  const double scale = part.layout.coordinates.scale;
  const bool bounds = readSmallDataset(cells, "MinPositions/" + type, lower, 3 * kMaxCells) &&
                      readSmallDataset(cells, "MaxPositions/" + type, upper, 3 * kMaxCells) && lower.size() == 3 * n &&
                      upper.size() == 3 * n;
  if (!bounds)
  {
    std::vector<double> centres, size;
    Handle meta(H5Gopen2(cells, "Meta-data", H5P_DEFAULT), H5Gclose);
    if (!readSmallDataset(cells, "Centres", centres, 3 * kMaxCells) || centres.size() != 3 * n || !meta.valid() ||
        !readNumericAttribute(meta, "size", size, 3) || size.size() != 3)
    {
      warning = "'" + part.file +
                "': /Cells has neither its particles' bounds nor the cells' centres and size; "
                "every particle is read";
      return every;
    }
    lower.resize(3 * n);
    upper.resize(3 * n);
    for (std::size_t c = 0; c < n; ++c)
    {
      for (int a = 0; a < 3; ++a)
      {
        lower[3 * c + a] = centres[3 * c + a] - 1.5 * size[a];
        upper[3 * c + a] = centres[3 * c + a] + 1.5 * size[a];
      }
    }
  }
  std::vector<RowRange> rows;
  for (std::size_t c = 0; c < n; ++c)
  {
    if (files[c] != part.fileIndex || !(counts[c] > 0.0))
    {
      continue;
    }
    bool overlaps = true;
    for (int a = 0; a < 3; ++a)
    {
      overlaps &= scale * upper[3 * c + a] >= box[2 * a] && scale * lower[3 * c + a] <= box[2 * a + 1];
    }
    if (!overlaps)
    {
      continue;
    }
    if (!(offsets[c] >= 0.0) || offsets[c] + counts[c] > static_cast<double>(part.layout.particles))
    {
      warning = "'" + part.file + "': /Cells lists rows beyond the " + std::to_string(part.layout.particles) +
                " particles of " + type + "; every particle is read";
      return every;
    }
    rows.push_back({ static_cast<std::uint64_t>(offsets[c]), static_cast<std::uint64_t>(counts[c]) });
  }
  std::sort(rows.begin(), rows.end(), [](const RowRange& a, const RowRange& b) { return a.first < b.first; });
  std::vector<RowRange> merged;
  for (const RowRange& r : rows)
  {
    if (!merged.empty() && r.first <= merged.back().first + merged.back().count)
    {
      const std::uint64_t end = std::max(merged.back().first + merged.back().count, r.first + r.count);
      merged.back().count = end - merged.back().first;
    }
    else
    {
      merged.push_back(r);
    }
  }
  return merged;
}
} // namespace parafluid::h5
