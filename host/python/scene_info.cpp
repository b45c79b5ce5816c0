// vkpt.MaterialInfo, CameraInfo, LightInfo, NodeInfo, MeshInfo, PrimitiveInfo,
// AnimationInfo, SceneStats and BvhInfo: the
// read-only records of include/vkpt/scene_info.h, their vectors as tuples.
#include <string>
#include <tuple>

#include <pybind11/stl.h>

#include "python/bindings.h"

namespace vkpt::python {
namespace {

template <class T>
T Py(const T& value) {
  return value;
}
// Typed tuples, so that pybind11's signatures (and the stubs made from them) name them.
std::tuple<float, float, float> Py(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }
std::tuple<float, float, float, float> Py(const std::array<float, 4>& v) { return {v[0], v[1], v[2], v[3]}; }

// "vkpt.Kind(index=i, name='name')"
template <class Record>
std::string Repr(const char* kind, const Record& r) {
  return std::string("vkpt.") + kind + "(index=" + std::to_string(r.index) +
         ", name=" + std::string(py::repr(py::str(r.name))) + ")";
}

void BindMaterial(py::module_& m) {
  py::class_<MaterialTextureInfo>(m, "MaterialTextureInfo", "A material's use of one of the file's textures.")
      .def_readonly("texture", &MaterialTextureInfo::texture, "the file's texture (glTF textures[i])")
      .def_readonly("tex_coord", &MaterialTextureInfo::texCoord, "the TEXCOORD set it is read at")
      .def("__repr__", [](const MaterialTextureInfo& t) {
        return "vkpt.MaterialTextureInfo(texture=" + std::to_string(t.texture) +
               ", tex_coord=" + std::to_string(t.texCoord) + ")";
      });
  py::class_<MaterialInfo> material(m, "MaterialInfo", R"(A material's factors as the renderer reads them (glTF's
defaults where the file is silent); Scene.materials lists them, vkpt's default last.)");
  material.def_readonly("index", &MaterialInfo::index, "the glTF material's (the last: vkpt's default material)")
      .def_readonly("name", &MaterialInfo::name, "the file's name, or \"materials[i]\" where it gives none");
#define VKPT_BIND_FACTOR(type, member, python, lo, hi, doc) \
  material.def_property_readonly(                           \
      python, [](const MaterialInfo& i) { return Py(i.member); }, doc);
  VKPT_MATERIAL_FACTORS(VKPT_BIND_FACTOR)
#undef VKPT_BIND_FACTOR
  material.def_readonly("alpha_mode", &MaterialInfo::alphaMode, "\"OPAQUE\", \"MASK\" or \"BLEND\"")
      .def_readonly("textures", &MaterialInfo::textures,
                    "slot name (\"baseColor\", \"normal\", …) → MaterialTextureInfo")
      .def("__repr__", [](const MaterialInfo& i) { return Repr("MaterialInfo", i); });
}

void BindCameraAndLight(py::module_& m) {
  py::class_<CameraInfo>(m, "CameraInfo", "One of the file's cameras, in world space (Scene.cameras).")
      .def_readonly("index", &CameraInfo::index, "among the file's cameras, in scene-graph order (Camera(index))")
      .def_readonly("name", &CameraInfo::name, "the camera's or its node's name")
      .def_property_readonly(
          "position", [](const CameraInfo& c) { return Py(c.position); }, "world space")
      .def_property_readonly(
          "forward", [](const CameraInfo& c) { return Py(c.forward); }, "unit")
      .def_property_readonly(
          "up", [](const CameraInfo& c) { return Py(c.up); }, "unit")
      .def_readonly("orthographic", &CameraInfo::orthographic, "an orthographic camera (else perspective)")
      .def_readonly("yfov_degrees", &CameraInfo::yfovDegrees, "perspective: the vertical field of view")
      .def_readonly("ymag", &CameraInfo::ymag, "orthographic: half the view height")
      .def_readonly("aspect_ratio", &CameraInfo::aspectRatio, "width / height from the file; 0 when absent")
      .def("__repr__", [](const CameraInfo& c) { return Repr("CameraInfo", c); });
  py::class_<LightInfo>(m, "LightInfo", "A KHR_lights_punctual light as placed in the scene (Scene.lights).")
      .def_readonly("index", &LightInfo::index, "among the placed lights, in scene-graph order")
      .def_readonly("light", &LightInfo::light,
                    "the file's KHR_lights_punctual lights[light]: parameters \"lights/<light>/...\" edit it")
      .def_readonly("name", &LightInfo::name, "the light's or its node's name")
      .def_readonly("type", &LightInfo::type, "\"point\", \"spot\" or \"directional\"")
      .def_property_readonly(
          "color", [](const LightInfo& l) { return Py(l.color); }, "linear, in [0, 1]")
      .def_readonly("intensity", &LightInfo::intensity, "candela (point, spot) or lux (directional)")
      .def_property_readonly(
          "position", [](const LightInfo& l) { return Py(l.position); }, "world space (not for a directional light)")
      .def_property_readonly(
          "direction", [](const LightInfo& l) { return Py(l.direction); }, "unit, the way the light travels")
      .def_readonly("range", &LightInfo::range, "0: unbounded")
      .def_readonly("inner_cone_degrees", &LightInfo::innerConeDegrees,
                    "spot: full intensity within this angle of the direction")
      .def_readonly("outer_cone_degrees", &LightInfo::outerConeDegrees, "spot: no light beyond this angle")
      .def("__repr__", [](const LightInfo& l) { return Repr("LightInfo", l); });
  py::class_<AnimationInfo>(m, "AnimationInfo", "One of the file's animations (Scene.animations).")
      .def_readonly("index", &AnimationInfo::index, "the file's animation index (Scene(animation=...))")
      .def_readonly("name", &AnimationInfo::name, "\"\" where the file gives none")
      .def_readonly("duration", &AnimationInfo::duration, "seconds")
      .def("__repr__", [](const AnimationInfo& a) { return Repr("AnimationInfo", a); });
}

void BindNodeAndMesh(py::module_& m) {
  py::class_<NodeInfo>(m, "NodeInfo", R"(A node of the file (glTF nodes[index], Scene.nodes): what it places and
its local transform, which the parameters "nodes/<index>/translation", ".../rotation" and
".../scale" edit.)")
      .def_readonly("index", &NodeInfo::index, "the file's node index: parameters \"nodes/<index>/...\"")
      .def_readonly("name", &NodeInfo::name, "\"\" where the file gives none")
      .def_readonly("mesh", &NodeInfo::mesh, "the file's mesh it places, or None")
      .def_readonly("camera", &NodeInfo::camera, "the file's camera it places, or None")
      .def_readonly("light", &NodeInfo::light, "the KHR_lights_punctual light it places, or None")
      .def_readonly("children", &NodeInfo::children, "its children's indices")
      .def_property_readonly(
          "translation", [](const NodeInfo& n) { return Py(n.translation); }, "local, as the file places the node")
      .def_property_readonly(
          "rotation", [](const NodeInfo& n) { return Py(n.rotation); }, "a unit quaternion (x, y, z, w)")
      .def_property_readonly(
          "scale", [](const NodeInfo& n) { return Py(n.scale); }, "local")
      .def_readonly("matrix", &NodeInfo::matrix, R"(placed by a matrix: translation, rotation and scale are its
decomposition (without shear), and editing one replaces the matrix by all three)")
      .def("__repr__", [](const NodeInfo& n) { return Repr("NodeInfo", n); });
  py::class_<PrimitiveInfo>(m, "PrimitiveInfo", "A triangle primitive of a mesh.")
      .def_readonly("material", &PrimitiveInfo::material, "its material, in the variant chosen")
      .def_readonly("triangles", &PrimitiveInfo::triangles, "as decoded (one per three indices)");
  py::class_<MeshInfo>(m, "MeshInfo", "A mesh of the file (glTF meshes[index], Scene.meshes).")
      .def_readonly("index", &MeshInfo::index, "the file's mesh index")
      .def_readonly("name", &MeshInfo::name, "\"\" where the file gives none")
      .def_property_readonly(
          "primitives", [](const MeshInfo& mesh) { return py::tuple(py::cast(mesh.primitives)); },
          "its triangle primitives (vkpt.PrimitiveInfo); points and lines are left out")
      .def("__repr__", [](const MeshInfo& mesh) { return Repr("MeshInfo", mesh); });
}

void BindStats(py::module_& m) {
  py::class_<BvhInfo>(m, "BvhInfo", "The BVH of the scene as last built.")
      .def_readonly("splits", &BvhInfo::splits, "\"object\" or \"spatial\"")
      .def_readonly("nodes", &BvhInfo::nodes, "nodes of the tree")
      .def_readonly("leaves", &BvhInfo::leaves, "leaves of the tree")
      .def_readonly("depth", &BvhInfo::depth, "its deepest leaf's depth")
      .def_readonly("references", &BvhInfo::references, "triangle references in the leaves")
      .def_readonly("sah_cost", &BvhInfo::sahCost, "the surface area heuristic's cost of the tree")
      .def_readonly("build_ms", &BvhInfo::buildMs, "its build time, milliseconds");
  py::class_<SceneStats>(m, "SceneStats", R"(The counts of a scene as loaded, and (lights, degenerate
triangles, bvh, texture bytes) as last built for a render, zero before the first.)")
      .def_readonly("path", &SceneStats::path, "the file loaded")
      .def_readonly("content_hash", &SceneStats::contentHash, "FNV-1a of the file and what it references")
      .def_readonly("triangles", &SceneStats::triangles, "as loaded and posed")
      .def_readonly("degenerate_triangles", &SceneStats::degenerateTriangles, "of zero area, left out of the BVH")
      .def_readonly("lights", &SceneStats::lights, "emissive triangles and punctual lights sampled")
      .def_readonly("materials", &SceneStats::materials, "the file's, and vkpt's default material")
      .def_readonly("textures", &SceneStats::textures, "glTF textures read (by texture and colour space)")
      .def_readonly("images", &SceneStats::images, "images decoded")
      .def_readonly("texels", &SceneStats::texels, "of the images at full size")
      .def_readonly("texture_bytes", &SceneStats::textureBytes, "every texture with its mip levels, as rendered")
      .def_property_readonly(
          "bounds", [](const SceneStats& s) { return py::make_tuple(Py(s.boundsMin), Py(s.boundsMax)); },
          "(min, max) corners")
      .def_readonly("memory_counted", &SceneStats::memoryCounted, "bytes")
      .def_readonly("memory_limit", &SceneStats::memoryLimit, "bytes")
      .def_readonly("variant", &SceneStats::variant, "the variant rendered, or None")
      .def_readonly("animation", &SceneStats::animation, "the animation posing the scene, or None")
      .def_readonly("animation_time", &SceneStats::animationTime, "the pose last built, seconds")
      .def_readonly("warnings", &SceneStats::warnings, "what a user should know about the load (each also logged)")
      .def_readonly("ignored_features", &SceneStats::ignoredFeatures, "what the file uses that vkpt does not render")
      .def_readonly("bvh", &SceneStats::bvh, "the BVH as last built (vkpt.BvhInfo)");
}

}  // namespace

void BindSceneInfo(py::module_& m) {
  BindMaterial(m);
  BindCameraAndLight(m);
  BindNodeAndMesh(m);
  BindStats(m);
}

}  // namespace vkpt::python
