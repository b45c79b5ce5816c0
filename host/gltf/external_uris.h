// The files a glTF asks to read: every buffer and image `uri` that is not a data URI,
// listed from the JSON before tinygltf opens any of them.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkpt::internal {

struct ExternalUri {
  std::string owner;                   // "buffers[0]", "images[2]"
  std::string written;                 // the uri exactly as the file writes it
  std::string decoded;                 // percent-decoded as tinygltf decodes it (the path it asks for)
  std::optional<uint64_t> byteLength;  // buffers: the size the file must have
  bool used = true;                    // images: referenced by a texture (an unused image is not read)
};

// Data URIs that tinygltf decodes itself: anything else is a path or a URL.
bool IsEmbeddedDataUri(const std::string& uri);

// tinygltf's decoding of a uri: %XX escapes, and '+' as a space.
std::string DecodeUri(const std::string& uri);

std::vector<ExternalUri> ListExternalUris(const nlohmann::json& doc);

}  // namespace vkpt::internal
