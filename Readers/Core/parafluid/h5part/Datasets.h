#pragma once
// Reading the values of H5Part datasets into memory the caller owns: the one value type that holds
// every dataset of an array without loss (vx int32 with vy/vz float64 reads as float64, uint32
// as int64), row slices of N or N x k datasets, component datasets interleaved into a vector, and
// ids that must be whole numbers.
#include "parafluid/h5part/Hdf5.h"

#include <cstdint>
#include <string>
#include <vector>

namespace parafluid::h5
{
enum class ValueType
{
  Float32,
  Float64,
  Int32,
  Int64,
  UInt64
};

/// The narrowest type that holds the values of all the datasets of `group` named in `datasets`.
ValueType commonValueType(hid_t group, const std::vector<std::string>& datasets);
hid_t memoryType(ValueType type);
std::size_t valueBytes(ValueType type);

/// Reads rows [offset, offset + count) of a dataset of N or N x k values into column `column` (of
/// `stride` columns) of `target`, which holds count x stride values of `type`. False (with
/// `error`) when the dataset cannot be read or its width does not fit the stride.
/// `frame` >= 0 reads those rows of frame `frame` of an F x N (x k) dataset.
bool readSlice(hid_t group, const std::string& name, ValueType type, std::uint64_t offset, std::uint64_t count,
               void* target, std::uint64_t stride, std::uint64_t column, std::string& error, std::int64_t frame = -1);

/// Reads ids [offset, offset + count) of a 1-D id dataset. A float id dataset is accepted only
/// when every value is a whole number within int64's range; false with `error` naming the first
/// bad value otherwise.
bool readIds(hid_t group, const std::string& name, std::uint64_t offset, std::uint64_t count, std::int64_t* ids,
             std::string& error, std::int64_t frame = -1);
} // namespace parafluid::h5
