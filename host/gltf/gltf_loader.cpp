#include "gltf/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <stdexcept>

#include "gltf/asset_access.h"
#include "gltf/external_uris.h"
#include "gltf/geometry_budget.h"
#include "gltf/gltf_accessors.h"
#include "gltf/gltf_animation.h"
#include "gltf/gltf_asset_parts.h"
#include "gltf/gltf_draco.h"
#include "gltf/gltf_instancing.h"
#include "gltf/gltf_lights.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_meshopt.h"
#include "gltf/gltf_schema.h"
#include "gltf/gltf_source.h"
#include "gltf/gltf_textures.h"
#include "gltf/gltf_validate.h"
#include "gltf/gltf_variants.h"
#include "gltf/scene_file.h"
#include "gltf/tinygltf_edits.h"
#include "util/byte_size.h"
#include "util/content_hash.h"
#include "util/error.h"

namespace vkpt::internal {

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

// tinygltf's messages may quote a whole data URI: keep the first line's start.
std::string Shorten(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  std::replace(s.begin(), s.end(), '\n', ';');
  if (s.size() > 240) s = s.substr(0, 200) + "… (" + std::to_string(s.size()) + " characters)";
  return s;
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
    if (ext == "KHR_texture_basisu")
      ig.push_back("extension " + ext + ": KTX2 images are not decoded; each texture's fallback image is used");
    else if (!IsSupportedExtension(ext)) ig.push_back("extension " + ext);
}

// The phases of reading a file, in the order that makes each safe: the structure is
// checked before any data it points to is read, the memory counted before anything is
// decoded. What posing needs is kept in `parts`.
void BuildScene(const GltfSource& src, const LoadLimits& limits, const SceneChoice& choice, MemoryBudget& budget,
                GltfAsset::Parts& parts) {
  Scene& scene = parts.scene;
  CheckAsset(src);
  DecodeMeshoptViews(src.path, parts.model, budget);
  CheckBufferViews(src);
  DecodeDracoPrimitives(src.path, parts.model, budget);
  for (size_t i = 0; i < src.m.accessors.size(); ++i) CheckAccessor(src, int(i));
  CheckTexturesAndMaterials(src);
  const uint32_t defaultMaterial = LoadMaterials(src, scene);
  LoadTextures(src, limits, budget, scene);
  parts.textured = HasMaterialTextures(scene);
  const bool tangents = UsesTangents(scene);
  parts.parents = CheckNodeGraph(src);
  const uint64_t before = budget.Used();
  ChargeGeometry(src, MeshInstances(src, SceneRoots(src, parts.parents)), parts.textured, tangents, budget);
  parts.geometryBytes = budget.Used() - before;
  scene.materialVariants = ReadVariants(src);
  scene.variant = ResolveVariant(src, scene.materialVariants, choice.variant);
  // Texture coordinates are decoded where tangents are generated from them, kept where
  // textures read them.
  parts.decoding = {defaultMaterial, parts.textured || tangents,    tangents,
                    scene.variant,   scene.materialVariants.size(), !src.m.skins.empty()};
  parts.meshes.resize(src.m.meshes.size());
  for (size_t i = 0; i < src.m.meshes.size(); ++i) parts.meshes[i] = DecodeMeshOf(src, parts, i, scene.warnings);
  scene.generatedTangentPrimitives = GeneratedTangentPrimitives(parts.meshes);
  CheckCameras(src);
  CheckLights(src);
  parts.rest = RestPoses(src);
  parts.skins = ReadSkins(src);
  scene.animations = ListAnimations(src);
  scene.animation = ResolveAnimation(src, scene.animations, choice.animation);
  if (scene.animation >= 0) parts.animationBytes = ChargeAnimation(src, scene.animation, budget);
  NoteIgnoredFeatures(src, scene);
}

// The JSON is parsed and checked, and the files it names are listed, before tinygltf
// opens any of them; the parse tree is freed before tinygltf builds its own. A file
// tinygltf would refuse for its compression gets its JSON edited (`edits`).
std::vector<ExternalUri> CheckJson(const std::string& path, SceneFile& file, TinyGltfEdits& edits) {
  const std::string_view json = file.json;
  if (json.size() >= 3 && std::memcmp(json.data(), "\xEF\xBB\xBF", 3) == 0)
    throw Error(path + ": the JSON starts with a UTF-8 byte-order mark, which glTF forbids");
  nlohmann::json doc = ParseGltfJson(path, json);
  CheckGltfSchema(path, doc);
  std::vector<ExternalUri> uris = ListExternalUris(doc);
  edits = EditForTinyGltf(doc);
  if (!edits.Empty()) ReplaceJson(file, doc.dump());
  return uris;
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
    ok = file.binary
             ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes, unsigned(file.bytes.size()), access.BaseDir())
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

// Its base's normal texture's set, else its coat's, else its anisotropy texture's, else 0
// for an anisotropic material.
int TangentUVSet(const Material& mat) {
  for (TextureSlot s : {TextureSlot::kNormal, TextureSlot::kClearcoatNormal, TextureSlot::kAnisotropy})
    if (mat.texture(s).Present()) return int(mat.texture(s).texCoord);
  return mat.anisotropyStrength > 0.0f ? 0 : -1;
}

std::vector<DecodedPrimitive> DecodeMeshOf(const GltfSource& src, const GltfAsset::Parts& parts, size_t mesh,
                                           std::vector<std::string>& warnings) {
  std::vector<DecodedPrimitive> decoded = DecodeMesh(src, int(mesh), parts.decoding, warnings);
  if (parts.decoding.withTangents)
    for (DecodedPrimitive& prim : decoded) {
      const int uvSet = TangentUVSet(parts.scene.materials[prim.material]);
      if (uvSet >= 0) GenerateMissingTangents(prim, uint32_t(uvSet));
    }
  return decoded;
}

uint32_t GeneratedTangentPrimitives(const std::vector<std::vector<DecodedPrimitive>>& meshes) {
  uint32_t n = 0;
  for (const std::vector<DecodedPrimitive>& mesh : meshes)
    for (const DecodedPrimitive& prim : mesh) n += prim.generatedTangentSet >= 0 ? 1 : 0;
  return n;
}

GltfAsset::GltfAsset(const std::string& path, const LoadLimits& limits, const SceneChoice& choice)
    : parts_(std::make_unique<Parts>()) {
  MemoryBudget budget(limits.maxMemory ? limits.maxMemory : DefaultMaxMemory(), path);
  try {
    SceneFile file = ReadSceneFile(path, budget);
    ContentHash hash;
    hash.Add({reinterpret_cast<const unsigned char*>(file.bytes.data()), file.bytes.size()});
    TinyGltfEdits edits;
    AssetAccess access(path, CheckJson(path, file, edits), limits, budget);
    Scene& scene = parts_->scene;
    scene.path = path;
    parts_->model = ParseWithTinyGltf(path, file, access, scene.warnings);
    UndoTinyGltfEdits(edits, parts_->model);
    for (const tinygltf::Buffer& b : parts_->model.buffers) hash.Add(b.data);
    scene.contentHash = hash.Value();
    file = SceneFile{};
    for (const std::string& skipped : access.SkippedImages()) scene.warnings.push_back(skipped);
    BuildScene(GltfSource{path, parts_->model}, limits, choice, budget, *parts_);
    scene.memoryLimit = budget.Limit();
    scene.memoryCounted = budget.Used();
    parts_->readWarnings = scene.warnings.size();
  } catch (const std::bad_alloc&) {
    throw Error(path + ": ran out of memory while loading, within --max-memory " + FormatBytes(budget.Limit()) +
                " (the process may have a lower limit, e.g. ulimit -v)");
  }
}

GltfAsset::~GltfAsset() = default;

void GltfAsset::Kept(const char* what) const {
  if (parts_->released) throw std::logic_error(std::string("GltfAsset::") + what + " after ReleaseSource");
}

void GltfAsset::PoseAt(double time) {
  Kept("PoseAt");
  Scene& scene = parts_->scene;
  const GltfSource src{scene.path, parts_->model};
  try {
    scene.triangles.clear();
    scene.normals.clear();
    scene.colors.clear();
    scene.uvs.clear();
    scene.tangents.clear();
    scene.cameras.clear();
    scene.lights.clear();
    scene.meshInstances.clear();
    scene.triangleRuns.clear();
    scene.bounds = Bounds3f{};
    scene.warnings.resize(parts_->readWarnings);
    ScenePose pose{parts_->rest, {}, parts_->skins};
    if (scene.animation >= 0) PoseAtTime(src, scene.animation, time, pose.nodes);
    pose.world = WorldTransforms(parts_->parents, pose.nodes);
    scene.animationTime = time;
    InstantiateScene(src, parts_->parents, pose, parts_->meshes, scene);
  } catch (const std::bad_alloc&) {
    throw Error(scene.path + ": ran out of memory while posing, within --max-memory " + FormatBytes(scene.memoryLimit) +
                " (the process may have a lower limit, e.g. ulimit -v)");
  }
  if (scene.triangles.empty()) src.Fail("the scene contains no triangles to render");
}

void GltfAsset::ReleaseSource() {
  Parts& p = *parts_;
  p.model = tinygltf::Model{};
  p.meshes = {};
  p.rest = {};
  p.skins = {};
  p.parents = {};
  p.released = true;
}

const Scene& GltfAsset::scene() const { return parts_->scene; }

Scene GltfAsset::TakeScene() { return std::move(parts_->scene); }

Scene LoadGltf(const std::string& path, const LoadLimits& limits, const SceneChoice& choice) {
  GltfAsset asset(path, limits, choice);
  asset.PoseAt(choice.time);
  return asset.TakeScene();
}

}  // namespace vkpt::internal
