#include "ParticleBlockRead.h"

#include "ParticleArrays.h"
#include "ParticleContract.h"
#include "parafluid/common/MemoryBudget.h"
#include "parafluid/h5part/Datasets.h"
#include "parafluid/h5part/Handle.h"

#include "vtkAlgorithm.h"
#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTypeInt64Array.h"
#include "vtkTypeUInt64Array.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace parafluid::vtk
{
namespace
{
using parafluid::h5::ArraySource;
using parafluid::h5::BlockPart;
using parafluid::h5::Handle;
using parafluid::h5::ValueType;

vtkSmartPointer<vtkDataArray> arrayOf(ValueType type)
{
  switch (type)
  {
    case ValueType::Float32:
      return vtkSmartPointer<vtkFloatArray>::New();
    case ValueType::Float64:
      return vtkSmartPointer<vtkDoubleArray>::New();
    case ValueType::Int32:
      return vtkSmartPointer<vtkIntArray>::New();
    case ValueType::Int64:
      return vtkSmartPointer<vtkTypeInt64Array>::New();
    default:
      return vtkSmartPointer<vtkTypeUInt64Array>::New();
  }
}

bool allocate(vtkDataArray* array, int components, vtkIdType n)
{
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  return array->GetNumberOfTuples() == n;
}

/// The first tuple holding a NaN or infinite value, -1 when none (a typed scan: GetComponent's
/// virtual call per value cost as much as the read itself).
vtkIdType firstNonFinite(vtkDataArray* values)
{
  const vtkIdType total = values->GetNumberOfValues();
  const int components = std::max(values->GetNumberOfComponents(), 1);
  auto scan = [&](const auto* v) -> vtkIdType
  {
    // Blocks of 4096 checked branch-free (x - x is 0 exactly when x is finite: vectorised), and
    // the block that has one searched.
    constexpr vtkIdType kBlock = 4096;
    for (vtkIdType first = 0; first < total; first += kBlock)
    {
      const vtkIdType last = std::min(total, first + kBlock);
      bool finite = true;
      for (vtkIdType k = first; k < last; ++k)
      {
        finite &= (v[k] - v[k]) == 0;
      }
      if (!finite)
      {
        for (vtkIdType k = first; k < last; ++k)
        {
          if (!std::isfinite(v[k]))
          {
            return k / components;
          }
        }
      }
    }
    return -1;
  };
  if (auto* floats = vtkFloatArray::SafeDownCast(values))
  {
    return scan(floats->GetPointer(0));
  }
  if (auto* doubles = vtkDoubleArray::SafeDownCast(values))
  {
    return scan(doubles->GetPointer(0));
  }
  return -1;
}

/// Rows [first, first + count) of part `part`, at `at` of this piece's output (before the subset).
struct Rows
{
  std::size_t part = 0;
  std::uint64_t first = 0, count = 0, at = 0;
};

/// The rows this piece reads: of each part, its rows near the selection box (its spatial index's
/// cells) or all of them, and of those together this piece's contiguous share.
std::vector<Rows> rowsOfPiece(const parafluid::h5::ParticleBlock& block, const BlockReading& how,
                              std::vector<std::string>& warnings)
{
  std::vector<Rows> candidates;
  std::uint64_t total = 0;
  for (std::size_t p = 0; p < block.parts.size(); ++p)
  {
    std::string warning;
    const std::vector<parafluid::h5::RowRange> ranges =
      how.useBox ? parafluid::h5::rowsNearBox(block.parts[p], how.box, warning)
                 : std::vector<parafluid::h5::RowRange>{ { 0, block.parts[p].layout.particles } };
    if (!warning.empty())
    {
      warnings.push_back(warning);
    }
    for (const auto& range : ranges)
    {
      candidates.push_back({ p, range.first, range.count, total });
      total += range.count;
    }
  }
  const auto p = static_cast<std::uint64_t>(std::max(how.piece, 0)),
             n = static_cast<std::uint64_t>(std::max(how.pieces, 1));
  const std::uint64_t begin = total / n * p + std::min(p, total % n);
  const std::uint64_t end = begin + total / n + (p < total % n ? 1 : 0);
  std::vector<Rows> rows;
  for (const Rows& r : candidates)
  {
    const std::uint64_t low = std::max(begin, r.at), high = std::min(end, r.at + r.count);
    if (high > low)
    {
      rows.push_back({ r.part, r.first + (low - r.at), high - low, low - begin });
    }
  }
  return rows;
}

/// The type an array is read as: the stored one, or doubles when a unit factor applies (a solar
/// mass in kilograms, 2e30, is beyond a float's range at 1e10 of them).
ValueType readType(hid_t group, const ArraySource& source)
{
  return source.scale != 1.0 ? ValueType::Float64 : parafluid::h5::commonValueType(group, source.datasets);
}

void applyScale(vtkDataArray* array, double scale)
{
  if (scale == 1.0)
  {
    return;
  }
  const vtkIdType values = array->GetNumberOfValues();
  if (auto* f = vtkFloatArray::SafeDownCast(array))
  {
    std::for_each(f->GetPointer(0), f->GetPointer(0) + values,
                  [scale](float& v) { v = static_cast<float>(v * scale); });
  }
  else if (auto* d = vtkDoubleArray::SafeDownCast(array))
  {
    std::for_each(d->GetPointer(0), d->GetPointer(0) + values, [scale](double& v) { v *= scale; });
  }
}

/// The name readSource knows the coordinates' offsets by ("" is the coordinates).
constexpr const char* kOffset = "#offset";

/// Reads `source` (found in every part) into `array` sized for this piece's rows.
bool readSource(const std::vector<BlockPart>& parts, const std::vector<Rows>& rows, const ArraySource& first,
                const std::string& name, ValueType type, vtkDataArray* array, std::string& error)
{
  const bool scattered = rows.size() > parts.size(); // a spatial index's cells: many small blocks
  std::size_t openPart = parts.size();
  Handle file(-1, H5Fclose), group(-1, H5Gclose);
  const ArraySource* source = nullptr;
  for (const Rows& r : rows)
  {
    const BlockPart& part = parts[r.part];
    if (r.part != openPart)
    {
      source = &first;
      if (r.part > 0)
      {
        const auto& arrays = part.layout.arrays;
        const auto found =
          std::find_if(arrays.begin(), arrays.end(), [&](const ArraySource& a) { return a.name == name; });
        source = name.empty()      ? &part.layout.coordinates
                 : name == kOffset ? &part.layout.coordinateOffset
                                   : (found == arrays.end() ? nullptr : &*found);
        if (!source)
        {
          error = "'" + part.file + "': " + part.group + " has no " + name + " as the snapshot's first file has";
          return false;
        }
      }
      std::string fileError;
      group.reset();
      file = Handle(parafluid::h5::openForReading(part.file, fileError, scattered), H5Fclose);
      group = Handle(file.valid() ? H5Gopen2(file, part.group.c_str(), H5P_DEFAULT) : -1, H5Gclose);
      if (!group.valid())
      {
        error = fileError.empty() ? "'" + part.file + "': cannot open " + part.group : fileError;
        return false;
      }
      openPart = r.part;
    }
    const std::size_t bytes = parafluid::h5::valueBytes(type) * static_cast<std::size_t>(source->components);
    void* target = static_cast<char*>(array->GetVoidPointer(0)) + r.at * bytes;
    for (std::size_t c = 0; c < source->datasets.size(); ++c)
    {
      if (source->datasets[c].empty())
      {
        continue; // a component the layout gives as a constant (the array was zero-filled)
      }
      if (!parafluid::h5::readSlice(group, source->datasets[c], type, part.layout.firstRow + r.first, r.count, target,
                                    static_cast<std::uint64_t>(source->components), source->datasets.size() > 1 ? c : 0,
                                    error, source->frame))
      {
        error = "'" + part.file + "': " + part.group + ": " + error;
        return false;
      }
    }
  }
  return true;
}

/// Which of this piece's rows are returned: all, or those the selection box, the stride and the
/// layout's real-particle tag keep.
struct Subset
{
  std::vector<unsigned char> keep; // per row; empty when every row is kept
  vtkIdType kept = 0;
};

/// SplitMix64's finaliser (Steele, Lea & Flood 2014): ids of any pattern (consecutive, even
/// only, blocks per process) spread evenly over the residues the stride keeps.
std::uint64_t mixed(std::uint64_t id)
{
  id += 0x9e3779b97f4a7c15ull;
  id = (id ^ (id >> 30)) * 0xbf58476d1ce4e5b9ull;
  id = (id ^ (id >> 27)) * 0x94d049bb133111ebull;
  return id ^ (id >> 31);
}

/// Moves the kept tuples of `array` to its front, in order, and shortens it to them.
void compact(vtkDataArray* array, const Subset& subset)
{
  if (subset.keep.empty())
  {
    return;
  }
  const std::size_t bytes = static_cast<std::size_t>(array->GetDataTypeSize()) * array->GetNumberOfComponents();
  auto* data = static_cast<unsigned char*>(array->GetVoidPointer(0));
  std::size_t to = 0;
  for (std::size_t i = 0; i < subset.keep.size(); ++i)
  {
    if (subset.keep[i])
    {
      if (to != i)
      {
        std::memmove(data + to * bytes, data + i * bytes, bytes);
      }
      ++to;
    }
  }
  array->SetNumberOfTuples(subset.kept);
}

/// The rows of this piece that are returned (`points` read, scaled and shifted; `ids` read).
bool selectSubset(const parafluid::h5::ParticleBlock& block, const std::vector<Rows>& rows, const BlockReading& how,
                  vtkDataArray* points, vtkTypeInt64Array* ids, Subset& subset, std::string& error)
{
  const vtkIdType n = points->GetNumberOfTuples();
  subset.kept = n;
  const std::string& tag = block.parts.front().layout.realTagDataset;
  if (!how.useBox && how.stride <= 1 && tag.empty())
  {
    return true;
  }
  subset.keep.assign(static_cast<std::size_t>(n), 1);
  if (!tag.empty())
  {
    vtkNew<vtkTypeInt64Array> tags;
    if (!allocate(tags, 1, n) ||
        !readSource(block.parts, rows, ArraySource{ tag, { tag }, 1 }, tag, ValueType::Int64, tags, error))
    {
      error = error.empty() ? "not enough memory for the tags of " + block.parts.front().group : error;
      return false;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      subset.keep[i] &= tags->GetValue(i) == 0 ? 1 : 0;
    }
  }
  if (how.stride > 1)
  {
    const auto stride = static_cast<std::uint64_t>(how.stride);
    for (vtkIdType i = 0; i < n; ++i)
    {
      subset.keep[i] &= mixed(static_cast<std::uint64_t>(ids->GetValue(i))) % stride == 0 ? 1 : 0;
    }
  }
  if (how.useBox)
  {
    auto inside = [&](const auto* x)
    {
      for (vtkIdType i = 0; i < n; ++i)
      {
        bool in = true;
        for (int a = 0; a < 3; ++a)
        {
          in &= x[3 * i + a] >= how.box[2 * a] && x[3 * i + a] <= how.box[2 * a + 1];
        }
        subset.keep[i] &= in ? 1 : 0;
      }
    };
    if (auto* f = vtkFloatArray::SafeDownCast(points))
    {
      inside(f->GetPointer(0));
    }
    else
    {
      inside(vtkDoubleArray::SafeDownCast(points)->GetPointer(0));
    }
  }
  subset.kept = static_cast<vtkIdType>(std::count(subset.keep.begin(), subset.keep.end(), 1));
  return true;
}

/// Adds the layout's offsets to the scaled coordinates: a read offset array and a constant per axis.
bool shiftCoordinates(const parafluid::h5::ParticleBlock& block, const std::vector<Rows>& rows, vtkDataArray* points,
                      std::string& error)
{
  const parafluid::h5::StepLayout& layout = block.parts.front().layout;
  const double* shift = layout.coordinateShift;
  const bool offsets = !layout.coordinateOffset.datasets.empty();
  if (!offsets && shift[0] == 0.0 && shift[1] == 0.0 && shift[2] == 0.0)
  {
    return true;
  }
  vtkNew<vtkDoubleArray> offset;
  if (!allocate(offset, 3, points->GetNumberOfTuples()))
  {
    error = "not enough memory for the coordinates' offsets of " + block.parts.front().group;
    return false;
  }
  offset->Fill(0.0);
  if (offsets && !readSource(block.parts, rows, layout.coordinateOffset, kOffset, ValueType::Float64, offset, error))
  {
    return false;
  }
  const double scale = offsets ? layout.coordinateOffset.scale : 1.0;
  for (vtkIdType i = 0; i < points->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      points->SetComponent(i, c, points->GetComponent(i, c) + scale * offset->GetComponent(i, c) + shift[c]);
    }
  }
  return true;
}
} // namespace

BlockReading blockReadingFor(vtkInformation* outInfo, vtkDataArraySelection* selection, vtkAlgorithm* algorithm)
{
  BlockReading how;
  how.selection = selection;
  how.algorithm = algorithm;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    how.piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  }
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
  {
    how.pieces = std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  }
  return how;
}

std::vector<std::string> blockArrayNames(const parafluid::h5::ParticleBlock& block)
{
  std::vector<std::string> names;
  if (!block.parts.empty())
  {
    for (const ArraySource& source : block.parts.front().layout.arrays)
    {
      names.push_back(source.name);
    }
  }
  for (const auto& constant : block.constants)
  {
    names.push_back(constant.name);
  }
  return names;
}

bool readParticleBlock(const parafluid::h5::ParticleBlock& block, const BlockReading& how, vtkPolyData* output,
                       std::vector<std::string>& warnings, std::string& error)
{
  if (block.parts.empty())
  {
    error = "block " + block.name + " has no rows";
    return false;
  }
  const std::vector<Rows> rows = rowsOfPiece(block, how, warnings);
  std::uint64_t count = 0;
  for (const Rows& r : rows)
  {
    count += r.count;
  }
  const auto n = static_cast<vtkIdType>(count);
  const BlockPart& head = block.parts.front();
  const auto enabled = [&](const std::string& name)
  { return !how.selection || how.selection->ArrayIsEnabled(name.c_str()); };

  std::string openError;
  // HDF5 shares one open file among its opens, with the first open's settings.
  const bool scattered = rows.size() > block.parts.size();
  Handle file(parafluid::h5::openForReading(head.file, openError, scattered), H5Fclose);
  Handle group(file.valid() ? H5Gopen2(file, head.group.c_str(), H5P_DEFAULT) : -1, H5Gclose);
  if (!group.valid())
  {
    error = openError.empty() ? "'" + head.file + "': cannot open " + head.group : openError;
    return false;
  }
  const ArraySource coordinates = head.layout.coordinates.datasets.empty()
                                    ? ArraySource{ "", head.layout.coordinateDatasets, 3 }
                                    : head.layout.coordinates;
  const ValueType coordinateType =
    readType(group, coordinates) == ValueType::Float32 ? ValueType::Float32 : ValueType::Float64;
  double bytes = static_cast<double>(count) * (3.0 * parafluid::h5::valueBytes(coordinateType) + 8.0 + 16.0);
  std::vector<ValueType> types;
  for (const ArraySource& source : head.layout.arrays)
  {
    types.push_back(readType(group, source));
    if (enabled(source.name))
    {
      bytes += static_cast<double>(count) * source.components * parafluid::h5::valueBytes(types.back());
    }
  }
  const std::string tooLarge = parafluid::checkMemoryBudget(
    bytes, head.group + " (" + std::to_string(block.particles()) + " particles, as the file declares)");
  if (!tooLarge.empty())
  {
    error = "'" + head.file + "': " + tooLarge + "; deselect point arrays or read it under MPI in pieces";
    return false;
  }

  vtkSmartPointer<vtkDataArray> points = arrayOf(coordinateType);
  if (!allocate(points, 3, n))
  {
    error = "not enough memory for the coordinates of " + head.group;
    return false;
  }
  if (std::any_of(coordinates.datasets.begin(), coordinates.datasets.end(),
                  [](const std::string& d) { return d.empty(); }))
  {
    points->Fill(0.0); // components the layout leaves to constants stay 0 before the shift
  }
  if (!readSource(block.parts, rows, coordinates, "", coordinateType, points, error))
  {
    return false;
  }
  applyScale(points, coordinates.scale);
  if (!shiftCoordinates(block, rows, points, error))
  {
    return false;
  }
  if (!coordinates.unit.empty())
  {
    points->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), coordinates.unit.c_str());
  }
  const vtkIdType bad = firstNonFinite(points);
  if (bad >= 0)
  {
    warnings.push_back(head.group + ": particle " + std::to_string(bad) +
                       " of this piece has a NaN or infinite coordinate (read as it is; filters that need finite "
                       "values refuse or drop such particles)");
  }
  vtkNew<vtkPoints> pointSet;
  pointSet->SetData(points);
  output->SetPoints(pointSet);

  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName(parafluid::contract::Id);
  if (!allocate(ids, 1, n))
  {
    error = "not enough memory for the ids of " + head.group;
    return false;
  }
  std::vector<std::uint64_t> partStart(block.parts.size() + 1, 0); // the part's first row in the block
  for (std::size_t p = 0; p < block.parts.size(); ++p)
  {
    partStart[p + 1] = partStart[p] + block.parts[p].layout.particles;
  }
  for (const Rows& r : rows)
  {
    const BlockPart& part = block.parts[r.part];
    auto* target = reinterpret_cast<std::int64_t*>(ids->GetPointer(0)) + r.at;
    std::string problem;
    bool read = false;
    if (!part.layout.idDataset.empty())
    {
      Handle partFile(parafluid::h5::openForReading(part.file, problem, scattered), H5Fclose);
      Handle partGroup(partFile.valid() ? H5Gopen2(partFile, part.group.c_str(), H5P_DEFAULT) : -1, H5Gclose);
      read =
        partGroup.valid() && parafluid::h5::readIds(partGroup, part.layout.idDataset, part.layout.firstRow + r.first,
                                                    r.count, target, problem, part.layout.idFrame);
    }
    if (!read)
    {
      if (!problem.empty())
      {
        warnings.push_back(part.group + ": " + problem + "; each particle's id is its index in the file instead");
      }
      std::iota(target, target + r.count, static_cast<std::int64_t>(partStart[r.part] + r.first));
    }
  }
  Subset subset;
  if (!selectSubset(block, rows, how, points, ids, subset, error))
  {
    return false;
  }
  compact(points, subset);
  compact(ids, subset);
  output->GetPoints()->Modified();
  parafluid::vtk::setOneVertexPerPoint(output, subset.kept);
  output->GetPointData()->AddArray(ids);

  for (std::size_t k = 0; k < head.layout.arrays.size(); ++k)
  {
    const ArraySource& source = head.layout.arrays[k];
    if (how.algorithm && how.algorithm->CheckAbort())
    {
      error = "reading was aborted";
      return false;
    }
    if (!enabled(source.name))
    {
      continue;
    }
    auto array = arrayOf(types[k]);
    array->SetName(source.name.c_str());
    if (!allocate(array, source.components, n) ||
        !readSource(block.parts, rows, source, source.name, types[k], array, error))
    {
      error = error.empty() ? "not enough memory for array " + source.name + " of " + head.group : error;
      return false;
    }
    compact(array, subset);
    applyScale(array, source.scale);
    if (!source.unit.empty())
    {
      array->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), source.unit.c_str());
    }
    output->GetPointData()->AddArray(array);
  }
  for (const auto& constant : block.constants)
  {
    if (!enabled(constant.name))
    {
      continue;
    }
    vtkNew<vtkDoubleArray> array;
    array->SetName(constant.name.c_str());
    if (!allocate(array, 1, subset.kept))
    {
      error = "not enough memory for array " + constant.name + " of " + head.group;
      return false;
    }
    array->FillValue(constant.value);
    if (!constant.unit.empty())
    {
      array->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), constant.unit.c_str());
    }
    output->GetPointData()->AddArray(array);
  }
  if (auto* velocity = output->GetPointData()->GetArray(parafluid::contract::Velocity))
  {
    output->GetPointData()->SetVectors(velocity);
  }
  return true;
}
} // namespace parafluid::vtk
