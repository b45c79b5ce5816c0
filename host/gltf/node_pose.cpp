#include "gltf/node_pose.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace vkpt::internal {
namespace {

// Whether the node gives `field` (`size` finite numbers); fails on a wrong count or a
// non-finite number.
bool Given(const GltfSource& src, const std::vector<double>& v, size_t size, const std::string& field) {
  if (v.empty()) return false;
  if (v.size() != size) src.Fail(field + " must have " + std::to_string(size) + " numbers");
  for (double x : v)
    if (!std::isfinite(x)) src.Fail(field + " has a non-finite value");
  return true;
}

// The morph weights a node's mesh renders with (spec §3.7.2.2): the node's, else the
// mesh's, else zeros.
std::vector<double> RestWeights(const GltfSource& src, const tinygltf::Node& n, const std::string& name) {
  if (n.mesh < 0 || size_t(n.mesh) >= src.m.meshes.size()) return {};  // reported by the instancer
  const size_t targets = MorphTargetCount(src, n.mesh);
  const tinygltf::Mesh& mesh = src.m.meshes[n.mesh];
  for (const auto& [weights, what] : {std::pair{&n.weights, name + ".weights"},
                                      std::pair{&mesh.weights, "meshes[" + std::to_string(n.mesh) + "].weights"}}) {
    if (weights->empty()) continue;
    if (weights->size() != targets)
      src.Fail(what + " has " + std::to_string(weights->size()) + " weights, but the mesh has " +
               std::to_string(targets) + " morph targets");
    Given(src, *weights, targets, what);
    return *weights;
  }
  return std::vector<double>(targets, 0.0);
}

}  // namespace

glm::dmat4 NodePose::Local() const {
  if (matrix) return *matrix;
  return glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
}

std::vector<NodePose> RestPoses(const GltfSource& src) {
  std::vector<NodePose> poses(src.m.nodes.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    const tinygltf::Node& n = src.m.nodes[i];
    const std::string name = "nodes[" + std::to_string(i) + "]";
    NodePose& p = poses[i];
    if (Given(src, n.matrix, 16, name + ".matrix")) p.matrix = glm::make_mat4(n.matrix.data());  // column-major
    if (Given(src, n.translation, 3, name + ".translation")) p.translation = glm::make_vec3(n.translation.data());
    if (Given(src, n.rotation, 4, name + ".rotation")) {
      const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // (w, x, y, z)
      const double len = glm::length(q);
      if (len < 1e-6) src.Fail(name + ".rotation is not a unit quaternion");
      p.rotation = q / len;
    }
    if (Given(src, n.scale, 3, name + ".scale")) p.scale = glm::make_vec3(n.scale.data());
    p.weights = RestWeights(src, n, name);
  }
  return poses;
}

std::vector<glm::dmat4> WorldTransforms(const std::vector<int>& parents, const std::vector<NodePose>& poses) {
  // Parents before children: each node is reached from its root, and every node has one
  // (CheckNodeGraph refuses cycles).
  std::vector<std::vector<int>> children(poses.size());
  std::vector<int> work;
  for (size_t i = 0; i < parents.size(); ++i)
    if (parents[i] == -1) work.push_back(int(i));
    else children[parents[i]].push_back(int(i));
  std::vector<glm::dmat4> world(poses.size());
  while (!work.empty()) {
    const int n = work.back();
    work.pop_back();
    world[n] = parents[n] == -1 ? poses[n].Local() : world[parents[n]] * poses[n].Local();
    work.insert(work.end(), children[n].begin(), children[n].end());
  }
  return world;
}

size_t MorphTargetCount(const GltfSource& src, int mesh) {
  const std::vector<tinygltf::Primitive>& prims = src.m.meshes[mesh].primitives;
  const size_t targets = prims.empty() ? 0 : prims[0].targets.size();
  for (size_t p = 1; p < prims.size(); ++p)
    if (prims[p].targets.size() != targets)
      src.Fail("meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(p) + "] has " +
               std::to_string(prims[p].targets.size()) + " morph targets, but primitives[0] has " +
               std::to_string(targets) + " (a mesh's primitives must have the same number)");
  return targets;
}

}  // namespace vkpt::internal
