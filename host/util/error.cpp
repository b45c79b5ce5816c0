#include "util/error.h"

#include <algorithm>
#include <cstdio>

namespace vkpt::internal {

void PrintError(const char* kind, std::string what) {
  std::replace(what.begin(), what.end(), '\n', ' ');
  constexpr size_t kMaxLength = 480;
  if (what.size() > kMaxLength) what = what.substr(0, kMaxLength - 80) + " … " + what.substr(what.size() - 60);
  std::fprintf(stderr, "vkpt: %s: %s\n", kind, what.c_str());
}

}  // namespace vkpt::internal
