// glTF mesh primitives (spec §3.7.2) as the renderer wants them: object-space positions,
// vertex normals and colours if given, and a triangle list; strips and fans are converted, points
// and lines skipped.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include "gltf/gltf_source.h"

namespace vkpt::internal {

// A morph target's displacements (spec §3.7.2.2), one per vertex; empty for an
// attribute the target leaves alone (or the primitive does not keep).
struct MorphTarget {
  std::vector<glm::vec3> positions, normals, tangents;
};

struct DecodedPrimitive {
  std::vector<glm::vec3> positions;       // object space
  std::vector<glm::vec3> normals;         // object space, one per position; empty without NORMAL
  std::vector<glm::vec4> colors;          // COLOR_0, linear RGBA in [0, 1], one per position; empty without it
  std::vector<glm::vec2> uvs[2];          // TEXCOORD_0 and TEXCOORD_1, one per position; empty without them
  std::vector<glm::vec4> tangents;        // TANGENT (w = ±1), one per position; empty without it
  std::vector<glm::vec4> cornerTangents;  // or generated (MikkTSpace), one per index
  std::vector<uint32_t> indices;          // triangle list, 3 per triangle
  uint32_t material;
  int generatedTangentSet = -1;      // the TEXCOORD set cornerTangents were generated from; −1: none
  std::vector<MorphTarget> targets;  // in the mesh's order
  // JOINTS_0/1 and WEIGHTS_0/1 (read in files with skins), one per position; empty
  // without them.
  std::vector<glm::u16vec4> joints[2];
  std::vector<glm::vec4> weights[2];
};

// What DecodeMesh reads besides the primitives themselves.
struct MeshDecoding {
  uint32_t defaultMaterial = 0;  // for primitives without a material
  bool withUVs = false;          // some material has a texture
  bool withTangents = false;     // some material has a normal map
  int variant = -1;              // KHR_materials_variants' variant to render (−1: none)
  size_t variantCount = 0;       // the file's variants
  bool withSkins = false;        // the file has skins: JOINTS_n and WEIGHTS_n are read
};

// Checks and decodes the triangle primitives of meshes[meshIndex]: positions, normals and
// colours finite, indices in range and no primitive-restart values. Points and lines add a
// warning, and so do colours outside [0, 1] (clamped). Texture coordinates are read only
// when `d.withUVs`, tangents when `d.withTangents`; both must be finite. A primitive takes
// its material in `d.variant` where its variant mappings give one (gltf_variants.h).
std::vector<DecodedPrimitive> DecodeMesh(const GltfSource& src, int meshIndex, const MeshDecoding& d,
                                         std::vector<std::string>& warnings);

// MikkTSpace tangents per corner (scene/tangent_space.h) for a primitive that supplies no
// TANGENT, from its normals — for a flat primitive, the area-weighted face normals around
// each vertex — and texture coordinate set `uvSet`; it keeps none without those coordinates.
// Returns whether it generated them.
bool GenerateMissingTangents(DecodedPrimitive& prim, uint32_t uvSet);

// `prim` with its morph targets applied at `weights` (one per target): displaced
// positions, normals and tangents, and tangents generated anew where they were generated.
DecodedPrimitive Morphed(const DecodedPrimitive& prim, const std::vector<double>& weights);

// Triangles a primitive makes, from its accessors' counts alone (nothing is decoded).
uint64_t TriangleCount(const GltfSource& src, const tinygltf::Primitive& prim);

}  // namespace vkpt::internal
