#include "app/options_api.h"

#include "session/aov.h"

namespace vkpt::internal {
namespace {

vkpt::SceneOptions SceneOptionsOf(const Options& o) {
  vkpt::SceneOptions s;
  s.backend = o.backend;
  s.device = o.device;
  s.validation = o.validation;
  s.threads = o.threads;
  s.maxMemory = o.load.maxMemory;
  s.maxTexels = o.load.maxTextureTexels;
  s.allowExternalUris = o.load.allowExternalUris;
  s.variant = o.variant;
  s.animation = o.animation;
  s.environment = o.env;
  s.environmentIntensity = o.envIntensity;
  s.lightSampler = o.lightSampler;
  return s;
}

vkpt::Camera CameraOf(const Options& o) {
  vkpt::Camera c;
  c.index = o.camera;
  c.lookFrom = o.lookFrom;
  c.lookAt = o.lookAt;
  c.up = o.up;
  c.fovDegrees = o.fov;
  c.orbitDegrees = o.orbit.value_or(0.0);
  return c;
}

vkpt::RenderOptions RenderOptionsOf(const Options& o) {
  vkpt::RenderOptions r;
  r.width = o.width;
  r.height = o.height;
  r.spp = o.spp;
  r.seconds = o.time;
  r.noiseTarget = o.noiseTarget;
  r.adaptive = o.adaptive;
  r.seed = o.seed;
  r.maxDepth = o.maxDepth;
  r.rrDepth = o.rrDepth;
  r.chunkSpp = o.chunkSpp;
  r.batch = o.batch;
  r.time = o.at.value_or(0.0);
  r.background = o.background;
  r.environmentRotation = o.envRotation;
  r.textureLod = o.textureLod;
  for (Aov aov : o.aovs) r.aovs.emplace_back(AovName(aov));
  r.denoise = o.denoise;
  return r;
}

}  // namespace

ApiSettings ApiSettingsOf(const Options& o) { return {SceneOptionsOf(o), CameraOf(o), RenderOptionsOf(o)}; }

}  // namespace vkpt::internal
