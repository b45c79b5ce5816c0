// A parsed glTF and the file it came from: what every phase of the loader reads
// (validation, accessor decoding, materials, instancing), and how each reports a
// problem — Error naming the file and the glTF object, e.g. "meshes[2].indices".
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "util/error.h"

namespace vkpt::internal {

struct GltfSource {
  std::string path;
  const tinygltf::Model& m;

  [[noreturn]] void Fail(const std::string& what) const { throw Error(path + ": " + what); }

  // The index of `wanted` among `names` (an option's value: --variant, --animation): a
  // name, else a decimal index; −1 for "". Fails naming `option` when the file has no
  // `plural` at all (`none`), or listing its names when it has no such `singular`.
  int Choose(const std::vector<std::string>& names, const std::string& wanted, const std::string& option,
             const std::string& singular, const std::string& none) const {
    if (wanted.empty()) return -1;
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == wanted) return int(i);
    const bool digits = wanted.size() <= 9 && wanted.find_first_not_of("0123456789") == std::string::npos;
    if (digits && std::stoul(wanted) < names.size()) return int(std::stoul(wanted));
    if (names.empty()) Fail(option + " " + wanted + ": the file has " + none);
    std::string list;
    for (size_t i = 0; i < names.size(); ++i) list += (i ? ", " : "") + std::to_string(i) + " \"" + names[i] + "\"";
    Fail(option + " " + wanted + ": the file has no such " + singular + "; it has " + list);
  }

  template <class T>
  void CheckIndex(int index, const std::vector<T>& array, const std::string& what) const {
    if (index < 0 || size_t(index) >= array.size())
      Fail(what + " refers to index " + std::to_string(index) + ", but there are only " + std::to_string(array.size()));
  }
};

}  // namespace vkpt::internal
