// libFuzzer target for the PFM reader of --diff: every input is written as image.pfm
// into a private directory and read with vkpt::ReadPfm. An Image or a vkpt::Error is the
// expected outcome; anything else is a finding (fuzz_target.h).
#include <cstdint>

#include "fuzz_target.h"
#include "image/image.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::fuzz::TempInput input(vkpt::fuzz::ScratchDir("vkpt-fuzz-pfm") + "/image.pfm", vkpt::fuzz::AsText(data, size));
  vkpt::fuzz::ExpectOnly<vkpt::Error>("fuzz_pfm", "vkpt::Error", [&] { vkpt::ReadPfm(input.path()); });
  return 0;
}
