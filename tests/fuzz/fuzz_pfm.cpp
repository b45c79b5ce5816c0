// libFuzzer target for the PFM reader of --diff: every input is written as image.pfm
// into a private directory and read with ReadPfm. An Image or a Error is the
// expected outcome; anything else is a finding (fuzz_target.h).
#include <cstdint>

#include "fuzz_bodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::internal::fuzz::ExpectOnly<vkpt::internal::Error>("fuzz_pfm", "vkpt::internal::Error", [&] {
    vkpt::internal::fuzz::RunPfm(vkpt::internal::fuzz::AsText(data, size));
  });
  return 0;
}
