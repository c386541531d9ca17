#include "parafluid/common/MemoryBudget.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sys/resource.h>
#include <unistd.h>

namespace parafluid
{
std::size_t memoryBudgetBytes()
{
  if (const char* megabytes = std::getenv("PARAFLUID_MEMORY_BUDGET_MB"))
  {
    const double mb = std::atof(megabytes);
    if (mb > 0.0)
    {
      return static_cast<std::size_t>(mb * 1024.0 * 1024.0);
    }
  }
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGE_SIZE);
  double limit = pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 8e9;
  rlimit addressSpace{};
  if (::getrlimit(RLIMIT_AS, &addressSpace) == 0 && addressSpace.rlim_cur != RLIM_INFINITY)
  {
    limit = std::min(limit, static_cast<double>(addressSpace.rlim_cur));
  }
  return static_cast<std::size_t>(limit / 2.0);
}

std::string describeBytes(double bytes)
{
  char text[64];
  if (bytes >= 1e9)
  {
    std::snprintf(text, sizeof(text), "%.1f GB", bytes / 1e9);
  }
  else if (bytes >= 1e6)
  {
    std::snprintf(text, sizeof(text), "%.0f MB", bytes / 1e6);
  }
  else
  {
    std::snprintf(text, sizeof(text), "%.0f kB", bytes / 1e3);
  }
  return text;
}

std::string checkMemoryBudget(double bytes, const std::string& what)
{
  const double budget = static_cast<double>(memoryBudgetBytes());
  if (!(bytes <= budget))
  {
    return what + " would take " + describeBytes(bytes) + ", more than the " + describeBytes(budget) +
           " one output may use (" +
           (std::getenv("PARAFLUID_MEMORY_BUDGET_MB") ? std::string("PARAFLUID_MEMORY_BUDGET_MB")
                                                      : std::string("half of this machine's memory; "
                                                                    "PARAFLUID_MEMORY_BUDGET_MB sets another limit")) +
           ")";
  }
  return {};
}
} // namespace parafluid
