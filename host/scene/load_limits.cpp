#include "scene/load_limits.h"

#include <unistd.h>

#include <fstream>

#include "util/byte_size.h"
#include "util/error.h"

namespace vkpt {
namespace {

// cgroup v2's memory.max for this process ("max" or absent: no limit).
uint64_t CgroupLimit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(in >> text) || text == "max") return UINT64_MAX;
  return ParseByteSize(text).value_or(UINT64_MAX);
}

}  // namespace

uint64_t DefaultMaxMemory() {
  long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  uint64_t physical = pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : (uint64_t(4) << 30);
  return std::min(physical, CgroupLimit()) / 2;
}

void MemoryBudget::Charge(uint64_t bytes, const std::string& what) {
  const uint64_t before = used_;
  used_ = bytes > UINT64_MAX - used_ ? UINT64_MAX : used_ + bytes;
  if (used_ <= limit_) return;
  std::string message = file_ + ": " + what + " needs " + FormatBytes(bytes);
  if (before) message += " on top of the " + FormatBytes(before) + " counted before it";
  throw Error(message + ", more than --max-memory " + FormatBytes(limit_) +
              " allows (raise --max-memory if the scene is genuine)");
}

}  // namespace vkpt
