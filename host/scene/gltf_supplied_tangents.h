// The TANGENT attributes a glTF file supplies, with the attributes MikkTSpace derives
// tangents from: for measuring GenerateTangents (scene/tangent_space.h) against the
// tangents an exporter wrote. Keeps tinygltf out of the callers (tests), which may not
// include it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt {

struct SuppliedTangents {
  std::string name;                  // "meshes[i].primitives[j]"
  std::vector<glm::vec3> positions;  // object space, one per vertex
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;       // the set the material's normalTexture reads (TEXCOORD_0 without one)
  std::vector<uint32_t> indices;    // triangle list
  std::vector<glm::vec4> tangents;  // TANGENT as the file has it
};

// Every triangle primitive of the glTF file at `path` with TANGENT, NORMAL and the uv set
// above, decoded by the loader's own checked readers (scene/gltf_meshes.h). Meant for
// files the caller trusts: the file is read whole, without the loader's LoadLimits.
// Throws vkpt::Error on a file the loader would reject.
std::vector<SuppliedTangents> ReadSuppliedTangents(const std::string& path);

}  // namespace vkpt
