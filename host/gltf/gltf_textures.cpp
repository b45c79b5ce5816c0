#include "gltf/gltf_textures.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "gltf/gltf_texture_images.h"

namespace vkpt::internal {
namespace {

// The textureInfo of a core texture slot of `mat` (TextureSlotInfo::path); tinygltf parses
// these, and the extensions' (TextureReader::ExtensionTexture) are read from their JSON.
tinygltf::TextureInfo CoreTexture(const tinygltf::Material& mat, const std::string& path) {
  if (path == "pbrMetallicRoughness.baseColorTexture") return mat.pbrMetallicRoughness.baseColorTexture;
  if (path == "pbrMetallicRoughness.metallicRoughnessTexture") return mat.pbrMetallicRoughness.metallicRoughnessTexture;
  if (path == "emissiveTexture") return mat.emissiveTexture;
  if (path != "normalTexture")
    throw std::logic_error("gpu_records.def names a core texture the loader does not read: " + path);
  tinygltf::TextureInfo normal;  // a normalTextureInfo is a textureInfo with a scale
  normal.index = mat.normalTexture.index;
  normal.texCoord = mat.normalTexture.texCoord;
  normal.extensions = mat.normalTexture.extensions;
  return normal;
}

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
  void Read(uint32_t m, uint32_t slot, const tinygltf::TextureInfo& info) {
    if (info.index < 0) return;
    const TextureSlotInfo& s = kTextureSlotInfo[slot];
    const std::string what = MaterialName(m) + "." + s.path;
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
    ref.texture = TextureIndex(info.index, s.srgb, what);
    scene_.materials[m].textures[slot] = ref;
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
      scene_.textures.push_back({uint32_t(image), ReadSampler(src_, tex.sampler), srgb, uint32_t(gltfTexture)});
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
  for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
    const TextureSlotInfo& s = kTextureSlotInfo[slot];
    reader.Read(m, slot, s.extension ? reader.ExtensionTexture(m, s.extension, s.field) : CoreTexture(mat, s.path));
  }
  const double scale = mat.normalTexture.scale;
  if (!std::isfinite(scale) || std::abs(scale) > 1e6)
    src.Fail("materials[" + std::to_string(m) + "].normalTexture.scale is not a finite number of at most 1e6");
  scene.materials[m].normalScale = float(scale);
}

}  // namespace

bool IsAppliedExtensionTexture(const std::string& extension, const std::string& field) {
  for (const TextureSlotInfo& s : kTextureSlotInfo)
    if (s.extension && extension == s.extension && field == s.field) return true;
  return false;
}

bool UsesTangents(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (m.texture(TextureSlot::kNormal).Present() || m.texture(TextureSlot::kClearcoatNormal).Present() ||
        m.anisotropyStrength > 0.0f)
      return true;
  return false;
}

void LoadTextures(const GltfSource& src, const LoadLimits& limits, MemoryBudget& budget, Scene& scene) {
  TextureReader reader(src, scene);
  for (uint32_t m = 0; m < src.m.materials.size(); ++m) ReadMaterialTextures(src, m, reader, scene);
  if (scene.textures.empty()) return;
  LoadTextureImages(src, reader.Users(), limits, budget, scene);
}

}  // namespace vkpt::internal
