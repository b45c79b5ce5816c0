#include "scene/load_limits.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

#include <fstream>

#include "util/byte_size.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// cgroup v2's memory.max for this process ("max" or absent: no limit).
uint64_t CgroupLimit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(in >> text) || text == "max") return UINT64_MAX;
  return ParseByteSize(text).value_or(UINT64_MAX);
}

// The soft limit on this process's address space or data (ulimit -v, ulimit -d).
uint64_t AddressSpaceLimit() {
  uint64_t limit = UINT64_MAX;
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit r{};
    if (getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY) limit = std::min<uint64_t>(limit, r.rlim_cur);
  }
  return limit;
}

}  // namespace

uint64_t DefaultMaxMemory() {
  long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  uint64_t physical = pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : (uint64_t(4) << 30);
  return std::min({physical, CgroupLimit(), AddressSpaceLimit()}) / 2;
}

void MemoryBudget::Charge(uint64_t bytes, const std::string& what, const std::string& advice) {
  const uint64_t before = used_;
  used_ = bytes > UINT64_MAX - used_ ? UINT64_MAX : used_ + bytes;
  if (used_ <= limit_) return;
  std::string message = file_ + ": " + what + " needs " + FormatBytes(bytes);
  if (before) message += " on top of the " + FormatBytes(before) + " counted before it";
  throw Error(message + ", more than --max-memory " + FormatBytes(limit_) + " allows (" + advice + ")");
}

}  // namespace vkpt::internal
