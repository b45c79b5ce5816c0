// The one exception type for user-facing failures. main() prints
// "vkpt: error: <what>" and exits 1; the message names the file and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace vkpt {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vkpt
