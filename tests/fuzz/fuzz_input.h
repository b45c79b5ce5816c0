// One fuzz input through the glTF loader, the way the fuzz target (fuzz_loader.cpp) runs
// it; the regression test (tests/test_fuzz_regressions.cpp) replays kept inputs with the
// same code, so a kept input meets the loader exactly as it did when it was found.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "gltf/gltf_loader.h"
#include "util/error.h"

namespace vkpt::internal::fuzz {

// A new empty directory only this process uses (mode 0700), under $TMPDIR or /tmp: the
// input file is alone in it, so a relative URI in the input finds nothing of ours.
inline std::string MakePrivateDir(const std::string& prefix) {
  const char* tmp = std::getenv("TMPDIR");
  std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + "-XXXXXX";
  if (!mkdtemp(dir.data())) throw std::runtime_error("mkdtemp " + dir + ": " + std::strerror(errno));
  return dir;
}

// The input's file name, by content as the loader itself decides: scene.glb when it
// starts with the GLB magic "glTF", else scene.gltf.
inline std::string InputFileName(std::string_view bytes) {
  return bytes.substr(0, 4) == "glTF" ? "scene.glb" : "scene.gltf";
}

// The loader's memory budget for fuzz inputs: far below libFuzzer's -malloc_limit_mb, so
// an input that asks for too much is refused by the budget (a Error, as a user
// would see it) and anything that still allocates past the malloc limit is a finding:
// memory the budget failed to count.
constexpr uint64_t kFuzzMaxMemory = uint64_t(256) << 20;

// Writes `bytes` to <dir>/InputFileName(bytes), loads that file with LoadGltf and
// removes it. True when a scene loaded, false on Error (its message goes to
// `error` if given); any other exception (or crash) is the caller's finding.
inline bool LoadInput(const std::string& dir, std::string_view bytes, std::string* error = nullptr) {
  const std::string path = dir + "/" + InputFileName(bytes);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot create " + path + ": " + std::strerror(errno));
  bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !written) throw std::runtime_error("cannot write " + path);
  struct Remove {
    const std::string& path;
    ~Remove() { std::remove(path.c_str()); }
  } remove{path};
  try {
    const vkpt::internal::LoadLimits limits{.maxMemory = kFuzzMaxMemory};
    const vkpt::internal::Scene scene = vkpt::internal::LoadGltf(path, limits);
    // An animated file is loaded once more, posed halfway through its first animation, so
    // that its keyframes are read too.
    if (!scene.animations.empty())
      vkpt::internal::LoadGltf(path, limits, {.animation = "0", .time = scene.animations[0].duration / 2});
    return true;
  } catch (const vkpt::internal::Error& e) {
    if (error) *error = e.what();
    return false;
  }
}

}  // namespace vkpt::internal::fuzz
