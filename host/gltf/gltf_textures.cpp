#include "gltf/gltf_textures.h"

#include <cmath>
#include <map>
#include <utility>

#include "gltf/gltf_texture_images.h"

namespace vkpt::internal {
namespace {

// A material's use of a texture: which of its textures, and whether its RGB is colour (sRGB).
struct Slot {
  MaterialTexture Material::*texture;
  const char* field;
  bool srgb;
};
const Slot kBaseColor{&Material::baseColorTexture, "pbrMetallicRoughness.baseColorTexture", true};
const Slot kMetallicRoughness{&Material::metallicRoughnessTexture, "pbrMetallicRoughness.metallicRoughnessTexture",
                              false};
const Slot kEmissive{&Material::emissiveTexture, "emissiveTexture", true};
const Slot kNormal{&Material::normalTexture, "normalTexture", false};
// The material extensions' textures vkpt applies, and where each is read from.
struct ExtensionSlot {
  Slot slot;
  const char* extension;
  const char* field;
};
const ExtensionSlot kExtensionSlots[] = {
    {{&Material::transmissionTexture, "extensions.KHR_materials_transmission.transmissionTexture", false},
     "KHR_materials_transmission",
     "transmissionTexture"},
    {{&Material::specularTexture, "extensions.KHR_materials_specular.specularTexture", false},
     "KHR_materials_specular",
     "specularTexture"},
    {{&Material::specularColorTexture, "extensions.KHR_materials_specular.specularColorTexture", true},
     "KHR_materials_specular",
     "specularColorTexture"},
    {{&Material::clearcoatTexture, "extensions.KHR_materials_clearcoat.clearcoatTexture", false},
     "KHR_materials_clearcoat",
     "clearcoatTexture"},
    {{&Material::clearcoatRoughnessTexture, "extensions.KHR_materials_clearcoat.clearcoatRoughnessTexture", false},
     "KHR_materials_clearcoat",
     "clearcoatRoughnessTexture"},
    {{&Material::clearcoatNormalTexture, "extensions.KHR_materials_clearcoat.clearcoatNormalTexture", false},
     "KHR_materials_clearcoat",
     "clearcoatNormalTexture"},
    {{&Material::sheenColorTexture, "extensions.KHR_materials_sheen.sheenColorTexture", true},
     "KHR_materials_sheen",
     "sheenColorTexture"},
    {{&Material::sheenRoughnessTexture, "extensions.KHR_materials_sheen.sheenRoughnessTexture", false},
     "KHR_materials_sheen",
     "sheenRoughnessTexture"},
    {{&Material::diffuseTransmissionTexture, "extensions.KHR_materials_diffuse_transmission.diffuseTransmissionTexture",
      false},
     "KHR_materials_diffuse_transmission",
     "diffuseTransmissionTexture"},
    {{&Material::diffuseTransmissionColorTexture,
      "extensions.KHR_materials_diffuse_transmission.diffuseTransmissionColorTexture", true},
     "KHR_materials_diffuse_transmission",
     "diffuseTransmissionColorTexture"},
    {{&Material::iridescenceTexture, "extensions.KHR_materials_iridescence.iridescenceTexture", false},
     "KHR_materials_iridescence",
     "iridescenceTexture"},
    {{&Material::iridescenceThicknessTexture, "extensions.KHR_materials_iridescence.iridescenceThicknessTexture",
      false},
     "KHR_materials_iridescence",
     "iridescenceThicknessTexture"},
    {{&Material::anisotropyTexture, "extensions.KHR_materials_anisotropy.anisotropyTexture", false},
     "KHR_materials_anisotropy",
     "anisotropyTexture"},
};

using Wrap = TextureSampler::Wrap;
using Mip = TextureSampler::Mip;

Wrap WrapMode(int gl, const std::string& what, const GltfSource& src) {
  switch (gl) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return Wrap::kRepeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::kClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::kMirroredRepeat;
    default: src.Fail(what + " is " + std::to_string(gl) + ", not a glTF wrap mode");
  }
}

// A sampler's modes. Without a sampler, or a filter, glTF leaves the choice to the
// renderer: TextureSampler's defaults.
TextureSampler ReadSampler(const GltfSource& src, int sampler) {
  TextureSampler out;
  if (sampler < 0) return out;
  const tinygltf::Sampler& s = src.m.samplers[sampler];
  const std::string name = "samplers[" + std::to_string(sampler) + "]";
  out.wrapS = WrapMode(s.wrapS, name + ".wrapS", src);
  out.wrapT = WrapMode(s.wrapT, name + ".wrapT", src);
  if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.magLinear = false;
  else if (s.magFilter != -1 && s.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
    src.Fail(name + ".magFilter is " + std::to_string(s.magFilter) + ", not NEAREST (9728) or LINEAR (9729)");
  auto minify = [&](bool linear, Mip mip) {
    out.minLinear = linear;
    out.mip = mip;
    return out;
  };
  switch (s.minFilter) {
    case -1:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: return minify(true, Mip::kLinear);
    case TINYGLTF_TEXTURE_FILTER_NEAREST: return minify(false, Mip::kNone);
    case TINYGLTF_TEXTURE_FILTER_LINEAR: return minify(true, Mip::kNone);
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: return minify(false, Mip::kNearest);
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: return minify(true, Mip::kNearest);
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: return minify(false, Mip::kLinear);
    default: src.Fail(name + ".minFilter is " + std::to_string(s.minFilter) + ", not a glTF minification filter");
  }
}

// The image textures[t] draws from: its EXT_texture_webp source, else its own `source`
// (for a KHR_texture_basisu texture, the fallback: vkpt decodes no KTX2); −1: none.
int TextureSource(const GltfSource& src, int t) {
  const tinygltf::Texture& tex = src.m.textures[t];
  const auto webp = tex.extensions.find("EXT_texture_webp");
  if (webp == tex.extensions.end()) return tex.source;
  const std::string what = "textures[" + std::to_string(t) + "].extensions.EXT_texture_webp.source";
  if (!webp->second.IsObject() || !webp->second.Has("source") || !webp->second.Get("source").IsInt())
    src.Fail(what + " is missing or not an image index");
  const int image = webp->second.Get("source").Get<int>();
  src.CheckIndex(image, src.m.images, what);
  return image;
}

class TextureReader {
 public:
  TextureReader(const GltfSource& src, Scene& scene) : src_(src), scene_(scene) {}

  // Slot `slot` of materials[m] from `info` (a textureInfo; index −1: none).
  void Read(uint32_t m, const Slot& slot, const tinygltf::TextureInfo& info) {
    if (info.index < 0) return;
    const std::string what = MaterialName(m) + "." + slot.field;
    const std::string texture = "textures[" + std::to_string(info.index) + "]";
    if (TextureSource(src_, info.index) < 0) {
      if (src_.m.textures[info.index].extensions.count("KHR_texture_basisu"))
        src_.Fail(what + ": " + texture +
                  " has only a KHR_texture_basisu (KTX2) image, which vkpt cannot decode (Debian packages no KTX2 or "
                  "Basis Universal decoder), and no PNG, JPEG or WebP source to fall back on");
      scene_.warnings.push_back(what + ": " + texture + " has no image; the factor is used alone");
      return;
    }
    MaterialTexture ref = Transform(info, what);
    if (ref.texCoord > 1) {
      scene_.warnings.push_back(what + " reads TEXCOORD_" + std::to_string(ref.texCoord) +
                                "; vkpt reads TEXCOORD_0 and TEXCOORD_1, so the factor is used alone");
      return;
    }
    ref.texture = TextureIndex(info.index, slot.srgb, what);
    scene_.materials[m].*slot.texture = ref;
  }

  // The textureInfo `field` of materials[m]'s extension `extension` (index −1: none).
  tinygltf::TextureInfo ExtensionTexture(uint32_t m, const char* extension, const char* field) const {
    tinygltf::TextureInfo info;
    const tinygltf::ExtensionMap& exts = src_.m.materials[m].extensions;
    auto ext = exts.find(extension);
    if (ext == exts.end() || !ext->second.IsObject() || !ext->second.Has(field)) return info;
    const tinygltf::Value& v = ext->second.Get(field);
    const std::string what = MaterialName(m) + ".extensions." + extension + "." + field;
    if (!v.IsObject()) src_.Fail(what + " is not an object");
    if (!v.Has("index") || !v.Get("index").IsInt()) src_.Fail(what + ".index is missing or not an integer");
    info.index = v.Get("index").GetNumberAsInt();
    src_.CheckIndex(info.index, src_.m.textures, what + ".index");
    if (v.Has("texCoord")) {
      const tinygltf::Value& tc = v.Get("texCoord");
      if (!tc.IsInt() || tc.GetNumberAsInt() < 0) src_.Fail(what + ".texCoord is not a non-negative integer");
      info.texCoord = tc.GetNumberAsInt();
    }
    if (v.Has("extensions")) {
      const tinygltf::Value& e = v.Get("extensions");
      if (!e.IsObject()) src_.Fail(what + ".extensions is not an object");
      for (const std::string& key : e.Keys()) info.extensions[key] = e.Get(key);
    }
    return info;
  }

  // The images the textures use, in glTF order, each with the first place that uses it.
  const std::map<int, std::string>& Users() const { return users_; }

 private:
  std::string MaterialName(uint32_t m) const {
    std::string name = "materials[" + std::to_string(m) + "]";
    const std::string& own = src_.m.materials[m].name;
    return own.empty() ? name : name + " \"" + own + "\"";
  }

  // KHR_texture_transform (offset, rotation, scale, texCoord) as the 2×3 matrix
  // T · R · S of the extension's specification, R turning the UVs by `rotation`
  // counter-clockwise as seen with v pointing down (the image's rows), the direction
  // TextureTransformTest checks; the identity without it.
  MaterialTexture Transform(const tinygltf::TextureInfo& info, const std::string& what) const {
    MaterialTexture ref;
    ref.texCoord = uint32_t(std::max(info.texCoord, 0));
    auto ext = info.extensions.find("KHR_texture_transform");
    if (ext == info.extensions.end()) return ref;
    const tinygltf::Value& t = ext->second;
    const std::string name = what + ".extensions.KHR_texture_transform";
    double offset[2] = {0.0, 0.0}, scale[2] = {1.0, 1.0};
    Pair(t, "offset", name, offset);
    Pair(t, "scale", name, scale);
    const double rotation = t.Has("rotation") ? Number(t.Get("rotation"), name + ".rotation") : 0.0;
    if (t.Has("texCoord")) {
      const tinygltf::Value& tc = t.Get("texCoord");
      if (!tc.IsInt() || tc.GetNumberAsInt() < 0) src_.Fail(name + ".texCoord is not a non-negative integer");
      ref.texCoord = uint32_t(tc.GetNumberAsInt());
    }
    const double c = std::cos(rotation), s = std::sin(rotation);
    ref.transformU = glm::vec3(float(c * scale[0]), float(s * scale[1]), float(offset[0]));
    ref.transformV = glm::vec3(float(-s * scale[0]), float(c * scale[1]), float(offset[1]));
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(ref.transformU[i]) || !std::isfinite(ref.transformV[i]))
        src_.Fail(name + " makes a transform that is not finite in single precision");
    return ref;
  }

  double Number(const tinygltf::Value& v, const std::string& what) const {
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) src_.Fail(what + " is not a finite number");
    return v.GetNumberAsDouble();
  }

  void Pair(const tinygltf::Value& t, const char* field, const std::string& name, double out[2]) const {
    if (!t.Has(field)) return;
    const tinygltf::Value& v = t.Get(field);
    const std::string what = name + "." + field;
    if (!v.IsArray() || v.ArrayLen() != 2) src_.Fail(what + " is not an array of two numbers");
    for (int i = 0; i < 2; ++i) out[i] = Number(v.Get(i), what + "[" + std::to_string(i) + "]");
  }

  uint32_t TextureIndex(int gltfTexture, bool srgb, const std::string& what) {
    auto [it, added] = textures_.try_emplace({gltfTexture, srgb}, uint32_t(scene_.textures.size()));
    if (added) {
      const tinygltf::Texture& tex = src_.m.textures[gltfTexture];
      const int image = TextureSource(src_, gltfTexture);
      scene_.textures.push_back({uint32_t(image), ReadSampler(src_, tex.sampler), srgb});
      users_.try_emplace(image, what);
    }
    return it->second;
  }

  const GltfSource& src_;
  Scene& scene_;
  std::map<std::pair<int, bool>, uint32_t> textures_;  // (glTF texture, sRGB) → Scene::textures
  std::map<int, std::string> users_;                   // glTF image → the first textureInfo using it
};

// Every texture slot of materials[m], and its normal texture's scale.
void ReadMaterialTextures(const GltfSource& src, uint32_t m, TextureReader& reader, Scene& scene) {
  const tinygltf::Material& mat = src.m.materials[m];
  reader.Read(m, kBaseColor, mat.pbrMetallicRoughness.baseColorTexture);
  reader.Read(m, kMetallicRoughness, mat.pbrMetallicRoughness.metallicRoughnessTexture);
  reader.Read(m, kEmissive, mat.emissiveTexture);
  tinygltf::TextureInfo normal;  // a normalTextureInfo is a textureInfo with a scale
  normal.index = mat.normalTexture.index;
  normal.texCoord = mat.normalTexture.texCoord;
  normal.extensions = mat.normalTexture.extensions;
  reader.Read(m, kNormal, normal);
  const double scale = mat.normalTexture.scale;
  if (!std::isfinite(scale) || std::abs(scale) > 1e6)
    src.Fail("materials[" + std::to_string(m) + "].normalTexture.scale is not a finite number of at most 1e6");
  scene.materials[m].normalScale = float(scale);
  for (const ExtensionSlot& e : kExtensionSlots)
    reader.Read(m, e.slot, reader.ExtensionTexture(m, e.extension, e.field));
}

}  // namespace

bool IsAppliedExtensionTexture(const std::string& extension, const std::string& field) {
  for (const ExtensionSlot& e : kExtensionSlots)
    if (extension == e.extension && field == e.field) return true;
  return false;
}

bool UsesTangents(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (m.normalTexture.Present() || m.clearcoatNormalTexture.Present() || m.anisotropyStrength > 0.0f) return true;
  return false;
}

void LoadTextures(const GltfSource& src, const LoadLimits& limits, MemoryBudget& budget, Scene& scene) {
  TextureReader reader(src, scene);
  for (uint32_t m = 0; m < src.m.materials.size(); ++m) ReadMaterialTextures(src, m, reader, scene);
  if (scene.textures.empty()) return;
  LoadTextureImages(src, reader.Users(), limits, budget, scene);
}

}  // namespace vkpt::internal
