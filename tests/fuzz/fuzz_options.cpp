// libFuzzer target for the command-line parser: the input is split on NUL bytes into
// arguments (argv[0] "vkpt" first) for ParseOptions; Options or a UsageError
// are the expected outcome, anything else is a finding (fuzz_target.h). Seeds are the
// command lines of options.seeds, one a line, written NUL-separated by run.sh.
#include <cstdint>

#include "fuzz_bodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::internal::fuzz::ExpectOnly<vkpt::internal::UsageError>("fuzz_options", "vkpt::internal::UsageError", [&] {
    vkpt::internal::fuzz::RunOptions(vkpt::internal::fuzz::AsText(data, size));
  });
  return 0;
}
