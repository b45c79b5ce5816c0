// The labels of the id AOVs (image/aov_layer.h): which glTF node, material and mesh instance
// a scene triangle came from, and what each id names.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace vkpt::internal {

// −1 where there is nothing to name: no triangle (the ray left the scene), or a scene made
// in code, whose triangles came from no node.
struct TriangleIds {
  int64_t object = -1;    // the glTF node whose mesh the triangle is part of
  int64_t material = -1;  // Scene::materials index: the glTF material, the default one last
  int64_t instance = -1;  // Scene::meshInstances index
};

// The ids of scene triangle `triangle`; all −1 for an index past the triangles (the
// shader's kInvalidIndex where nothing was hit).
TriangleIds IdsOfTriangle(const Scene& scene, uint32_t triangle);

// How many ids of each kind a scene has: ids run from 0 to one less.
struct IdCounts {
  uint64_t objects = 0, materials = 0, instances = 0;
};
IdCounts IdCountsOf(const Scene& scene);

// Float32 holds every integer up to this one exactly: the largest id an id AOV stores.
constexpr int64_t kLargestExactId = int64_t(1) << 24;

// Throws Error naming `file` if an id would be beyond kLargestExactId: checked when a
// render with an id AOV is prepared, so that no render is refused after it has run.
void CheckIdsAreExact(const IdCounts& counts, const std::string& file);

// What the ids name, as a JSON object:
//   {"none": -1,
//    "object_id": [{"id": node, "name": node name, "mesh": mesh name}, …],  nodes with a mesh
//    "material_id": [{"id": material, "name": material name}, …],           every material
//    "instance_id": [{"id": instance, "object_id": node, "placement": k}, …]}
// "placement" numbers an EXT_mesh_gpu_instancing node's instances (0 for other nodes).
std::string IdsJson(const Scene& scene);

}  // namespace vkpt::internal
