// Members of a glTF extension object, which tinygltf hands over as untyped Values: each
// read checks the type and range the extension's schema gives, naming the member.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

// obj[key] as an integer in [0, 2^53); `fallback` when absent, failing if that is < 0.
inline uint64_t ExtensionUnsigned(const GltfSource& src, const tinygltf::Value& obj, const char* key,
                                  const std::string& what, int64_t fallback = -1) {
  if (!obj.Has(key)) {
    if (fallback < 0) src.Fail(what + "." + key + " is missing");
    return uint64_t(fallback);
  }
  const tinygltf::Value& v = obj.Get(key);
  const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
  if (!(d >= 0.0 && d < 9007199254740992.0 && d == std::floor(d)))
    src.Fail(what + "." + key + " must be a non-negative integer");
  return uint64_t(d);
}

// obj[key] as an index into `array`, checked.
template <class T>
int ExtensionIndex(const GltfSource& src, const tinygltf::Value& obj, const char* key, const std::vector<T>& array,
                   const std::string& what) {
  const uint64_t i = ExtensionUnsigned(src, obj, key, what);
  if (i >= array.size())
    src.Fail(what + "." + key + " refers to index " + std::to_string(i) + ", but there are only " +
             std::to_string(array.size()));
  return int(i);
}

// obj[key] as a string; `fallback` when absent.
inline std::string ExtensionString(const GltfSource& src, const tinygltf::Value& obj, const char* key,
                                   const std::string& what, const std::string& fallback) {
  if (!obj.Has(key)) return fallback;
  if (!obj.Get(key).IsString()) src.Fail(what + "." + key + " must be a string");
  return obj.Get(key).Get<std::string>();
}

}  // namespace vkpt::internal
