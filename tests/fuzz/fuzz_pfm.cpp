// libFuzzer target for the PFM reader of --diff: every input is written as image.pfm
// into a private directory and read with vkpt::ReadPfm. An Image or a vkpt::Error is the
// expected outcome; anything else is a finding (fuzz_target.h).
#include <cstdint>

#include "fuzz_bodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::fuzz::ExpectOnly<vkpt::Error>("fuzz_pfm", "vkpt::Error",
                                      [&] { vkpt::fuzz::RunPfm(vkpt::fuzz::AsText(data, size)); });
  return 0;
}
