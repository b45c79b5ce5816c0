#include "vkpt/scene_records.h"

#include <cmath>

#include "vkpt/public_values.h"
#include "vkpt/scene_access.h"

namespace vkpt::internal {
namespace {

const char* LightTypeName(PunctualLight::Type type) {
  switch (type) {
    case PunctualLight::Type::kSpot: return "spot";
    case PunctualLight::Type::kDirectional: return "directional";
    default: return "point";
  }
}

double Degrees(double radians) { return radians * 180.0 / M_PI; }

vkpt::BvhInfo BvhInfoOf(const BvhStats& b) {
  return {b.spatialSplits ? "spatial" : "object",
          b.nodes,
          b.leaves,
          b.depth,
          b.references,
          b.sahCost,
          b.rejectedSahCost,
          b.buildMs};
}

}  // namespace

vkpt::MaterialInfo MaterialInfoOf(const Scene& scene, uint32_t index) {
  const Material& m = scene.materials[index];
  vkpt::MaterialInfo info;
  info.index = index;
  info.name = scene.materialNames[index];
#define VKPT_COPY_FACTOR(type, member, python, lo, hi, doc) info.member = Public(m.member);
  VKPT_MATERIAL_FACTORS(VKPT_COPY_FACTOR)
#undef VKPT_COPY_FACTOR
  info.alphaMode = kAlphaModeNames[size_t(m.alphaMode)];
  for (uint32_t s = 0; s < kTextureSlotCount; ++s)
    if (const MaterialTexture& t = m.textures[s]; t.Present())
      info.textures[kTextureSlotInfo[s].name] = {scene.textures[t.texture].fileIndex, t.texCoord};
  return info;
}

vkpt::CameraInfo CameraInfoOf(const Camera& c, uint32_t index) {
  return {index,           c.name, Public(c.position), Public(c.forward), Public(c.up), c.orthographic,
          Degrees(c.yfov), c.ymag, c.aspectRatio};
}

vkpt::LightInfo LightInfoOf(const PunctualLight& l, uint32_t index) {
  const bool spot = l.type == PunctualLight::Type::kSpot;
  return {index,
          l.light,
          l.name,
          LightTypeName(l.type),
          Public(l.color),
          l.lightIntensity,
          Public(l.position),
          Public(l.direction),
          l.range,
          spot ? Degrees(std::acos(double(l.cosInner))) : 0.0,
          spot ? Degrees(std::acos(double(l.cosOuter))) : 0.0};
}

vkpt::NodeInfo NodeInfoOf(const NodeSummary& n, uint32_t index) {
  const auto optional = [](int i) { return i < 0 ? std::nullopt : std::optional<uint32_t>(uint32_t(i)); };
  return {index,
          n.name,
          optional(n.mesh),
          optional(n.camera),
          optional(n.light),
          n.children,
          Public(n.translation),
          Public(n.rotation),
          Public(n.scale),
          n.matrix};
}

vkpt::SceneStats StatsOf(const LoadedScene& loaded) {
  const Scene& scene = loaded.scene();
  const RenderScene& rs = loaded.Arrays();
  vkpt::SceneStats s;
  s.path = scene.path;
  s.contentHash = scene.contentHash;
  s.triangles = scene.triangles.size();
  s.degenerateTriangles = rs.degenerateTriangles;
  s.materials = scene.materials.size();
  s.lights = rs.lights.size();
  s.textures = scene.textures.size();
  s.images = scene.images.size();
  for (const TextureImage& im : scene.images) s.texels += uint64_t(im.width) * im.height;
  s.textureBytes = rs.texels.size() * sizeof(uint32_t);
  s.vertexColors = !scene.colors.empty();
  s.generatedTangentPrimitives = scene.generatedTangentPrimitives;
  s.boundsMin = Public(scene.bounds.lo);
  s.boundsMax = Public(scene.bounds.hi);
  s.memoryCounted = scene.memoryCounted;
  s.memoryLimit = scene.memoryLimit;
  if (scene.variant >= 0) s.variant = uint32_t(scene.variant);
  if (scene.animation >= 0) s.animation = uint32_t(scene.animation);
  s.animationTime = scene.animationTime;
  s.warnings = scene.warnings;
  s.ignoredFeatures = scene.ignoredFeatures;
  s.bvh = BvhInfoOf(rs.bvhStats);
  return s;
}

}  // namespace vkpt::internal

namespace vkpt {

std::vector<MaterialInfo> Scene::Materials() const {
  const internal::Scene& scene = SceneAccess::Engine(*this).scene();
  std::vector<MaterialInfo> materials;
  for (uint32_t i = 0; i < scene.materials.size(); ++i) materials.push_back(internal::MaterialInfoOf(scene, i));
  return materials;
}

std::vector<CameraInfo> Scene::Cameras() const {
  const internal::Scene& scene = SceneAccess::Engine(*this).scene();
  std::vector<CameraInfo> cameras;
  for (uint32_t i = 0; i < scene.cameras.size(); ++i) cameras.push_back(internal::CameraInfoOf(scene.cameras[i], i));
  return cameras;
}

std::vector<LightInfo> Scene::Lights() const {
  const internal::Scene& scene = SceneAccess::Engine(*this).scene();
  std::vector<LightInfo> lights;
  for (uint32_t i = 0; i < scene.lights.size(); ++i) lights.push_back(internal::LightInfoOf(scene.lights[i], i));
  return lights;
}

std::vector<NodeInfo> Scene::Nodes() const {
  std::vector<NodeInfo> nodes;
  for (const internal::NodeSummary& n : SceneAccess::Engine(*this).Asset().Nodes())
    nodes.push_back(internal::NodeInfoOf(n, uint32_t(nodes.size())));
  return nodes;
}

std::vector<MeshInfo> Scene::Meshes() const {
  std::vector<MeshInfo> meshes;
  for (const internal::MeshSummary& m : SceneAccess::Engine(*this).Asset().Meshes()) {
    MeshInfo info{uint32_t(meshes.size()), m.name, {}};
    for (const auto& [material, triangles] : m.primitives) info.primitives.push_back({material, triangles});
    meshes.push_back(std::move(info));
  }
  return meshes;
}

std::vector<AnimationInfo> Scene::Animations() const {
  const internal::Scene& scene = SceneAccess::Engine(*this).scene();
  std::vector<AnimationInfo> animations;
  for (uint32_t i = 0; i < scene.animations.size(); ++i)
    animations.push_back({i, scene.animations[i].name, scene.animations[i].duration});
  return animations;
}

std::vector<std::string> Scene::Variants() const { return SceneAccess::Engine(*this).scene().materialVariants; }

SceneStats Scene::Stats() const { return internal::StatsOf(SceneAccess::Engine(*this)); }

}  // namespace vkpt
