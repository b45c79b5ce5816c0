// Tangent frames for normal maps when a glTF primitive supplies none: glTF 2.0 §3.7.2.1
// asks clients to compute them with the MikkTSpace algorithm (M. S. Mikkelsen, "Simulation
// of Wrinkled Surfaces Revisited", MSc thesis, University of Copenhagen, 2008; reference
// implementation mikktspace.c, https://github.com/mmikk/MikkTSpace), so that a normal map
// baked against MikkTSpace tangents is decoded in the frame it was baked in.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt::internal {

// MikkTSpace tangents for one triangle-list primitive, one per vertex: xyz unit and
// orthogonal to the vertex normal, w = ±1 with the bitangent w · cross(normal, tangent).
// positions, normals and uvs (the normal texture's texture coordinates) have one entry per
// vertex; indices hold 3 per triangle. The sign follows glTF: texture coordinates grow
// down the image while a normal map's +Y points up it, so the bitangent points along −∂P/∂v
// (tangent_space.cpp). Vertices that no non-degenerate triangle defines get some unit
// tangent orthogonal to their normal and w = 1. Safe on any input: triangles with an index
// past the shorter of the three arrays are ignored, and the output is always finite.
std::vector<glm::vec4> GenerateTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> uvs, std::span<const uint32_t> indices);

// The same per triangle corner (one per index), as the reference outputs them: a corner
// takes the frame of its own triangle's orientation, so where mirrored and unmirrored
// texture coordinates meet at a vertex each side keeps its own frame (GenerateTangents
// gives such a vertex one). Corners of triangles that define no frame take their vertex's.
std::vector<glm::vec4> GenerateCornerTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                              std::span<const glm::vec2> uvs, std::span<const uint32_t> indices);

}  // namespace vkpt::internal
