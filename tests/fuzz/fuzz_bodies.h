// One input through the entry point each fuzz target exercises, exactly as the target
// runs it: the libFuzzer targets (fuzz_<target>.cpp) call these, and so does the replay
// of every kept finding in the normal build (tests/test_fuzz_regressions.cpp). Each
// throws its entry point's documented error type on a clean refusal.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/options.h"
#include "fuzz_target.h"
#include "image/image.h"
#include "image/image_load.h"
#include "image/texture_decode.h"
#include "util/error.h"

namespace vkpt::fuzz {

// --env maps: written as env.exr (OpenEXR's magic number first) or env.hdr into a private
// directory and read by ReadEnvironmentImage, the function --env uses, under the fuzz
// memory budget (fuzz_input.h). Throws vkpt::Error.
inline void RunEnv(std::string_view bytes) {
  const bool exr = bytes.substr(0, 4) == std::string_view("\x76\x2f\x31\x01", 4);
  TempInput input(ScratchDir("vkpt-fuzz-env") + (exr ? "/env.exr" : "/env.hdr"), bytes);
  uint64_t charged = 0;
  auto charge = [&](uint64_t n, const std::string& what) {
    charged += n;
    if (charged > kFuzzMaxMemory) throw Error(what + " exceed the fuzz memory budget");
  };
  std::vector<std::string> warnings;
  ReadEnvironmentImage(input.path(), charge, &warnings);
}

// What the loader charges per texel (kBytesPerTexel in scene/gltf_texture_images.cpp).
constexpr uint64_t kTextureBytesPerTexel = 16 + 4 + 4 * 6;

// Texture images (PNG, JPEG) in memory, as the glTF loader decodes them
// (scene/gltf_texture_images.cpp): the header, the loader's charge for the texels
// (refused above the fuzz budget, as the loader's budget would), then the decode.
// Throws vkpt::Error.
inline void RunTexture(std::string_view text) {
  const std::span<const unsigned char> bytes(reinterpret_cast<const unsigned char*>(text.data()), text.size());
  const TextureImageHeader header = ReadTextureImageHeader(bytes, "");
  if (uint64_t(header.width) * header.height * kTextureBytesPerTexel > kFuzzMaxMemory) return;
  DecodeTextureImage(bytes, header);
}

// The PFM reader of --diff: written as image.pfm into a private directory and read by
// ReadPfm. Throws vkpt::Error.
inline void RunPfm(std::string_view bytes) {
  TempInput input(ScratchDir("vkpt-fuzz-pfm") + "/image.pfm", bytes);
  ReadPfm(input.path());
}

// The command line: split on NUL bytes into arguments (argv[0] "vkpt" first) for
// ParseOptions. Throws vkpt::UsageError.
inline void RunOptions(std::string_view text) {
  std::vector<std::string> args{"vkpt"};
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find('\0', start), text.size());
    if (end > start || end < text.size()) args.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  ParseOptions(int(args.size()), argv.data());
}

}  // namespace vkpt::fuzz
