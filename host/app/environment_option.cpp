#include "app/environment_option.h"

#include <cstdio>

#include "image/image_load.h"
#include "scene/load_limits.h"
#include "util/byte_size.h"

namespace vkpt {

EnvironmentMap LoadEnvironment(const Options& o, const Scene& scene, uint64_t* counted) {
  *counted = 0;
  if (o.env.empty()) return {};
  MemoryBudget budget(scene.memoryLimit, o.env);
  budget.Charge(scene.memoryCounted, "the scene " + scene.path);
  std::vector<std::string> warnings;
  const Image image = ReadEnvironmentImage(
      o.env, [&](uint64_t bytes, const std::string& what) { budget.Charge(bytes, what); }, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "vkpt: warning: %s\n", w.c_str());
  budget.Charge(uint64_t(image.width) * image.height * kEnvironmentBytesPerTexel, "its sampling distribution");
  EnvironmentMap env = BuildEnvironmentMap(image.width, image.height, image.pixels, o.threads);
  if (o.verbose)
    std::printf(
        "environment: %s: %u × %u texels, rotation %g°, intensity %g; distribution built in %.2f ms; "
        "memory: %s counted with the scene\n",
        o.env.c_str(), env.width, env.height, o.envRotation, o.envIntensity, env.buildMs,
        FormatBytes(budget.Used()).c_str());
  *counted = budget.Used() - scene.memoryCounted;
  return env;
}

}  // namespace vkpt
