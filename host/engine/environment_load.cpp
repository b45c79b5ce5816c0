#include "engine/environment_load.h"

#include <cstdio>

#include "image/image_load.h"
#include "scene/load_limits.h"
#include "util/byte_size.h"

namespace vkpt::internal {

EnvironmentMap LoadEnvironment(const SceneSettings& s, const Scene& scene, const EngineLog& log, uint64_t* counted) {
  *counted = 0;
  if (s.env.empty()) return {};
  MemoryBudget budget(scene.memoryLimit, s.env);
  budget.Charge(scene.memoryCounted, "the scene " + scene.path);
  std::vector<std::string> warnings;
  const Image image = ReadEnvironmentImage(
      s.env, [&](uint64_t bytes, const std::string& what) { budget.Charge(bytes, what); }, &warnings);
  for (const std::string& w : warnings) log.Warn(w);
  budget.Charge(uint64_t(image.width) * image.height * kEnvironmentBytesPerTexel, "its sampling distribution");
  EnvironmentMap env = BuildEnvironmentMap(image.width, image.height, image.pixels, s.threads);
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "%u × %u texels, intensity %g; distribution built in %.2f ms", env.width,
                env.height, s.envIntensity, env.buildMs);
  log.Info("environment: " + s.env + ": " + numbers + "; memory: " + FormatBytes(budget.Used()) +
           " counted with the scene");
  *counted = budget.Used() - scene.memoryCounted;
  return env;
}

}  // namespace vkpt::internal
