#include "gltf/posed_primitive.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

namespace vkpt::internal {
namespace {

// One vertex's transform and what follows from it for its attributes.
struct VertexTransform {
  glm::dmat4 m;
  glm::dmat3 normalMatrix;  // normals stay perpendicular to the surface under the inverse transpose
  bool mirrored;            // negative determinant
};

VertexTransform MakeTransform(const glm::dmat4& m) {
  return {m, glm::inverseTranspose(glm::dmat3(m)), glm::determinant(glm::dmat3(m)) < 0.0};
}

// The unit world-space normal, or zero when the transform leaves it no direction.
glm::vec3 WorldNormal(const glm::dmat3& normalMatrix, const glm::vec3& n) {
  const glm::dvec3 w = normalMatrix * glm::dvec3(n);
  const double len = glm::length(w);
  if (!(len > 0.0) || !std::isfinite(len)) return glm::vec3(0.0f);
  return glm::vec3(w / len);
}

// Tangents lie in the surface: they transform as directions, and a mirroring transform
// flips the bitangent (w). Zero where the transform leaves no direction.
glm::vec4 WorldTangent(const VertexTransform& x, const glm::vec4& t) {
  const glm::dvec3 w = glm::dmat3(x.m) * glm::dvec3(t);
  const double len = glm::length(w);
  if (!(len > 0.0) || !std::isfinite(len)) return glm::vec4(0.0f);
  return glm::vec4(glm::vec3(w / len), t.w * (x.mirrored ? -1.0f : 1.0f));
}

// The primitive's attributes moved by `transformOf(v)`, vertex v's VertexTransform.
template <class TransformOf>
PosedPrimitive Pose(const GltfSource& src, const DecodedPrimitive& prim, const std::string& what,
                    const TransformOf& transformOf) {
  PosedPrimitive out;
  out.positions.resize(prim.positions.size());
  for (size_t v = 0; v < prim.positions.size(); ++v) {
    const glm::dvec3 w = glm::dvec3(transformOf(v).m * glm::dvec4(glm::dvec3(prim.positions[v]), 1.0));
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z) ||
        glm::any(glm::greaterThan(glm::abs(w), glm::dvec3(1e30))))
      src.Fail(what + ": transformed position is not finite");
    out.positions[v] = glm::vec3(w);
  }
  out.normals.resize(prim.normals.size());
  for (size_t v = 0; v < prim.normals.size(); ++v)
    out.normals[v] = WorldNormal(transformOf(v).normalMatrix, prim.normals[v]);
  const bool perCorner = !prim.cornerTangents.empty();
  const std::vector<glm::vec4>& tangents = perCorner ? prim.cornerTangents : prim.tangents;
  out.tangents.resize(tangents.size());
  for (size_t k = 0; k < tangents.size(); ++k)
    out.tangents[k] = WorldTangent(transformOf(perCorner ? prim.indices[k] : k), tangents[k]);
  out.mirrored.resize(prim.indices.size() / 3);
  // A triangle whose corners disagree (a skin blending a mirrored joint) follows most of them.
  for (size_t t = 0; t < out.mirrored.size(); ++t)
    out.mirrored[t] = transformOf(prim.indices[3 * t]).mirrored + transformOf(prim.indices[3 * t + 1]).mirrored +
                          transformOf(prim.indices[3 * t + 2]).mirrored >=
                      2;
  return out;
}

}  // namespace

PosedPrimitive PoseRigid(const GltfSource& src, const DecodedPrimitive& prim, const glm::dmat4& world,
                         const std::string& what) {
  const VertexTransform x = MakeTransform(world);
  return Pose(src, prim, what, [&](size_t) -> const VertexTransform& { return x; });
}

PosedPrimitive PoseSkinned(const GltfSource& src, const DecodedPrimitive& prim,
                           const std::vector<glm::dmat4>& jointMatrices, const std::string& what, size_t& unweighted) {
  std::vector<VertexTransform> x(prim.positions.size());
  for (size_t v = 0; v < x.size(); ++v) {
    glm::dmat4 m(0.0);
    double sum = 0.0;
    for (int set = 0; set < 2; ++set) {
      if (prim.joints[set].empty()) continue;
      for (int i = 0; i < 4; ++i) {
        const double w = prim.weights[set][v][i];
        if (w == 0.0) continue;
        const uint16_t joint = prim.joints[set][v][i];
        if (joint >= jointMatrices.size())
          src.Fail(what + ": vertex " + std::to_string(v) + " names joint " + std::to_string(joint) +
                   ", but the skin has " + std::to_string(jointMatrices.size()));
        m += w * jointMatrices[joint];
        sum += w;
      }
    }
    unweighted += sum == 0.0;
    x[v] = MakeTransform(sum > 0.0 ? m / sum : glm::dmat4(1.0));
  }
  return Pose(src, prim, what, [&](size_t v) -> const VertexTransform& { return x[v]; });
}

}  // namespace vkpt::internal
