// What a GltfAsset tells of its file's nodes, meshes and lights, and the edits
// vkpt::Scene::Update makes to them: each written into the parsed file, checked by the
// rules that check a file as it is loaded, and the scene posed again.
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/matrix_decompose.hpp>
#include <stdexcept>

#include "gltf/gltf_asset_parts.h"
#include "gltf/gltf_lights.h"
#include "gltf/gltf_source.h"

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

void GltfAsset::Edit(const AssetEdits& edits, double time) {
  Kept("Edit");
  tinygltf::Model& model = parts_->model;
  const GltfSource src{parts_->scene.path, model};
  std::map<uint32_t, tinygltf::Node> nodesBefore;
  std::map<uint32_t, tinygltf::Light> lightsBefore;
  for (const auto& [i, edit] : edits.nodes) {
    nodesBefore.emplace(i, model.nodes.at(i));
    Apply(edit, parts_->rest[i], model.nodes[i]);
  }
  for (const auto& [i, edit] : edits.lights) {
    lightsBefore.emplace(i, model.lights.at(i));
    Apply(edit, model.lights[i]);
  }
  const std::vector<NodePose> restBefore = parts_->rest;
  try {
    CheckLights(src);
    parts_->rest = RestPoses(src);
    PoseAt(time);
  } catch (const Error&) {
    for (auto& [i, node] : nodesBefore) model.nodes[i] = std::move(node);
    for (auto& [i, light] : lightsBefore) model.lights[i] = std::move(light);
    parts_->rest = restBefore;
    PoseAt(time);
    throw;
  }
}

}  // namespace vkpt::internal
