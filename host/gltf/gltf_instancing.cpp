#include "gltf/gltf_instancing.h"

#include <algorithm>
#include <cmath>

#include "gltf/gltf_gpu_instancing.h"
#include "gltf/gltf_lights.h"
#include "gltf/gltf_textures.h"
#include "gltf/posed_primitive.h"

namespace vkpt::internal {
namespace {

class Instancer {
 public:
  Instancer(const GltfSource& src, const std::vector<int>& parents, const ScenePose& pose,
            const std::vector<std::vector<DecodedPrimitive>>& meshes, Scene& scene)
      : src_(src),
        parents_(parents),
        pose_(pose),
        meshes_(meshes),
        scene_(scene),
        withUVs_(HasMaterialTextures(scene)),
        withTangents_(UsesTangents(scene)) {}

  void Run() {
    for (size_t s = 0; s < src_.m.scenes.size(); ++s)
      for (int n : src_.m.scenes[s].nodes) {
        src_.CheckIndex(n, src_.m.nodes, "scenes[" + std::to_string(s) + "].nodes");
        if (parents_[n] != -1)
          src_.Fail("scenes[" + std::to_string(s) + "] lists nodes[" + std::to_string(n) +
                    "], which is not a root node");
      }
    if (src_.m.defaultScene != -1) src_.CheckIndex(src_.m.defaultScene, src_.m.scenes, "scene");
    if (src_.m.scenes.empty() && std::count(parents_.begin(), parents_.end(), -1) > 0)
      scene_.warnings.push_back("the file defines no scene; rendering all root nodes");
    scene_.nodeNames = Names(src_.m.nodes, "nodes");
    scene_.meshNames = Names(src_.m.meshes, "meshes");
    for (int r : SceneRoots(src_, parents_)) InstantiateTree(r);
    if (unweighted_)
      scene_.warnings.push_back(std::to_string(unweighted_) +
                                " skinned vertices have no weight on any joint and stay in their bind pose");
  }

 private:
  // Each object's name, or "<array>[i]" where it has none.
  template <class T>
  static std::vector<std::string> Names(const std::vector<T>& objects, const std::string& array) {
    std::vector<std::string> names;
    names.reserve(objects.size());
    for (size_t i = 0; i < objects.size(); ++i)
      names.push_back(objects[i].name.empty() ? array + "[" + std::to_string(i) + "]" : objects[i].name);
    return names;
  }

  void AddCamera(int cameraIndex, const glm::dmat4& world, const std::string& nodeName) {
    const tinygltf::Camera& in = src_.m.cameras[cameraIndex];
    Camera cam;
    cam.name = in.name.empty() ? nodeName : in.name;
    cam.position = glm::vec3(world[3]);
    // The camera looks down its local −Z with +Y up; scale in the node is ignored.
    glm::dvec3 fwd = -glm::dvec3(world[2]);
    glm::dvec3 up = glm::dvec3(world[1]);
    if (glm::length(fwd) < 1e-12 || glm::length(up) < 1e-12) src_.Fail(nodeName + ": camera transform is degenerate");
    fwd = glm::normalize(fwd);
    up = glm::normalize(up - fwd * glm::dot(up, fwd));
    cam.forward = glm::vec3(fwd);
    cam.up = glm::vec3(up);
    cam.right = glm::vec3(glm::normalize(glm::cross(fwd, up)));
    if (in.type == "perspective") {
      cam.yfov = float(in.perspective.yfov);
      cam.aspectRatio = float(in.perspective.aspectRatio);
    } else {
      cam.orthographic = true;
      cam.xmag = float(std::abs(in.orthographic.xmag));
      cam.ymag = float(std::abs(in.orthographic.ymag));
      cam.aspectRatio = cam.xmag / cam.ymag;
    }
    scene_.cameras.push_back(cam);
  }

  // Instantiates a root and its subtree, each node once, parents first. Iterative: a
  // hierarchy thousands of levels deep must not overflow the call stack.
  void InstantiateTree(int root) {
    std::vector<int> work{root};
    while (!work.empty()) {
      const int node = work.back();
      work.pop_back();
      InstantiateNode(node);
      const std::vector<int>& children = src_.m.nodes[node].children;
      work.insert(work.end(), children.rbegin(), children.rend());
    }
  }

  // Adds one node's camera, light and mesh.
  void InstantiateNode(int nodeIndex) {
    const tinygltf::Node& n = src_.m.nodes[nodeIndex];
    const std::string name = "nodes[" + std::to_string(nodeIndex) + "]";
    const glm::dmat4& world = pose_.world[nodeIndex];
    if (n.camera != -1) {
      src_.CheckIndex(n.camera, src_.m.cameras, name + ".camera");
      AddCamera(n.camera, world, name);
    }
    if (int light = NodeLight(src_, nodeIndex); light != -1)
      scene_.lights.push_back(PlaceLight(src_, light, world, name));
    if (n.mesh == -1) return;
    src_.CheckIndex(n.mesh, src_.m.meshes, name + ".mesh");
    if (n.skin != -1) src_.CheckIndex(n.skin, pose_.skins, name + ".skin");
    // A skinned mesh moves with its joints alone; its node's transform plays no part.
    const std::vector<glm::dmat4> joints =
        n.skin != -1 ? JointMatrices(pose_.skins[n.skin], pose_.world) : std::vector<glm::dmat4>{};
    const std::vector<double>& weights = pose_.nodes[nodeIndex].weights;
    const bool morphed = std::any_of(weights.begin(), weights.end(), [](double w) { return w != 0.0; });
    const std::string what = name + " (mesh " + std::to_string(n.mesh) + ")";
    // EXT_mesh_gpu_instancing: the mesh once per instance, the instance's transform first.
    std::vector<glm::dmat4> placements = InstanceTransforms(src_, nodeIndex);
    if (!placements.empty() && n.skin != -1) src_.Fail(name + " is skinned and instanced (EXT_mesh_gpu_instancing)");
    if (placements.empty()) placements.push_back(glm::dmat4(1.0));
    const uint32_t firstInstance = uint32_t(scene_.meshInstances.size());
    for (uint32_t k = 0; k < placements.size(); ++k)
      scene_.meshInstances.push_back({uint32_t(nodeIndex), uint32_t(n.mesh), k});
    for (const DecodedPrimitive& base : meshes_[n.mesh]) {
      DecodedPrimitive displaced;
      if (morphed) displaced = Morphed(base, weights);
      const DecodedPrimitive& prim = morphed ? displaced : base;
      if (n.skin != -1 && !prim.joints[0].empty()) {
        AddPrimitive(prim, PoseSkinned(src_, prim, joints, what, unweighted_), firstInstance);
        continue;
      }
      for (uint32_t k = 0; k < placements.size(); ++k)
        AddPrimitive(prim, PoseRigid(src_, prim, world * placements[k], what), firstInstance + k);
    }
  }

  // One primitive of mesh instance `instance`, `posed` in world space: its triangles.
  void AddPrimitive(const DecodedPrimitive& prim, const PosedPrimitive& posed, uint32_t instance) {
    std::vector<TriangleRun>& runs = scene_.triangleRuns;
    if (!prim.indices.empty() && (runs.empty() || runs.back().instance != instance))
      runs.push_back({uint32_t(scene_.triangles.size()), instance});
    const bool perCorner = !prim.cornerTangents.empty();
    const std::vector<glm::vec4>& tw = posed.tangents;
    for (size_t k = 0; k < prim.indices.size(); k += 3) {
      const uint32_t i[3] = {prim.indices[k], prim.indices[k + 1], prim.indices[k + 2]};
      VertexTangents vt;
      if (perCorner) vt = {{tw[k], tw[k + 1], tw[k + 2]}};
      else if (!tw.empty()) vt = {{tw[i[0]], tw[i[1]], tw[i[2]]}};
      AddCorners(prim, i, posed.positions, posed.normals, vt, posed.mirrored[k / 3]);
    }
  }

  // The triangle of corners i[0..2] with its world-space positions p, normals nw and
  // tangents vt, wound back the author's way when mirrored.
  void AddCorners(const DecodedPrimitive& prim, const uint32_t i[3], const std::vector<glm::vec3>& p,
                  const std::vector<glm::vec3>& nw, VertexTangents vt, bool mirrored) {
    SceneTriangle t{p[i[0]], p[i[1]], p[i[2]], prim.material};
    VertexNormals vn;
    if (!nw.empty()) vn = {nw[i[0]], nw[i[1]], nw[i[2]]};
    VertexColors vc;
    const std::vector<glm::vec4>& c = prim.colors;
    if (!c.empty()) vc = {c[i[0]], c[i[1]], c[i[2]]};
    VertexUVs vu;
    for (int set = 0; set < 2; ++set) {
      const std::vector<glm::vec2>& uv = prim.uvs[set];
      glm::vec2* out = set == 0 ? vu.set0 : vu.set1;
      if (!uv.empty()) out[0] = uv[i[0]], out[1] = uv[i[1]], out[2] = uv[i[2]];
    }
    if (mirrored) {
      std::swap(t.v1, t.v2);
      std::swap(vt.t[1], vt.t[2]);
      std::swap(vn.n1, vn.n2);
      std::swap(vc.c1, vc.c2);
      std::swap(vu.set0[1], vu.set0[2]);
      std::swap(vu.set1[1], vu.set1[2]);
    }
    AddTriangle(t, vn, vc, !c.empty(), vu, vt);
  }

  // A triangle with any vertex normal that did not survive its transform is shaded flat:
  // a normal that vanishes or overflows (a singular or extreme scale) has no direction
  // left to interpolate, but the geometry is still fine.
  void AddTriangle(const SceneTriangle& t, VertexNormals vn, const VertexColors& vc, bool hasColors,
                   const VertexUVs& vu, const VertexTangents& vt) {
    const glm::vec3 zero(0.0f);
    if (vn.n0 == zero || vn.n1 == zero || vn.n2 == zero) vn = VertexNormals{};
    AppendParallel(scene_.normals, vn, vn.Present());
    AppendParallel(scene_.colors, vc, hasColors);
    // Every triangle of a textured scene, whether or not its primitive has coordinates.
    AppendParallel(scene_.uvs, vu, withUVs_);
    AppendParallel(scene_.tangents, vt, withTangents_);
    scene_.bounds.Extend(t.v0);
    scene_.bounds.Extend(t.v1);
    scene_.bounds.Extend(t.v2);
    scene_.triangles.push_back(t);
  }

  // Appends a triangle's entry to an array parallel to scene_.triangles that exists once
  // some triangle has the attribute: it starts with the first such triangle, defaults
  // (flat normals, white) filling in for the triangles before it.
  template <class T>
  void AppendParallel(std::vector<T>& array, const T& value, bool present) {
    if (!present && array.empty()) return;
    array.resize(scene_.triangles.size());
    array.push_back(value);
  }

  const GltfSource& src_;
  const std::vector<int>& parents_;
  const ScenePose& pose_;
  const std::vector<std::vector<DecodedPrimitive>>& meshes_;
  Scene& scene_;
  size_t unweighted_ = 0;    // skinned vertices without weights
  const bool withUVs_;       // some material has a texture
  const bool withTangents_;  // some material has a normal texture
};

}  // namespace

std::vector<int> SceneRoots(const GltfSource& src, const std::vector<int>& parents) {
  if (src.m.defaultScene >= 0 && size_t(src.m.defaultScene) < src.m.scenes.size())
    return src.m.scenes[src.m.defaultScene].nodes;
  if (src.m.defaultScene == -1 && !src.m.scenes.empty()) return src.m.scenes[0].nodes;
  if (src.m.defaultScene != -1) return {};
  std::vector<int> roots;
  for (size_t i = 0; i < parents.size(); ++i)
    if (parents[i] == -1) roots.push_back(int(i));
  return roots;
}

std::vector<uint64_t> MeshInstances(const GltfSource& src, const std::vector<int>& roots) {
  std::vector<uint64_t> instances(src.m.meshes.size(), 0);
  std::vector<int> work = roots;
  while (!work.empty()) {
    int n = work.back();
    work.pop_back();
    if (n < 0 || size_t(n) >= src.m.nodes.size()) continue;  // reported by InstantiateScene
    int mesh = src.m.nodes[n].mesh;
    if (mesh >= 0 && size_t(mesh) < src.m.meshes.size()) instances[mesh] += InstanceCount(src, n);
    work.insert(work.end(), src.m.nodes[n].children.begin(), src.m.nodes[n].children.end());
  }
  return instances;
}

void InstantiateScene(const GltfSource& src, const std::vector<int>& parents, const ScenePose& pose,
                      const std::vector<std::vector<DecodedPrimitive>>& meshes, Scene& scene) {
  Instancer(src, parents, pose, meshes, scene).Run();
}

}  // namespace vkpt::internal
