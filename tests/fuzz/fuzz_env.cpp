// libFuzzer target for environment maps (--env): every input is written as env.exr (when
// it starts with OpenEXR's magic number) or env.hdr into a private directory and read
// with vkpt::ReadEnvironmentImage, the function --env uses, under the fuzz loader's
// memory budget (fuzz_input.h). An Image or a vkpt::Error is the expected outcome;
// anything else is a finding (fuzz_target.h).
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_target.h"
#include "image/image_load.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes = vkpt::fuzz::AsText(data, size);
  const bool exr = bytes.substr(0, 4) == std::string_view("\x76\x2f\x31\x01", 4);
  vkpt::fuzz::TempInput input(vkpt::fuzz::ScratchDir("vkpt-fuzz-env") + (exr ? "/env.exr" : "/env.hdr"), bytes);
  vkpt::fuzz::ExpectOnly<vkpt::Error>("fuzz_env", "vkpt::Error", [&] {
    uint64_t charged = 0;
    auto charge = [&](uint64_t n, const std::string& what) {
      charged += n;
      if (charged > vkpt::fuzz::kFuzzMaxMemory) throw vkpt::Error(what + " exceed the fuzz memory budget");
    };
    std::vector<std::string> warnings;
    vkpt::ReadEnvironmentImage(input.path(), charge, &warnings);
  });
  return 0;
}
