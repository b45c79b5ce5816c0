// A parsed glTF and the file it came from: what every phase of the loader reads
// (validation, accessor decoding, materials, instancing), and how each reports a
// problem — vkpt::Error naming the file and the glTF object, e.g. "meshes[2].indices".
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "util/error.h"

namespace vkpt {

struct GltfSource {
  std::string path;
  const tinygltf::Model& m;

  [[noreturn]] void Fail(const std::string& what) const { throw Error(path + ": " + what); }

  template <class T>
  void CheckIndex(int index, const std::vector<T>& array, const std::string& what) const {
    if (index < 0 || size_t(index) >= array.size())
      Fail(what + " refers to index " + std::to_string(index) + ", but there are only " + std::to_string(array.size()));
  }
};

}  // namespace vkpt
