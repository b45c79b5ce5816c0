#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "scene/asset_access.h"
#include "scene/external_uris.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_instancing.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_meshes.h"
#include "scene/gltf_schema.h"
#include "scene/gltf_source.h"
#include "scene/gltf_textures.h"
#include "scene/gltf_validate.h"
#include "scene/gltf_variants.h"
#include "scene/scene_file.h"
#include "util/byte_size.h"
#include "util/content_hash.h"
#include "util/error.h"

namespace vkpt {
namespace {

// tinygltf would decode every image with its own stb_image, used or not, before vkpt
// could check a header. vkpt keeps the bytes of images read from a uri and decodes what
// the materials use later (gltf_textures.cpp). An image in a bufferView is read from
// there once the bufferView is checked: tinygltf passes its bytes unchecked.
bool KeepImageEncoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0 && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// Host memory per triangle of the instanced scene, from the loader's arrays through the
// BVH builds (both trees with --splits auto) to the renderer's arrays and their device
// copies: up to ~490 bytes measured on 1 M triangles with vertex normals
// (docs/design-notes.md), with a margin.
constexpr uint64_t kBytesPerTriangle = 560;
// And per triangle with COLOR_0: the Scene's VertexColors (48 bytes), the packed
// TriangleColors (32) and their staging and device copies (32 each).
constexpr uint64_t kBytesPerColoredTriangle = 144;
// And per triangle with textures: the Scene's VertexUVs (48 bytes), the packed TriangleUVs
// (48) and their staging and device copies (48 each).
constexpr uint64_t kBytesPerTexturedTriangle = 192;
// And per triangle with normal maps: the Scene's VertexTangents (48 bytes), the packed
// TriangleTangents (16) and their staging and device copies (16 each), and generated
// tangents' corners (48, and 48 more while an instance transforms them).
constexpr uint64_t kBytesPerTangentTriangle = 192;
// Decoding an accessor holds each component as a double, then as a float.
constexpr uint64_t kBytesPerDecodedComponent = 12;
// Posing a primitive copies its attributes (morphed; up to ~100 bytes a vertex with
// every attribute and skin weights) and holds a skinned vertex's transform (208 bytes)
// and its posed attributes (~44 bytes): per byte of POSITION decoded (36 a vertex).
constexpr uint64_t kPosingBytesPerDecodedPosition = 10;

uint64_t SaturatingMul(uint64_t a, uint64_t b) { return b && a > UINT64_MAX / b ? UINT64_MAX : a * b; }

// tinygltf's messages may quote a whole data URI: keep the first line's start.
std::string Shorten(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  std::replace(s.begin(), s.end(), '\n', ';');
  if (s.size() > 240) s = s.substr(0, 200) + "… (" + std::to_string(s.size()) + " characters)";
  return s;
}

uint64_t DecodedBytes(const GltfSource& src, int accessor) {
  if (accessor < 0 || size_t(accessor) >= src.m.accessors.size()) return 0;
  const tinygltf::Accessor& a = src.m.accessors[accessor];
  return SaturatingMul(a.count, uint64_t(ComponentCount(a.type)) * kBytesPerDecodedComponent);
}

// The memory the meshes will take, counted before any is decoded: each primitive's
// positions, normals, colours and indices, and every triangle of every instance through to the
// renderer.
// `textured`, `tangents`: the scene keeps the texture coordinates, the tangents of
// every triangle.
void ChargeGeometry(const GltfSource& src, const std::vector<uint64_t>& instances, bool textured, bool tangents,
                    MemoryBudget& budget) {
  uint64_t largestPosing = 0;
  for (size_t i = 0; i < src.m.meshes.size(); ++i) {
    uint64_t decoded = 0, triangles = 0, colored = 0, posing = 0;
    for (const tinygltf::Primitive& prim : src.m.meshes[i].primitives) {
      decoded += DecodedBytes(src, prim.indices);
      for (const char* attr : {"POSITION", "NORMAL", "COLOR_0", "TEXCOORD_0", "TEXCOORD_1", "TANGENT", "JOINTS_0",
                               "JOINTS_1", "WEIGHTS_0", "WEIGHTS_1"})
        if (auto it = prim.attributes.find(attr); it != prim.attributes.end()) decoded += DecodedBytes(src, it->second);
      for (const auto& target : prim.targets)
        for (const auto& [attr, accessor] : target) decoded += DecodedBytes(src, accessor);
      // A morphed or skinned instance is posed from a copy, one primitive at a time.
      const bool deformed = !prim.targets.empty() || prim.attributes.count("JOINTS_0");
      if (auto it = prim.attributes.find("POSITION"); deformed && it != prim.attributes.end() && instances[i])
        posing = std::max(posing, SaturatingMul(DecodedBytes(src, it->second), kPosingBytesPerDecodedPosition));
      triangles += TriangleCount(src, prim);
      if (prim.attributes.count("COLOR_0")) colored += TriangleCount(src, prim);
    }
    std::string name = "meshes[" + std::to_string(i) + "]";
    budget.Charge(decoded, name + " (decoding its accessors)");
    if (posing > largestPosing) {
      budget.Charge(posing - largestPosing, name + " (posing an instance)");
      largestPosing = posing;
    }
    uint64_t total = SaturatingMul(triangles, instances[i]);
    budget.Charge(SaturatingMul(total, kBytesPerTriangle), name + " (" + std::to_string(triangles) + " triangles × " +
                                                               std::to_string(instances[i]) +
                                                               " instances = " + std::to_string(total) + " triangles)");
    if (colored)
      budget.Charge(SaturatingMul(SaturatingMul(colored, instances[i]), kBytesPerColoredTriangle),
                    name + " (vertex colours of " + std::to_string(colored) + " triangles × " +
                        std::to_string(instances[i]) + " instances)");
    if (textured)
      budget.Charge(SaturatingMul(total, kBytesPerTexturedTriangle),
                    name + " (texture coordinates of " + std::to_string(total) + " triangles)");
    if (tangents)
      budget.Charge(SaturatingMul(total, kBytesPerTangentTriangle),
                    name + " (tangents of " + std::to_string(total) + " triangles)");
  }
}

// The TEXCOORD set a material's tangents follow: its base's normal texture's, else its
// coat's, else its anisotropy texture's, else 0 for an anisotropic material; −1: it needs
// none.
int TangentUVSet(const Material& mat) {
  for (const MaterialTexture* t : {&mat.normalTexture, &mat.clearcoatNormalTexture, &mat.anisotropyTexture})
    if (t->Present()) return int(t->texCoord);
  return mat.anisotropyStrength > 0.0f ? 0 : -1;
}

// Extensions whose every property vkpt renders.
bool IsRenderedExtension(const std::string& ext) {
  static const char* const kRendered[] = {"KHR_materials_anisotropy",
                                          "KHR_materials_clearcoat",
                                          "KHR_materials_diffuse_transmission",
                                          "KHR_materials_dispersion",
                                          "KHR_materials_iridescence",
                                          "KHR_materials_sheen",
                                          "KHR_materials_variants",
                                          "KHR_materials_emissive_strength",
                                          "KHR_materials_ior",
                                          "KHR_materials_specular",
                                          "KHR_materials_transmission",
                                          "KHR_materials_volume",
                                          "KHR_materials_unlit",
                                          "KHR_lights_punctual",
                                          "KHR_mesh_quantization",
                                          "KHR_texture_transform"};
  return std::find(std::begin(kRendered), std::end(kRendered), ext) != std::end(kRendered);
}

// What the file uses that vkpt does not render yet (printed by -v).
void NoteIgnoredFeatures(const GltfSource& src, Scene& scene) {
  auto& ig = scene.ignoredFeatures;
  bool occlusionTex = false;
  std::set<std::string> extensionTextures;
  for (const tinygltf::Material& mat : src.m.materials) {
    occlusionTex |= mat.occlusionTexture.index >= 0;
    for (const auto& [name, ext] : mat.extensions)
      if (ext.IsObject())
        for (const std::string& key : ext.Keys())
          if (key.ends_with("Texture") && !IsAppliedExtensionTexture(name, key))
            extensionTextures.insert(name + "." + key);
  }
  if (occlusionTex) ig.push_back("occlusion textures: not applied (a path tracer computes occlusion)");
  // A rasterizer's stand-in for the distance light travels inside; paths trace it.
  const std::string thickness = "KHR_materials_volume.thicknessTexture";
  for (const std::string& t : extensionTextures)
    ig.push_back(t + (t == thickness ? ": not applied (a path tracer measures the thickness along each ray)"
                                     : ": the factor is used alone"));
  std::set<std::string> morphedOthers;
  for (const auto& mesh : src.m.meshes)
    for (const auto& p : mesh.primitives)
      for (const auto& target : p.targets)
        for (const auto& [attr, accessor] : target)
          if (attr != "POSITION" && attr != "NORMAL" && attr != "TANGENT") morphedOthers.insert(attr);
  for (const std::string& attr : morphedOthers) ig.push_back("morph targets of " + attr + ": the base values are used");
  for (const std::string& ext : src.m.extensionsUsed)
    if (!IsRenderedExtension(ext)) ig.push_back("extension " + ext);
}

// The nodes' pose: as the file places them, or at `choice`'s time of its animation.
ScenePose Pose(const GltfSource& src, const std::vector<int>& parents, const SceneChoice& choice, MemoryBudget& budget,
               Scene& scene) {
  ScenePose pose{RestPoses(src), {}, ReadSkins(src)};
  scene.animations = ListAnimations(src);
  scene.animation = ResolveAnimation(src, scene.animations, choice.animation);
  scene.animationTime = choice.time;
  if (scene.animation >= 0) {
    budget.Charge(AnimationBytes(src, scene.animation),
                  "animations[" + std::to_string(scene.animation) + "] (decoding its keyframes)");
    PoseAtTime(src, scene.animation, choice.time, pose.nodes);
  }
  pose.world = WorldTransforms(parents, pose.nodes);
  return pose;
}

// The phases of a load, in the order that makes each safe: the structure is checked
// before any data it points to is read, the memory counted before anything is decoded.
void BuildScene(const GltfSource& src, const LoadLimits& limits, const SceneChoice& choice, Scene& scene,
                MemoryBudget& budget) {
  CheckAsset(src);
  CheckBufferViews(src);
  for (size_t i = 0; i < src.m.accessors.size(); ++i) CheckAccessor(src, int(i));
  CheckTexturesAndMaterials(src);
  const uint32_t defaultMaterial = LoadMaterials(src, scene);
  LoadTextures(src, limits, budget, scene);
  const bool textured = HasMaterialTextures(scene), tangents = UsesTangents(scene);
  const std::vector<int> parents = CheckNodeGraph(src);
  ChargeGeometry(src, MeshInstances(src, SceneRoots(src, parents)), textured, tangents, budget);
  scene.materialVariants = ReadVariants(src);
  scene.variant = ResolveVariant(src, scene.materialVariants, choice.variant);
  // Texture coordinates are decoded where tangents are generated from them, kept where
  // textures read them.
  const MeshDecoding decoding{defaultMaterial, textured || tangents,          tangents,
                              scene.variant,   scene.materialVariants.size(), !src.m.skins.empty()};
  std::vector<std::vector<DecodedPrimitive>> meshes(src.m.meshes.size());
  for (size_t i = 0; i < src.m.meshes.size(); ++i) meshes[i] = DecodeMesh(src, int(i), decoding, scene.warnings);
  for (std::vector<DecodedPrimitive>& mesh : meshes)
    for (DecodedPrimitive& prim : mesh) {
      if (!tangents) break;
      const int uvSet = TangentUVSet(scene.materials[prim.material]);
      if (uvSet >= 0 && GenerateMissingTangents(prim, uint32_t(uvSet))) ++scene.generatedTangentPrimitives;
    }
  CheckCameras(src);
  CheckLights(src);
  InstantiateScene(src, parents, Pose(src, parents, choice, budget, scene), meshes, scene);
  if (scene.triangles.empty()) src.Fail("the scene contains no triangles to render");
  NoteIgnoredFeatures(src, scene);
}

// The JSON is parsed and checked, and the files it names are listed, before tinygltf
// opens any of them; the parse tree is freed before tinygltf builds its own.
std::vector<ExternalUri> CheckJson(const std::string& path, std::string_view json) {
  if (json.size() >= 3 && std::memcmp(json.data(), "\xEF\xBB\xBF", 3) == 0)
    throw Error(path + ": the JSON starts with a UTF-8 byte-order mark, which glTF forbids");
  nlohmann::json doc = ParseGltfJson(path, json);
  CheckGltfSchema(path, doc);
  return ListExternalUris(doc);
}

tinygltf::Model ParseWithTinyGltf(const std::string& path, const SceneFile& file, AssetAccess& access,
                                  std::vector<std::string>& warnings) {
  tinygltf::TinyGLTF gltf;
  access.Install(gltf);
  gltf.SetImageLoader(KeepImageEncoded, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  // tinygltf reports most problems through `err`, but some malformed input makes it
  // throw (nlohmann-json exceptions, std::bad_alloc): contain them all.
  try {
    const auto* bytes = reinterpret_cast<const unsigned char*>(file.bytes.data());
    ok = file.binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes, unsigned(file.bytes.size()), access.BaseDir())
                     : gltf.LoadASCIIFromString(&model, &err, &warn, file.bytes.data(), unsigned(file.bytes.size()),
                                                access.BaseDir());
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path + ": malformed glTF (" + Shorten(e.what()) + ")");
  }
  access.ThrowIfRefused();  // its message names the uri and the rule; tinygltf's would not
  if (!ok) throw Error(path + ": " + (err.empty() ? std::string("malformed glTF") : Shorten(err)));
  if (!warn.empty()) warnings.push_back("tinygltf: " + Shorten(warn));
  return model;
}

}  // namespace

Scene LoadGltf(const std::string& path, const LoadLimits& limits, const SceneChoice& choice) {
  MemoryBudget budget(limits.maxMemory ? limits.maxMemory : DefaultMaxMemory(), path);
  try {
    SceneFile file = ReadSceneFile(path, budget);
    AssetAccess access(path, CheckJson(path, file.json), limits, budget);
    Scene scene;
    scene.path = path;
    tinygltf::Model model = ParseWithTinyGltf(path, file, access, scene.warnings);
    ContentHash hash;
    hash.Add({reinterpret_cast<const unsigned char*>(file.bytes.data()), file.bytes.size()});
    for (const tinygltf::Buffer& b : model.buffers) hash.Add(b.data);
    scene.contentHash = hash.Value();
    file = SceneFile{};
    for (const std::string& skipped : access.SkippedImages()) scene.warnings.push_back(skipped);
    BuildScene(GltfSource{path, model}, limits, choice, scene, budget);
    scene.memoryLimit = budget.Limit();
    scene.memoryCounted = budget.Used();
    return scene;
  } catch (const std::bad_alloc&) {
    throw Error(path + ": ran out of memory while loading, within --max-memory " + FormatBytes(budget.Limit()) +
                " (the process may have a lower limit, e.g. ulimit -v)");
  }
}

}  // namespace vkpt
