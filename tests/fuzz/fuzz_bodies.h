// One input through the entry point each fuzz target exercises, exactly as the target
// runs it: the libFuzzer targets (fuzz_<target>.cpp) call these, and so does the replay
// of every kept finding in the normal build (tests/test_fuzz_regressions.cpp). Each
// throws its entry point's documented error type on a clean refusal.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/options.h"
#include "fuzz_target.h"
#include "gltf/draco_decode.h"
#include "gltf/meshopt_decode.h"
#include "image/image.h"
#include "image/image_load.h"
#include "image/texture_decode.h"
#include "util/error.h"

namespace vkpt::internal::fuzz {

// --env maps: written as env.exr (OpenEXR's magic number first) or env.hdr into a private
// directory and read by ReadEnvironmentImage, the function --env uses, under the fuzz
// memory budget (fuzz_input.h). Throws Error.
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

// What the loader charges per texel (kBytesPerTexel in gltf/gltf_texture_images.cpp).
constexpr uint64_t kTextureBytesPerTexel = 16 + 4 + 4 * 6;

// Texture images (PNG, JPEG) in memory, as the glTF loader decodes them
// (gltf/gltf_texture_images.cpp): the header, the loader's charge for the texels
// (refused above the fuzz budget, as the loader's budget would), then the decode.
// Throws Error.
inline void RunTexture(std::string_view text) {
  const std::span<const unsigned char> bytes(reinterpret_cast<const unsigned char*>(text.data()), text.size());
  const TextureImageHeader header = ReadTextureImageHeader(bytes, "");
  if (uint64_t(header.width) * header.height * kTextureBytesPerTexel > kFuzzMaxMemory) return;
  DecodeTextureImage(bytes, header);
}

// The PFM reader of --diff: written as image.pfm into a private directory and read by
// ReadPfm. Throws Error.
inline void RunPfm(std::string_view bytes) {
  TempInput input(ScratchDir("vkpt-fuzz-pfm") + "/image.pfm", bytes);
  ReadPfm(input.path());
}

// The command line: split on NUL bytes into arguments (argv[0] "vkpt" first) for
// ParseOptions. Throws UsageError.
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

// KHR_draco_mesh_compression bitstreams through DecodeDraco, in memory. The input
// is a 13-byte header, the glTF side of one primitive, then the Draco bitstream
// (fuzz_seeds writes seeds in this layout):
//   [0]       accessors: byte % 5 (0 … 4)
//   [1..8]    per accessor slot, 2 bytes: the Draco attribute's unique id, then its layout:
//             components 1 + (byte & 3), component type kDracoComponentTypes[(byte >> 2) % 6]
//   [9..10]   the accessors' count (points), little-endian, 0 … 65535
//   [11..12]  the indices accessor's count, little-endian, 0 … 65535
// Fixed offsets, so that mutating the bitstream never shifts the header. Small counts
// keep what DecodeDraco allocates for the accessors small; what libdraco allocates is
// the bitstream's to decide, and over -malloc_limit_mb is a finding (run.sh). Throws
// Error.
inline void RunDraco(std::string_view text) {
  constexpr size_t kHeaderSize = 13;
  constexpr int kDracoComponentTypes[6] = {5120, 5121, 5122, 5123, 5125, 5126};
  const char* const kNames[4] = {"A0", "A1", "A2", "A3"};
  const auto* data = reinterpret_cast<const uint8_t*>(text.data());
  if (text.size() < kHeaderSize) return;
  const size_t count = data[9] | data[10] << 8;
  const size_t indexCount = data[11] | data[12] << 8;
  std::vector<DracoAccessor> accessors;
  for (int i = 0; i < data[0] % 5; ++i) {
    const uint8_t layout = data[2 + 2 * i];
    accessors.push_back({kNames[i], data[1 + 2 * i], 1 + (layout & 3), kDracoComponentTypes[(layout >> 2) % 6], count});
  }
  DecodeDraco({data + kHeaderSize, text.size() - kHeaderSize}, accessors, indexCount);
}

// EXT_meshopt_compression streams the way the loader runs them (gltf/gltf_meshopt.cpp):
// CheckMeshoptStream, then, only for a stream it passes, DecodeMeshoptStream
// into exactly count × byteStride bytes. meshoptimizer is a shared library, not
// instrumented: ASan would not see it write past them, so they are followed by guard
// bytes checked after each decode. The input is a 6-byte header, the extension's
// parameters, then the encoded data (fuzz_seeds writes seeds in this layout):
//   [0]     mode: ATTRIBUTES, TRIANGLES, INDICES [byte % 3]
//   [1]     filter: NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL [byte % 4]
//   [2..3]  byteStride, little-endian, % 512: valid (4 … 256, 2 or 4) and invalid ones
//   [4..5]  count, little-endian, % 4096: at most 1 MiB of output for the harness
// Throws Error.
inline void RunMeshopt(std::string_view text) {
  constexpr size_t kHeaderSize = 6, kGuardSize = 64;
  constexpr unsigned char kGuardByte = 0xa5;
  const char* const kModes[3] = {"ATTRIBUTES", "TRIANGLES", "INDICES"};
  const char* const kFilters[4] = {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"};
  const auto* data = reinterpret_cast<const uint8_t*>(text.data());
  if (text.size() < kHeaderSize) return;
  MeshoptStream s;
  s.mode = kModes[data[0] % 3];
  s.filter = kFilters[data[1] % 4];
  s.byteStride = (data[2] | data[3] << 8) % 512;
  s.count = (data[4] | data[5] << 8) % 4096;
  if (!CheckMeshoptStream(s).empty()) return;
  std::vector<unsigned char> buffer(s.count * s.byteStride + kGuardSize, kGuardByte);
  const std::span<unsigned char> out(buffer.data(), s.count * s.byteStride);
  // Aborts, when destroyed (after a decode or as its error unwinds), if a guard changed.
  struct GuardCheck {
    const std::vector<unsigned char>& buffer;
    size_t end;
    ~GuardCheck() {
      for (size_t i = end; i < buffer.size(); ++i)
        if (buffer[i] != kGuardByte) {
          std::fprintf(stderr, "fuzz_meshopt: the decoder wrote byte %zu of a %zu-byte output\n", i, end);
          std::abort();
        }
    }
  } check{buffer, out.size()};
  DecodeMeshoptStream({data + kHeaderSize, text.size() - kHeaderSize}, s, out);
}

}  // namespace vkpt::internal::fuzz
