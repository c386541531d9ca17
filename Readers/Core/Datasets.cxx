#include "parafluid/h5part/Datasets.h"

#include "parafluid/h5part/Handle.h"

#include <cmath>

namespace parafluid::h5
{
ValueType commonValueType(hid_t group, const std::vector<std::string>& datasets)
{
  bool anyFloat = false, wideFloat = false, wideInteger = false, needsInt64 = false, needsUInt64 = false,
       anySigned = false;
  for (const std::string& name : datasets)
  {
    Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
    Handle type(dataset.valid() ? H5Dget_type(dataset) : -1, H5Tclose);
    if (!type.valid())
    {
      continue;
    }
    const std::size_t size = H5Tget_size(type);
    if (H5Tget_class(type) == H5T_FLOAT)
    {
      anyFloat = true;
      wideFloat = wideFloat || size > 4;
      continue;
    }
    const bool isSigned = H5Tget_sign(type) == H5T_SGN_2;
    anySigned = anySigned || isSigned;
    // float32 holds integers of up to 24 bits exactly: 8- and 16-bit ones.
    wideInteger = wideInteger || size > 2;
    if (isSigned ? size > 4 : size >= 4)
    {
      needsInt64 = true;
    }
    if (!isSigned && size > 4)
    {
      needsUInt64 = true;
    }
  }
  if (anyFloat)
  {
    return wideFloat || wideInteger ? ValueType::Float64 : ValueType::Float32;
  }
  if (needsUInt64)
  {
    // uint64 beside signed integers has no exact common integer type; doubles are nearest.
    return anySigned ? ValueType::Float64 : ValueType::UInt64;
  }
  return needsInt64 ? ValueType::Int64 : ValueType::Int32;
}

hid_t memoryType(ValueType type)
{
  switch (type)
  {
    case ValueType::Float32:
      return H5T_NATIVE_FLOAT;
    case ValueType::Float64:
      return H5T_NATIVE_DOUBLE;
    case ValueType::Int32:
      return H5T_NATIVE_INT32;
    case ValueType::Int64:
      return H5T_NATIVE_INT64;
    default:
      return H5T_NATIVE_UINT64;
  }
}

std::size_t valueBytes(ValueType type)
{
  return type == ValueType::Float32 || type == ValueType::Int32 ? 4 : 8;
}

namespace
{
bool readRows(hid_t dataset, hid_t memory, std::uint64_t offset, std::uint64_t count, std::uint64_t width, void* target,
              std::int64_t frame)
{
  Handle fileSpace(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(fileSpace);
  // Rows of one frame: the frame axis first, then the rows (and columns) as in an N (x k) dataset.
  const int lead = frame >= 0 ? 1 : 0;
  const hsize_t fileStart[3] = { frame >= 0 ? static_cast<hsize_t>(frame) : offset, frame >= 0 ? offset : 0, 0 };
  const hsize_t fileCount[3] = { frame >= 0 ? 1 : count, frame >= 0 ? count : width, width };
  if (rank < 1 + lead || H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, fileStart, nullptr, fileCount, nullptr) < 0)
  {
    return false;
  }
  Handle memorySpace(H5Screate_simple(rank, fileCount, nullptr), H5Sclose);
  return H5Dread(dataset, memory, memorySpace, fileSpace, H5P_DEFAULT, target) >= 0;
}
} // namespace

bool readSlice(hid_t group, const std::string& name, ValueType type, std::uint64_t offset, std::uint64_t count,
               void* target, std::uint64_t stride, std::uint64_t column, std::string& error, std::int64_t frame)
{
  Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
  {
    error = "cannot open dataset " + name;
    return false;
  }
  Handle fileSpace(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(fileSpace);
  const int lead = frame >= 0 ? 1 : 0;
  hsize_t shape[3] = { 0, 1, 1 };
  if (rank < 1 + lead || rank > 2 + lead || H5Sget_simple_extent_dims(fileSpace, shape, nullptr) < 0 ||
      (frame >= 0 && static_cast<hsize_t>(frame) >= shape[0]))
  {
    error = "dataset " + name + " does not have the rows asked for";
    return false;
  }
  const hsize_t* dims = shape + lead;
  if (offset + count > dims[0])
  {
    error = "dataset " + name + " does not have the rows asked for";
    return false;
  }
  const std::uint64_t width = rank == 2 + lead ? dims[1] : 1;
  if (count == 0)
  {
    return true;
  }
  const hid_t memory = memoryType(type);
  if (width == stride && column == 0)
  {
    if (!readRows(dataset, memory, offset, count, width, target, frame))
    {
      error = "HDF5 failed to read dataset " + name;
      return false;
    }
    return true;
  }
  if (width != 1 || column >= stride)
  {
    error = "dataset " + name + " has " + std::to_string(width) + " columns where 1 is expected";
    return false;
  }
  // A component of a vector (x of the points, vx of velocity) is read contiguously and then
  // interleaved: HDF5's own strided scatter is several times slower on chunked, compressed data.
  const std::size_t bytes = valueBytes(type);
  std::vector<unsigned char> component(static_cast<std::size_t>(count) * bytes);
  if (!readRows(dataset, memory, offset, count, 1, component.data(), frame))
  {
    error = "HDF5 failed to read dataset " + name;
    return false;
  }
  // Typed copies: a memcpy of a run-time size per value is several times slower.
  auto interleave = [&](auto* out, const auto* in)
  {
    for (std::uint64_t i = 0; i < count; ++i)
    {
      out[i * stride + column] = in[i];
    }
  };
  if (bytes == 4)
  {
    interleave(static_cast<std::uint32_t*>(target), reinterpret_cast<const std::uint32_t*>(component.data()));
  }
  else
  {
    interleave(static_cast<std::uint64_t*>(target), reinterpret_cast<const std::uint64_t*>(component.data()));
  }
  return true;
}

bool readIds(hid_t group, const std::string& name, std::uint64_t offset, std::uint64_t count, std::int64_t* ids,
             std::string& error, std::int64_t frame)
{
  const ValueType stored = commonValueType(group, { name });
  if (stored == ValueType::UInt64)
  {
    // Read as stored and checked here: HDF5's own uint64 -> int64 conversion, value by value with
    // overflow handling, took longer than the read (Gadget's and SWIFT's ids are uint64).
    if (!readSlice(group, name, ValueType::UInt64, offset, count, ids, 1, 0, error, frame))
    {
      return false;
    }
    for (std::uint64_t i = 0; i < count; ++i)
    {
      if (ids[i] < 0)
      {
        error = "dataset " + name + " holds " + std::to_string(static_cast<std::uint64_t>(ids[i])) + " at particle " +
                std::to_string(offset + i) + ", beyond int64's range";
        return false;
      }
    }
    return true;
  }
  if (stored != ValueType::Float32 && stored != ValueType::Float64)
  {
    return readSlice(group, name, ValueType::Int64, offset, count, ids, 1, 0, error, frame);
  }
  std::vector<double> values(static_cast<std::size_t>(count));
  if (!readSlice(group, name, ValueType::Float64, offset, count, values.data(), 1, 0, error, frame))
  {
    return false;
  }
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const double v = values[i];
    // 2^63 is the first double beyond int64's range.
    if (!(std::fabs(v) < 9.2233720368547758e18) || v != std::floor(v))
    {
      error = "dataset " + name + " holds " + std::to_string(v) + " at particle " + std::to_string(offset + i) +
              ", not a whole number";
      return false;
    }
    ids[i] = static_cast<std::int64_t>(v);
  }
  return true;
}
} // namespace parafluid::h5
