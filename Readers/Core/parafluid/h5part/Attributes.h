#pragma once
// The attributes of an HDF5 object (the scene constants on an H5Part file's root: particle_spacing,
// smoothing_length, a code's name...), each read into storage sized from its own dataspace and
// type: numbers of any integer or float type and any shape as doubles, fixed- and variable-length
// strings of any shape as strings. Anything else, or more than a limit, is skipped with a warning.
#include "parafluid/h5part/Hdf5.h"

#include <cstddef>
#include <string>
#include <vector>

namespace parafluid::h5
{
struct Attribute
{
  std::string name;
  bool text = false;           // strings (else numbers)
  std::vector<double> numbers; // every value, in row-major order
  std::vector<std::string> strings;
};

/// At most this many values per attribute (numbers or strings) and this many bytes of text.
constexpr std::size_t kMaxAttributeValues = std::size_t(1) << 20;
constexpr std::size_t kMaxAttributeTextBytes = std::size_t(16) << 20;

/// Every attribute of `object` that can be read; a warning for each that cannot, naming it.
std::vector<Attribute> readAttributes(hid_t object, std::vector<std::string>& warnings);
} // namespace parafluid::h5
