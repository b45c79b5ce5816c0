// libFuzzer target for environment maps (--env): every input is written as env.exr (when
// it starts with OpenEXR's magic number) or env.hdr into a private directory and read
// with ReadEnvironmentImage, the function --env uses, under the fuzz loader's
// memory budget (fuzz_input.h). An Image or a Error is the expected outcome;
// anything else is a finding (fuzz_target.h).
#include <cstdint>

#include "fuzz_bodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::internal::fuzz::ExpectOnly<vkpt::internal::Error>("fuzz_env", "vkpt::internal::Error", [&] {
    vkpt::internal::fuzz::RunEnv(vkpt::internal::fuzz::AsText(data, size));
  });
  return 0;
}
