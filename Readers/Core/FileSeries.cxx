// Numbered file series: PySPH's <name>_<count>.hdf5, Gadget's and SWIFT's snap_<k>.hdf5 (and
// snap_<k>.<part>.hdf5 for snapshots of several files), found by listing the file's folder.
#include "private/LayoutParts.h"

#include <algorithm>
#include <cctype>
#include <dirent.h>
#include <sys/stat.h>

namespace parafluid::h5::detail
{
namespace
{
// More members than this is a folder of unrelated outputs, not one run's series.
constexpr std::size_t kMaxSeriesFiles = 1000000;

bool isRegularFile(const std::string& path)
{
  struct stat status;
  return ::stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}

bool allDigits(const std::string& text)
{
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}
} // namespace

std::vector<std::string> numberedSeries(const std::string& fileName, bool multiFilePart)
{
  const std::size_t slash = fileName.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : fileName.substr(0, slash);
  const std::string name = slash == std::string::npos ? fileName : fileName.substr(slash + 1);
  // The number's end: before the extension, and before ".<part>" of a multi-file snapshot.
  std::size_t end = name.rfind('.');
  end = end == std::string::npos || end == 0 ? name.size() : end;
  if (multiFilePart)
  {
    const std::size_t part = name.rfind('.', end - 1);
    if (part == std::string::npos || !allDigits(name.substr(part + 1, end - part - 1)))
    {
      return {};
    }
    end = part;
  }
  std::size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(name[begin - 1])))
  {
    --begin;
  }
  if (begin == end)
  {
    return {};
  }
  const std::string prefix = name.substr(0, begin), suffix = name.substr(end);
  std::vector<std::pair<unsigned long long, std::string>> members;
  DIR* directory = ::opendir(folder.c_str());
  if (!directory)
  {
    return {};
  }
  while (const dirent* entry = ::readdir(directory))
  {
    const std::string other = entry->d_name;
    if (other.size() <= prefix.size() + suffix.size() || other.compare(0, prefix.size(), prefix) != 0 ||
        other.compare(other.size() - suffix.size(), suffix.size(), suffix) != 0)
    {
      continue;
    }
    const std::string number = other.substr(prefix.size(), other.size() - prefix.size() - suffix.size());
    const std::string path = slash == std::string::npos ? other : folder + "/" + other;
    if (allDigits(number) && number.size() < 19 && isRegularFile(path))
    {
      members.emplace_back(std::stoull(number), path);
    }
    if (members.size() > kMaxSeriesFiles)
    {
      break;
    }
  }
  ::closedir(directory);
  if (members.size() < 2 || members.size() > kMaxSeriesFiles)
  {
    return {};
  }
  std::sort(members.begin(), members.end());
  std::vector<std::string> files;
  for (const auto& member : members)
  {
    files.push_back(member.second);
  }
  return files;
}
} // namespace parafluid::h5::detail
