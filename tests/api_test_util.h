// What the library's tests (test_api*.cpp) share: the Cornell box, edited as a test
// needs, and a small render of it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_util.h"
#include "vkpt/scene_access.h"
#include "vkpt/vkpt.h"

namespace vkpt::internal::test {

inline std::string Cornell() { return SourcePath("scenes/cornell.gltf"); }

// 24 × 16 pixels, one chunk of 4 samples per pixel.
inline vkpt::RenderOptions SmallRender(uint32_t seed = 0) {
  vkpt::RenderOptions o;
  o.width = 24;
  o.height = 16;
  o.spp = o.chunkSpp = 4;
  o.seed = seed;
  return o;
}

inline vkpt::Scene Open(const std::string& path, vkpt::Backend backend, const std::string& environment = "") {
  vkpt::SceneOptions options;
  options.backend = backend;
  options.environment = environment;
  return vkpt::Scene(path, options);
}

// The Cornell box edited by `edit`, written to `name` in `folder` beside a copy of its
// buffer.
inline std::string WriteCornell(const TempFolder& folder, const std::string& name,
                                const std::function<void(nlohmann::json&)>& edit) {
  std::ifstream in(Cornell());
  nlohmann::json file = nlohmann::json::parse(in);
  edit(file);
  if (!std::filesystem::exists(folder / "cornell.bin"))
    std::filesystem::copy_file(SourcePath("scenes/cornell.bin"), folder / "cornell.bin");
  std::ofstream(folder / name) << file.dump();
  return folder / name;
}

// How often the scene's arrays were built whole (LoadedScene::Counts).
inline uint32_t Builds(vkpt::Scene& scene) { return vkpt::SceneAccess::Engine(scene).Counts().builds; }

// Each of `refused` raises SettingError with its message, and leaves the scene's values,
// its render and its built arrays as they were.
inline void ExpectEachRefused(vkpt::Scene& scene,
                              const std::vector<std::pair<vkpt::ParameterMap, std::string>>& refused) {
  const vkpt::ParameterMap original = scene.Parameters();
  const vkpt::RenderResult before = scene.Render({}, SmallRender(3));
  for (const auto& [changes, message] : refused) {
    try {
      scene.Update(changes);
      ADD_FAILURE() << "accepted: " << message;
    } catch (const vkpt::SettingError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(scene.Parameters(), original);
  EXPECT_EQ(scene.Render({}, SmallRender(3)).image.data, before.image.data);
  EXPECT_EQ(Builds(scene), 1u);
}

}  // namespace vkpt::internal::test
