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

/// One part's rows within this piece: [first, first + count) of the part, at `at` of the output.
struct Rows
{
  std::uint64_t first = 0, count = 0, at = 0;
};

std::vector<Rows> piecesOfParts(const parafluid::h5::ParticleBlock& block, int piece, int pieces)
{
  const std::uint64_t total = block.particles();
  const auto p = static_cast<std::uint64_t>(std::max(piece, 0)), n = static_cast<std::uint64_t>(std::max(pieces, 1));
  const std::uint64_t begin = total / n * p + std::min(p, total % n);
  const std::uint64_t end = begin + total / n + (p < total % n ? 1 : 0);
  std::vector<Rows> rows;
  std::uint64_t start = 0;
  for (const BlockPart& part : block.parts)
  {
    const std::uint64_t stop = start + part.layout.particles;
    const std::uint64_t low = std::max(begin, start), high = std::min(end, stop);
    rows.push_back({ low - std::min(low, start), high > low ? high - low : 0, low > begin ? low - begin : 0 });
    start = stop;
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

/// Reads `source` (found in every part) into `array` sized for this piece.
bool readSource(const std::vector<BlockPart>& parts, const std::vector<Rows>& rows, const ArraySource& first,
                const std::string& name, ValueType type, vtkDataArray* array, std::string& error)
{
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    if (rows[p].count == 0)
    {
      continue;
    }
    const BlockPart& part = parts[p];
    const ArraySource* source = &first;
    if (p > 0)
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
    Handle file(parafluid::h5::openForReading(part.file, fileError), H5Fclose);
    Handle group(file.valid() ? H5Gopen2(file, part.group.c_str(), H5P_DEFAULT) : -1, H5Gclose);
    if (!group.valid())
    {
      error = fileError.empty() ? "'" + part.file + "': cannot open " + part.group : fileError;
      return false;
    }
    const std::size_t bytes = parafluid::h5::valueBytes(type) * static_cast<std::size_t>(source->components);
    void* target = static_cast<char*>(array->GetVoidPointer(0)) + rows[p].at * bytes;
    for (std::size_t c = 0; c < source->datasets.size(); ++c)
    {
      if (source->datasets[c].empty())
      {
        continue; // a component the layout gives as a constant (the array was zero-filled)
      }
      if (!parafluid::h5::readSlice(group, source->datasets[c], type, part.layout.firstRow + rows[p].first,
                                    rows[p].count, target, static_cast<std::uint64_t>(source->components),
                                    source->datasets.size() > 1 ? c : 0, error, source->frame))
      {
        error = "'" + part.file + "': " + part.group + ": " + error;
        return false;
      }
    }
  }
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
  const std::vector<Rows> rows = piecesOfParts(block, how.piece, how.pieces);
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
  Handle file(parafluid::h5::openForReading(head.file, openError), H5Fclose);
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
  parafluid::vtk::setOneVertexPerPoint(output, n);

  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName(parafluid::contract::Id);
  if (!allocate(ids, 1, n))
  {
    error = "not enough memory for the ids of " + head.group;
    return false;
  }
  std::uint64_t start = 0;
  for (std::size_t p = 0; p < block.parts.size(); ++p)
  {
    const BlockPart& part = block.parts[p];
    auto* target = reinterpret_cast<std::int64_t*>(ids->GetPointer(0)) + rows[p].at;
    std::string problem;
    bool read = false;
    if (!part.layout.idDataset.empty() && rows[p].count > 0)
    {
      Handle partFile(parafluid::h5::openForReading(part.file, problem), H5Fclose);
      Handle partGroup(partFile.valid() ? H5Gopen2(partFile, part.group.c_str(), H5P_DEFAULT) : -1, H5Gclose);
      read = partGroup.valid() &&
             parafluid::h5::readIds(partGroup, part.layout.idDataset, part.layout.firstRow + rows[p].first,
                                    rows[p].count, target, problem, part.layout.idFrame);
    }
    if (!read)
    {
      if (!problem.empty())
      {
        warnings.push_back(part.group + ": " + problem + "; each particle's id is its index in the file instead");
      }
      std::iota(target, target + rows[p].count, static_cast<std::int64_t>(start + rows[p].first));
    }
    start += part.layout.particles;
  }
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
    if (!allocate(array, 1, n))
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
