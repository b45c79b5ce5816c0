// libFuzzer target for texture images (PNG, JPEG), in memory, the way the glTF loader
// decodes them (scene/gltf_texture_images.cpp): vkpt::ReadTextureImageHeader, the
// loader's memory charge for the texels (refused above the fuzz budget, fuzz_input.h,
// as the loader's budget would), then vkpt::DecodeTextureImage. Decoded texels or a
// vkpt::Error are the expected outcome; anything else is a finding (fuzz_target.h).
#include <cstdint>
#include <span>

#include "fuzz_target.h"
#include "image/texture_decode.h"
#include "util/error.h"

namespace {
// What the loader charges per texel (kBytesPerTexel in scene/gltf_texture_images.cpp).
constexpr uint64_t kBytesPerTexel = 16 + 4 + 4 * 6;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const unsigned char> bytes(data, size);
  vkpt::fuzz::ExpectOnly<vkpt::Error>("fuzz_texture", "vkpt::Error", [&] {
    const vkpt::TextureImageHeader header = vkpt::ReadTextureImageHeader(bytes, "");
    if (uint64_t(header.width) * header.height * kBytesPerTexel > vkpt::fuzz::kFuzzMaxMemory) return;
    vkpt::DecodeTextureImage(bytes, header);
  });
  return 0;
}
