// libFuzzer target for texture images (PNG, JPEG), in memory, the way the glTF loader
// decodes them (gltf/gltf_texture_images.cpp): ReadTextureImageHeader, the
// loader's memory charge for the texels (refused above the fuzz budget, fuzz_input.h,
// as the loader's budget would), then DecodeTextureImage. Decoded texels or a
// Error are the expected outcome; anything else is a finding (fuzz_target.h).
#include <cstdint>

#include "fuzz_bodies.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::internal::fuzz::ExpectOnly<vkpt::internal::Error>("fuzz_texture", "vkpt::internal::Error", [&] {
    vkpt::internal::fuzz::RunTexture(vkpt::internal::fuzz::AsText(data, size));
  });
  return 0;
}
