// The one exception type for user-facing failures. main() prints
// "vkpt: error: <what>" and exits 1; the message names the file and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace vkpt::internal {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Prints "vkpt: <kind>: <what>" to stderr as one line of at most a few hundred characters,
// whatever a file or an argument put into `what`.
void PrintError(const char* kind, std::string what);

}  // namespace vkpt::internal
