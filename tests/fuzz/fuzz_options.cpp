// libFuzzer target for the command-line parser: the input is split on NUL bytes into
// arguments (argv[0] "vkpt" first) for vkpt::ParseOptions; Options or a vkpt::UsageError
// are the expected outcome, anything else is a finding (fuzz_target.h). Seeds are the
// command lines of options.seeds, one a line, written NUL-separated by run.sh.
#include <cstdint>
#include <string>
#include <vector>

#include "app/options.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(vkpt::fuzz::AsText(data, size));
  std::vector<std::string> args{"vkpt"};
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find('\0', start), text.size());
    if (end > start || end < text.size()) args.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  vkpt::fuzz::ExpectOnly<vkpt::UsageError>("fuzz_options", "vkpt::UsageError",
                                           [&] { vkpt::ParseOptions(int(args.size()), argv.data()); });
  return 0;
}
