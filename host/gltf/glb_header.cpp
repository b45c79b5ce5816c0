#include "gltf/glb_header.h"

#include <cstdint>
#include <cstring>

#include "util/error.h"

namespace vkpt::internal {
namespace {

constexpr uint32_t kChunkJson = 0x4E4F534Au;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942u;   // "BIN\0"

uint32_t ReadU32(std::string_view s, size_t at) {
  uint32_t v;
  std::memcpy(&v, s.data() + at, 4);
  return v;  // GLB is little-endian, as is every platform vkpt builds for
}

}  // namespace

std::string_view CheckGlbHeader(const std::string& path, std::string_view file) {
  auto fail = [&](const std::string& what) { throw Error(path + ": invalid GLB: " + what); };
  if (file.size() < 12) fail("file is shorter than the 12-byte header");
  if (std::memcmp(file.data(), "glTF", 4) != 0) fail("magic is not \"glTF\"");
  if (uint32_t version = ReadU32(file, 4); version != 2)
    fail("container version is " + std::to_string(version) + ", expected 2");
  if (uint32_t length = ReadU32(file, 8); length != file.size())
    fail("header says " + std::to_string(length) + " bytes but the file has " + std::to_string(file.size()));
  std::string_view json;
  bool haveBin = false;
  size_t at = 12;
  for (int chunk = 0; at < file.size(); ++chunk) {
    if (file.size() - at < 8) fail("chunk " + std::to_string(chunk) + " header is truncated");
    uint32_t length = ReadU32(file, at);
    uint32_t type = ReadU32(file, at + 4);
    at += 8;
    if (length > file.size() - at)
      fail("chunk " + std::to_string(chunk) + " (" + std::to_string(length) + " bytes) runs past the end of the file");
    if (length % 4)
      fail("chunk " + std::to_string(chunk) + " length " + std::to_string(length) + " is not a multiple of 4");
    if (chunk == 0) {
      if (type != kChunkJson) fail("the first chunk is not the JSON chunk");
      json = file.substr(at, length);
    } else if (type == kChunkJson) {
      fail("more than one JSON chunk");
    } else if (type == kChunkBin) {
      if (chunk != 1 || haveBin) fail("the BIN chunk must come once, right after the JSON chunk");
      haveBin = true;
    }
    at += length;
  }
  if (json.empty()) fail("no JSON chunk");
  return json;
}

}  // namespace vkpt::internal
