#include "parafluid/h5part/Attributes.h"

#include "parafluid/h5part/Handle.h"

#include <algorithm>

namespace parafluid::h5
{
namespace
{
herr_t collectAttributeName(hid_t, const char* name, const H5A_info_t*, void* data)
{
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

/// A fixed-length string without its terminator and padding.
std::string trimmed(const char* text, std::size_t size, H5T_str_t padding)
{
  std::string s(text, std::find(text, text + size, '\0'));
  if (padding == H5T_STR_SPACEPAD)
  {
    s.erase(s.find_last_not_of(' ') + 1);
  }
  return s;
}

/// Why the attribute was not read; empty when it was.
std::string readOne(hid_t attribute, Attribute& out)
{
  Handle type(H5Aget_type(attribute), H5Tclose);
  Handle space(H5Aget_space(attribute), H5Sclose);
  if (!type.valid() || !space.valid())
  {
    return "HDF5 cannot read its type or shape";
  }
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count <= 0)
  {
    return "it holds no value";
  }
  if (static_cast<std::size_t>(count) > kMaxAttributeValues)
  {
    return "it holds " + std::to_string(count) + " values (more than " + std::to_string(kMaxAttributeValues) + ")";
  }
  const auto n = static_cast<std::size_t>(count);
  const H5T_class_t typeClass = H5Tget_class(type);
  if (typeClass == H5T_INTEGER || typeClass == H5T_FLOAT)
  {
    out.numbers.resize(n);
    return H5Aread(attribute, H5T_NATIVE_DOUBLE, out.numbers.data()) >= 0 ? "" : "HDF5 cannot convert it to numbers";
  }
  if (typeClass != H5T_STRING)
  {
    return "its type is neither numbers nor text";
  }
  out.text = true;
  if (H5Tis_variable_str(type) > 0)
  {
    Handle memoryType(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(memoryType, H5T_VARIABLE);
    H5Tset_cset(memoryType, H5Tget_cset(type));
    std::vector<char*> pointers(n, nullptr);
    if (H5Aread(attribute, memoryType, pointers.data()) < 0)
    {
      return "HDF5 cannot read its strings";
    }
    std::size_t bytes = 0;
    for (char* p : pointers)
    {
      std::string s = p ? std::string(p) : std::string();
      bytes += s.size();
      out.strings.push_back(bytes <= kMaxAttributeTextBytes ? std::move(s) : std::string());
    }
    H5Dvlen_reclaim(memoryType, space, H5P_DEFAULT, pointers.data());
    return bytes <= kMaxAttributeTextBytes ? "" : "its text is longer than " + std::to_string(kMaxAttributeTextBytes);
  }
  const std::size_t size = H5Tget_size(type);
  if (size == 0 || size > kMaxAttributeTextBytes / n)
  {
    return "its text is longer than " + std::to_string(kMaxAttributeTextBytes) + " bytes";
  }
  // n strings of `size` bytes each, read in the file's own fixed-length string type.
  Handle memoryType(H5Tcopy(type), H5Tclose);
  std::vector<char> text(n * size);
  if (H5Aread(attribute, memoryType, text.data()) < 0)
  {
    return "HDF5 cannot read its strings";
  }
  const H5T_str_t padding = H5Tget_strpad(type);
  for (std::size_t k = 0; k < n; ++k)
  {
    out.strings.push_back(trimmed(text.data() + k * size, size, padding));
  }
  return {};
}
} // namespace

std::vector<Attribute> readAttributes(hid_t object, std::vector<std::string>& warnings)
{
  std::vector<std::string> names;
  hsize_t position = 0;
  H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_NATIVE, &position, collectAttributeName, &names);
  std::vector<Attribute> attributes;
  for (const std::string& name : names)
  {
    Handle attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
    Attribute a;
    a.name = name;
    const std::string why = attribute.valid() ? readOne(attribute, a) : "HDF5 cannot open it";
    if (why.empty())
    {
      attributes.push_back(std::move(a));
    }
    else
    {
      warnings.push_back("attribute '" + name + "' is not read: " + why);
    }
  }
  return attributes;
}
} // namespace parafluid::h5
