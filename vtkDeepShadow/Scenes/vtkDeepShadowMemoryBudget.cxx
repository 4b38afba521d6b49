#include "vtkDeepShadowMemoryBudget.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sys/resource.h>
#include <unistd.h>

namespace deepshadow
{
namespace
{
std::string Readable(std::uint64_t bytes)
{
  const char* units[] = { "bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB" };
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 6)
  {
    value /= 1024.0;
    ++unit;
  }
  char text[64];
  std::snprintf(text, sizeof(text), unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}
}

std::uint64_t DefaultMemoryBudget()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  std::uint64_t budget = pages > 0 && pageSize > 0
    ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize) / 2
    : std::uint64_t(1) << 31;
  struct rlimit limit;
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
  {
    budget = std::min<std::uint64_t>(budget, static_cast<std::uint64_t>(limit.rlim_cur) / 2);
  }
  return budget;
}

std::uint64_t SaturatingProduct(std::uint64_t count, std::uint64_t size)
{
  if (count != 0 && size > std::numeric_limits<std::uint64_t>::max() / count)
  {
    return std::numeric_limits<std::uint64_t>::max();
  }
  return count * size;
}

std::string CheckMemoryBudget(const std::string& what, std::uint64_t bytes, std::uint64_t budget)
{
  if (bytes <= budget)
  {
    return std::string();
  }
  const std::string asked = bytes == std::numeric_limits<std::uint64_t>::max()
    ? std::string("more than 2^64 bytes")
    : std::to_string(bytes) + " bytes (" + Readable(bytes) + ")";
  return what + " would take " + asked + ", more than the memory budget of " +
    std::to_string(budget) + " bytes (" + Readable(budget) + ")";
}

}
