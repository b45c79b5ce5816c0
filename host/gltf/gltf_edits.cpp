// What a GltfAsset tells of its file's nodes, meshes and lights, and the edits
// vkpt::Scene::Update makes to them and to its materials, variant and animation: each
// written into the parsed file (or the decoded scene), checked by the rules that check a
// file as it is loaded, the meshes it decodes differently decoded again, and the scene
// posed again.
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/matrix_decompose.hpp>
#include <stdexcept>

#include "gltf/geometry_budget.h"
#include "gltf/gltf_animation.h"
#include "gltf/gltf_asset_parts.h"
#include "gltf/gltf_instancing.h"
#include "gltf/gltf_lights.h"
#include "gltf/gltf_source.h"
#include "gltf/gltf_textures.h"
#include "gltf/gltf_variants.h"
#include "util/byte_size.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

// A node's translation, rotation and scale: its own, or its matrix's decomposition.
struct Trs {
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};
};

Trs TrsOf(const NodePose& pose) {
  if (!pose.matrix) return {pose.translation, pose.rotation, pose.scale};
  Trs t;
  glm::dvec3 skew;
  glm::dvec4 perspective;
  glm::decompose(*pose.matrix, t.scale, t.rotation, t.translation, skew, perspective);
  return t;
}

// The node edited as the file would hold it: a node placed by a matrix is given all three.
void Apply(const NodeEdit& edit, const NodePose& pose, tinygltf::Node& node) {
  const Trs now = TrsOf(pose);
  const bool all = pose.matrix.has_value();
  node.matrix.clear();
  if (all || edit.translation) {
    const glm::dvec3 t = edit.translation.value_or(now.translation);
    node.translation = {t.x, t.y, t.z};
  }
  if (all || edit.rotation) {
    const glm::dquat q = edit.rotation.value_or(now.rotation);
    node.rotation = {q.x, q.y, q.z, q.w};
  }
  if (all || edit.scale) {
    const glm::dvec3 s = edit.scale.value_or(now.scale);
    node.scale = {s.x, s.y, s.z};
  }
}

void Apply(const LightEdit& edit, tinygltf::Light& light) {
  if (edit.color) light.color = {edit.color->x, edit.color->y, edit.color->z};
  if (edit.intensity) light.intensity = *edit.intensity;
}

}  // namespace

std::vector<NodeSummary> GltfAsset::Nodes() const {
  Kept("Nodes");
  const GltfSource src{parts_->scene.path, parts_->model};
  std::vector<NodeSummary> nodes;
  for (size_t i = 0; i < src.m.nodes.size(); ++i) {
    const tinygltf::Node& n = src.m.nodes[i];
    const Trs trs = TrsOf(parts_->rest[i]);
    NodeSummary s{n.name,
                  n.mesh,
                  n.camera,
                  NodeLight(src, int(i)),
                  {},
                  trs.translation,
                  trs.rotation,
                  trs.scale,
                  parts_->rest[i].matrix.has_value()};
    s.children.assign(n.children.begin(), n.children.end());
    nodes.push_back(std::move(s));
  }
  return nodes;
}

std::vector<MeshSummary> GltfAsset::Meshes() const {
  Kept("Meshes");
  std::vector<MeshSummary> meshes;
  for (size_t i = 0; i < parts_->meshes.size(); ++i) {
    MeshSummary s{parts_->model.meshes[i].name, {}};
    for (const DecodedPrimitive& p : parts_->meshes[i]) s.primitives.emplace_back(p.material, p.indices.size() / 3);
    meshes.push_back(std::move(s));
  }
  return meshes;
}

std::vector<LightSource> GltfAsset::Lights() const {
  Kept("Lights");
  std::vector<LightSource> lights;
  for (const tinygltf::Light& l : parts_->model.lights)
    lights.push_back({l.color.empty() ? glm::dvec3(1.0) : glm::dvec3(l.color[0], l.color[1], l.color[2]), l.intensity});
  return lights;
}

namespace {

// What an edit may change of a GltfAsset, as it was: restored where the edit is refused.
struct Undo {
  std::map<uint32_t, tinygltf::Node> nodes;
  std::map<uint32_t, tinygltf::Light> lights;
  std::vector<NodePose> rest;
  std::vector<Material> materials;
  int variant, animation;
  double posedAt;
  MeshDecoding decoding;
  uint64_t geometryBytes, animationBytes, memoryCounted;
  std::map<size_t, std::vector<DecodedPrimitive>> meshes;  // those decoded again

  explicit Undo(const GltfAsset::Parts& p)
      : rest(p.rest),
        materials(p.scene.materials),
        variant(p.scene.variant),
        animation(p.scene.animation),
        posedAt(p.scene.animationTime),
        decoding(p.decoding),
        geometryBytes(p.geometryBytes),
        animationBytes(p.animationBytes),
        memoryCounted(p.scene.memoryCounted) {}

  void Restore(GltfAsset::Parts& p) {
    for (auto& [i, node] : nodes) p.model.nodes[i] = std::move(node);
    for (auto& [i, light] : lights) p.model.lights[i] = std::move(light);
    p.rest = std::move(rest);
    p.scene.materials = std::move(materials);
    p.scene.variant = variant;
    p.scene.animation = animation;
    p.decoding = decoding;
    p.geometryBytes = geometryBytes;
    p.animationBytes = animationBytes;
    p.scene.memoryCounted = memoryCounted;
    for (auto& [i, mesh] : meshes) p.meshes[i] = std::move(mesh);
    p.scene.generatedTangentPrimitives = GeneratedTangentPrimitives(p.meshes);
  }
};

// The memory of the scene counted again for its tangents (p.decoding) and its animation,
// against its limit; the rest as counted when it loaded.
void Recount(const GltfSource& src, GltfAsset::Parts& p, bool tangentsChanged) {
  Scene& scene = p.scene;
  MemoryBudget budget(scene.memoryLimit, scene.path);
  budget.Charge(scene.memoryCounted - p.geometryBytes - p.animationBytes, "the file, its images and materials");
  if (tangentsChanged) {
    const uint64_t before = budget.Used();
    ChargeGeometry(src, MeshInstances(src, SceneRoots(src, p.parents)), p.textured, p.decoding.withTangents, budget);
    p.geometryBytes = budget.Used() - before;
  } else {
    budget.Charge(p.geometryBytes, "the meshes");
  }
  p.animationBytes = scene.animation >= 0 ? ChargeAnimation(src, scene.animation, budget) : 0;
  scene.memoryCounted = budget.Used();
}

// Whether meshes[i] decodes differently now: every mesh when the tangents are wanted or
// not, one with variant mappings when the variant changed, one whose primitive's material
// wants tangents from another TEXCOORD set.
bool DecodesAnew(const GltfAsset::Parts& p, const Undo& was, size_t i) {
  if (p.decoding.withTangents != was.decoding.withTangents) return true;
  if (p.scene.variant != was.variant)
    for (const tinygltf::Primitive& prim : p.model.meshes[i].primitives)
      if (prim.extensions.count("KHR_materials_variants")) return true;
  for (const DecodedPrimitive& prim : p.meshes[i])
    if (TangentUVSet(p.scene.materials[prim.material]) != TangentUVSet(was.materials[prim.material])) return true;
  return false;
}

}  // namespace

bool GltfAsset::Edit(const AssetEdits& edits, double time) {
  Kept("Edit");
  Parts& p = *parts_;
  Scene& scene = p.scene;
  const GltfSource src{scene.path, p.model};
  Undo undo(p);
  bool posing = false;
  const auto restore = [&] {
    undo.Restore(p);
    if (posing) PoseAt(undo.posedAt);
  };
  try {
    for (const auto& [i, edit] : edits.nodes) {
      undo.nodes.emplace(i, p.model.nodes.at(i));
      Apply(edit, p.rest[i], p.model.nodes[i]);
    }
    for (const auto& [i, edit] : edits.lights) {
      undo.lights.emplace(i, p.model.lights.at(i));
      Apply(edit, p.model.lights[i]);
    }
    for (const auto& [i, material] : edits.materials) scene.materials.at(i) = material;
    if (edits.variant) scene.variant = ResolveVariant(src, scene.materialVariants, *edits.variant);
    if (edits.animation) scene.animation = ResolveAnimation(src, scene.animations, *edits.animation);
    p.decoding.variant = scene.variant;
    p.decoding.withTangents = UsesTangents(scene);
    p.decoding.withUVs = p.textured || p.decoding.withTangents;
    const bool tangentsChanged = p.decoding.withTangents != undo.decoding.withTangents;
    const bool animationChanged = scene.animation != undo.animation;
    if (tangentsChanged || animationChanged) Recount(src, p, tangentsChanged);
    for (size_t i = 0; i < p.meshes.size(); ++i) {
      if (!DecodesAnew(p, undo, i)) continue;
      std::vector<std::string> warnings;  // those of the first decoding again
      std::vector<DecodedPrimitive> mesh = DecodeMeshOf(src, p, i, warnings);
      undo.meshes.emplace(i, std::move(p.meshes[i]));
      p.meshes[i] = std::move(mesh);
    }
    scene.generatedTangentPrimitives = GeneratedTangentPrimitives(p.meshes);
    if (!edits.lights.empty()) CheckLights(src);
    if (!edits.nodes.empty()) p.rest = RestPoses(src);
    const bool moved = !edits.nodes.empty() || !undo.meshes.empty() || animationChanged;
    if (moved || !edits.lights.empty()) {
      posing = true;
      PoseAt(time);
    }
    return moved;
  } catch (const Error&) {
    restore();
    throw;
  } catch (const std::bad_alloc&) {
    restore();
    throw Error(scene.path + ": ran out of memory while editing, within --max-memory " +
                FormatBytes(scene.memoryLimit) + " (the process may have a lower limit, e.g. ulimit -v)");
  }
}

}  // namespace vkpt::internal
