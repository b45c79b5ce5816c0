#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/glb_header.h"
#include "scene/gltf_schema.h"
#include "util/error.h"

namespace vkpt {
namespace {

// Extensions vkpt understands; a file that *requires* any other one is refused, as the
// glTF spec demands of a loader that does not implement it.
const std::set<std::string> kSupportedRequiredExtensions = {
    "KHR_materials_emissive_strength", "KHR_mesh_quantization", "KHR_texture_transform"};

// tinygltf decodes every image with stb_image by default. vkpt does not sample textures
// yet, so it keeps the bytes undecoded: faster, and a corrupt texture cannot stop a render.
bool KeepImageUndecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                        const unsigned char*, int, void*) {
  return true;
}

std::string ReadFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open file: " + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw Error(path + ": read error");
  return ss.str();
}

// tinygltf's own file reading opens whatever a URI resolves to: a URI that
// percent-decodes to a NUL byte ("%!Q...", tinygltf's issue 416) names the scene's folder
// once the path is cut at the NUL, a folder's size reads as 2^63 - 1 on ext4, and
// tinygltf then allocates that much (std::bad_alloc; under AddressSanitizer an abort).
// External buffers and images are read here instead: regular files only, no NUL.
bool RegularFileExists(const std::string& path, void*) {
  std::error_code ec;
  return path.find('\0') == std::string::npos && std::filesystem::is_regular_file(path, ec);
}

bool ReadRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  auto fail = [&](const std::string& what) {
    if (err) *err += what + ": " + path + "\n";
    return false;
  };
  if (!RegularFileExists(path, nullptr)) return fail("not a regular file");
  std::error_code ec;
  std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) return fail("cannot open");
  out->resize(size);
  if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) return fail("cannot read");
  return true;
}

int ComponentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int ComponentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

// Reads and validates a glTF model; every check names the offending object.
class Loader {
 public:
  Loader(std::string path, const tinygltf::Model& model, Scene& scene)
      : path_(std::move(path)), m_(model), scene_(scene) {}

  void Run() {
    CheckAsset();
    CheckBufferViews();
    for (size_t i = 0; i < m_.accessors.size(); ++i) CheckAccessor(int(i));
    CheckTexturesAndMaterials();
    LoadMaterials();
    meshes_.resize(m_.meshes.size());
    for (size_t i = 0; i < m_.meshes.size(); ++i) DecodeMesh(int(i));
    CheckCameras();
    InstantiateScene();
    if (scene_.triangles.empty()) Fail("the scene contains no triangles to render");
    NoteIgnoredFeatures();
  }

 private:
  struct DecodedPrimitive {
    std::vector<glm::vec3> positions;  // object space
    std::vector<uint32_t> indices;     // triangle list, 3 per triangle
    uint32_t material;
  };

  [[noreturn]] void Fail(const std::string& what) const { throw Error(path_ + ": " + what); }

  template <class T>
  void CheckIndex(int index, const std::vector<T>& array, const std::string& what) const {
    if (index < 0 || size_t(index) >= array.size())
      Fail(what + " refers to index " + std::to_string(index) + ", but there are only " +
           std::to_string(array.size()));
  }

  void CheckAsset() {
    const std::string& v = m_.asset.version;
    if (v.empty()) Fail("asset.version is missing");
    if (v.substr(0, v.find('.')) != "2")
      Fail("asset.version is \"" + v + "\"; vkpt reads glTF 2.x only");
    for (const std::string& ext : m_.extensionsRequired)
      if (!kSupportedRequiredExtensions.count(ext))
        Fail("the file requires extension " + ext + ", which vkpt does not support");
    quantized_ = std::count(m_.extensionsUsed.begin(), m_.extensionsUsed.end(),
                            "KHR_mesh_quantization") > 0;
  }

  void CheckBufferViews() {
    for (size_t i = 0; i < m_.bufferViews.size(); ++i) {
      const tinygltf::BufferView& bv = m_.bufferViews[i];
      std::string name = "bufferViews[" + std::to_string(i) + "]";
      CheckIndex(bv.buffer, m_.buffers, name + ".buffer");
      size_t size = m_.buffers[bv.buffer].data.size();
      if (bv.byteLength == 0) Fail(name + ".byteLength is 0");
      if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
        Fail(name + " (offset " + std::to_string(bv.byteOffset) + ", length " +
             std::to_string(bv.byteLength) + ") runs past the end of buffer " +
             std::to_string(bv.buffer) + " (" + std::to_string(size) + " bytes)");
      if (bv.byteStride != 0 && (bv.byteStride < 4 || bv.byteStride > 252 || bv.byteStride % 4))
        Fail(name + ".byteStride is " + std::to_string(bv.byteStride) +
             "; it must be a multiple of 4 in [4, 252]");
    }
  }

  // Checks that a (bufferView, byteOffset) region holds `count` elements of elemSize
  // bytes at stride `stride`.
  void CheckRegion(const std::string& name, int bufferView, size_t byteOffset, size_t count,
                   size_t elemSize, size_t stride) const {
    CheckIndex(bufferView, m_.bufferViews, name + ".bufferView");
    const tinygltf::BufferView& bv = m_.bufferViews[bufferView];
    if (count == 0) return;
    // Computed in a wide type: count comes from the file and may be absurd.
    long double end = (long double)byteOffset + (long double)stride * (count - 1) + elemSize;
    if (end > (long double)bv.byteLength)
      Fail(name + " needs " + std::to_string((unsigned long long)end) + " bytes of bufferViews[" +
           std::to_string(bufferView) + "], which has " + std::to_string(bv.byteLength));
  }

  size_t ElementSize(const tinygltf::Accessor& a) const {
    return size_t(ComponentSize(a.componentType)) * ComponentCount(a.type);
  }

  void CheckAccessor(int index) {
    const tinygltf::Accessor& a = m_.accessors[index];
    std::string name = "accessors[" + std::to_string(index) + "]";
    if (ComponentSize(a.componentType) == 0)
      Fail(name + ".componentType " + std::to_string(a.componentType) + " is not valid");
    if (ComponentCount(a.type) == 0) Fail(name + ".type is not valid");
    if (a.count == 0) Fail(name + ".count is 0");
    // Guards the allocation of an accessor without a bufferView (all zeros, or sparse).
    if (a.count > (size_t(1) << 28)) Fail(name + ".count " + std::to_string(a.count) + " is too large (limit 2^28)");
    size_t elem = ElementSize(a);
    if (a.bufferView >= 0) {
      CheckIndex(a.bufferView, m_.bufferViews, name + ".bufferView");
      const tinygltf::BufferView& bv = m_.bufferViews[a.bufferView];
      size_t stride = bv.byteStride ? bv.byteStride : elem;
      if (stride < elem)
        Fail(name + ": bufferViews[" + std::to_string(a.bufferView) + "].byteStride " +
             std::to_string(stride) + " is smaller than the element size " + std::to_string(elem));
      if (a.byteOffset % ComponentSize(a.componentType))
        Fail(name + ".byteOffset is not a multiple of its component size");
      CheckRegion(name, a.bufferView, a.byteOffset, a.count, elem, stride);
    } else if (a.byteOffset != 0) {
      Fail(name + " has a byteOffset but no bufferView");
    }
    if (a.sparse.isSparse) {
      const auto& s = a.sparse;
      if (s.count <= 0 || size_t(s.count) > a.count)
        Fail(name + ".sparse.count " + std::to_string(s.count) + " is not in [1, " +
             std::to_string(a.count) + "]");
      int isz = ComponentSize(s.indices.componentType);
      if (s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
          s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
          s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        Fail(name + ".sparse.indices.componentType is not an unsigned integer type");
      if (s.indices.byteOffset < 0 || s.values.byteOffset < 0)
        Fail(name + ".sparse has a negative byteOffset");
      CheckRegion(name + ".sparse.indices", s.indices.bufferView, size_t(s.indices.byteOffset),
                  size_t(s.count), size_t(isz), size_t(isz));
      CheckRegion(name + ".sparse.values", s.values.bufferView, size_t(s.values.byteOffset),
                  size_t(s.count), elem, elem);
    }
  }

  // Component `c` of element `i` of a region, converted to double; normalized integers
  // map to [0, 1] or [-1, 1] as the glTF spec defines.
  static double ReadComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        int8_t v; std::memcpy(&v, p, 1);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        uint8_t v; std::memcpy(&v, p, 1);
        return normalized ? v / 255.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v; std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v; std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v; std::memcpy(&v, p, 4);
        return normalized ? v / 4294967295.0 : v;
      }
      default: {
        float v; std::memcpy(&v, p, 4);
        return v;
      }
    }
  }

  const unsigned char* RegionBase(int bufferView, size_t byteOffset) const {
    const tinygltf::BufferView& bv = m_.bufferViews[bufferView];
    return m_.buffers[bv.buffer].data.data() + bv.byteOffset + byteOffset;
  }

  // All components of an (already checked) accessor, sparse substitution applied.
  std::vector<double> ReadAccessor(int index) const {
    const tinygltf::Accessor& a = m_.accessors[index];
    const int n = ComponentCount(a.type);
    const int cs = ComponentSize(a.componentType);
    std::vector<double> out(a.count * n, 0.0);
    if (a.bufferView >= 0) {
      const tinygltf::BufferView& bv = m_.bufferViews[a.bufferView];
      size_t stride = bv.byteStride ? bv.byteStride : ElementSize(a);
      const unsigned char* base = RegionBase(a.bufferView, a.byteOffset);
      for (size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < n; ++c)
          out[i * n + c] = ReadComponent(base + i * stride + c * cs, a.componentType, a.normalized);
    }
    if (a.sparse.isSparse) {
      const auto& s = a.sparse;
      const unsigned char* idx = RegionBase(s.indices.bufferView, size_t(s.indices.byteOffset));
      const unsigned char* val = RegionBase(s.values.bufferView, size_t(s.values.byteOffset));
      int isz = ComponentSize(s.indices.componentType);
      for (int k = 0; k < s.count; ++k) {
        double target = ReadComponent(idx + k * isz, s.indices.componentType, false);
        if (target >= double(a.count))
          Fail("accessors[" + std::to_string(index) + "].sparse index " +
               std::to_string((unsigned long long)target) + " is out of range (count " +
               std::to_string(a.count) + ")");
        for (int c = 0; c < n; ++c)
          out[size_t(target) * n + c] =
              ReadComponent(val + (size_t(k) * n + c) * cs, a.componentType, a.normalized);
      }
    }
    return out;
  }

  void CheckTextureRef(int index, const std::string& what) {
    if (index != -1) CheckIndex(index, m_.textures, what);
  }

  void CheckTexturesAndMaterials() {
    for (size_t i = 0; i < m_.textures.size(); ++i) {
      const tinygltf::Texture& t = m_.textures[i];
      std::string name = "textures[" + std::to_string(i) + "]";
      if (t.source != -1) CheckIndex(t.source, m_.images, name + ".source");
      if (t.sampler != -1) CheckIndex(t.sampler, m_.samplers, name + ".sampler");
    }
    for (size_t i = 0; i < m_.images.size(); ++i) {
      const tinygltf::Image& im = m_.images[i];
      if (im.bufferView != -1) CheckIndex(im.bufferView, m_.bufferViews,
                                          "images[" + std::to_string(i) + "].bufferView");
    }
    for (size_t i = 0; i < m_.materials.size(); ++i) {
      const tinygltf::Material& mat = m_.materials[i];
      std::string name = "materials[" + std::to_string(i) + "]";
      CheckTextureRef(mat.pbrMetallicRoughness.baseColorTexture.index,
                      name + ".pbrMetallicRoughness.baseColorTexture.index");
      CheckTextureRef(mat.pbrMetallicRoughness.metallicRoughnessTexture.index,
                      name + ".pbrMetallicRoughness.metallicRoughnessTexture.index");
      CheckTextureRef(mat.normalTexture.index, name + ".normalTexture.index");
      CheckTextureRef(mat.occlusionTexture.index, name + ".occlusionTexture.index");
      CheckTextureRef(mat.emissiveTexture.index, name + ".emissiveTexture.index");
    }
  }

  static bool Finite(double v) { return std::isfinite(v); }

  void LoadMaterials() {
    for (size_t i = 0; i < m_.materials.size(); ++i) {
      const tinygltf::Material& src = m_.materials[i];
      std::string name = "materials[" + std::to_string(i) + "]";
      const auto& pbr = src.pbrMetallicRoughness;
      Material mat{};
      if (pbr.baseColorFactor.size() != 4) Fail(name + ".baseColorFactor must have 4 numbers");
      for (int c = 0; c < 3; ++c) {
        double v = pbr.baseColorFactor[c];
        if (!Finite(v) || v < 0.0 || v > 1.0)
          Fail(name + ".baseColorFactor[" + std::to_string(c) + "] is not in [0, 1]");
        mat.baseColor[c] = float(v);
      }
      double strength = 1.0;
      auto it = src.extensions.find("KHR_materials_emissive_strength");
      if (it != src.extensions.end() && it->second.Has("emissiveStrength")) {
        const tinygltf::Value& s = it->second.Get("emissiveStrength");
        if (!s.IsNumber() || !Finite(s.GetNumberAsDouble()) || s.GetNumberAsDouble() < 0.0)
          Fail(name + ": KHR_materials_emissive_strength.emissiveStrength is not a number >= 0");
        strength = s.GetNumberAsDouble();
      }
      if (src.emissiveFactor.size() != 3) Fail(name + ".emissiveFactor must have 3 numbers");
      for (int c = 0; c < 3; ++c) {
        double v = src.emissiveFactor[c];
        if (!Finite(v) || v < 0.0) Fail(name + ".emissiveFactor has a negative or non-finite value");
        mat.emission[c] = float(v * strength);
      }
      if (!Finite(pbr.metallicFactor) || !Finite(pbr.roughnessFactor))
        Fail(name + ": metallicFactor/roughnessFactor is not finite");
      mat.metallic = float(std::clamp(pbr.metallicFactor, 0.0, 1.0));
      mat.roughness = float(std::clamp(pbr.roughnessFactor, 0.0, 1.0));
      mat.flags = src.doubleSided ? shader::kMaterialDoubleSided : 0u;
      scene_.materials.push_back(mat);
      scene_.materialNames.push_back(src.name.empty() ? name : src.name);
    }
    // glTF's default material for primitives without one: white, rough, one-sided.
    defaultMaterial_ = uint32_t(scene_.materials.size());
    Material def{};
    def.baseColor = glm::vec3(1.0f);
    def.metallic = 1.0f;
    def.roughness = 1.0f;
    scene_.materials.push_back(def);
    scene_.materialNames.push_back("(default)");
  }

  // Index list of a primitive converted to a triangle list.
  std::vector<uint32_t> TriangleList(const tinygltf::Primitive& prim, size_t vertexCount,
                                     const std::string& name) const {
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
      CheckIndex(prim.indices, m_.accessors, name + ".indices");
      const tinygltf::Accessor& a = m_.accessors[prim.indices];
      std::string an = "accessors[" + std::to_string(prim.indices) + "]";
      if (a.type != TINYGLTF_TYPE_SCALAR || a.normalized ||
          (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        Fail(name + ".indices (" + an + ") must be unsigned byte/short/int SCALAR");
      // The all-ones value is reserved for primitive restart, which glTF forbids.
      const double restart = std::pow(2.0, 8.0 * ComponentSize(a.componentType)) - 1.0;
      std::vector<double> raw = ReadAccessor(prim.indices);
      idx.reserve(raw.size());
      for (size_t k = 0; k < raw.size(); ++k) {
        if (raw[k] == restart)
          Fail(name + ".indices (" + an + ") element " + std::to_string(k) +
               " is the primitive-restart value " + std::to_string((unsigned long long)restart) +
               ", which glTF forbids");
        if (raw[k] >= double(vertexCount))
          Fail(name + ".indices (" + an + ") element " + std::to_string(k) + " is " +
               std::to_string((unsigned long long)raw[k]) + ", but the primitive has only " +
               std::to_string(vertexCount) + " vertices");
        idx.push_back(uint32_t(raw[k]));
      }
    } else {
      idx.resize(vertexCount);
      for (size_t k = 0; k < vertexCount; ++k) idx[k] = uint32_t(k);
    }
    std::vector<uint32_t> tris;
    switch (prim.mode) {
      case TINYGLTF_MODE_TRIANGLES:
        if (idx.size() % 3)
          Fail(name + " has " + std::to_string(idx.size()) +
               " triangle-list indices, which is not a multiple of 3");
        return idx;
      case TINYGLTF_MODE_TRIANGLE_STRIP:
        // Every other triangle swaps two vertices to keep the strip's winding.
        for (size_t k = 2; k < idx.size(); ++k) {
          bool odd = k % 2;
          tris.insert(tris.end(), {idx[k - 2 + odd], idx[k - 1 - odd], idx[k]});
        }
        return tris;
      case TINYGLTF_MODE_TRIANGLE_FAN:
        for (size_t k = 2; k < idx.size(); ++k) tris.insert(tris.end(), {idx[k - 1], idx[k], idx[0]});
        return tris;
      default:
        return {};
    }
  }

  void DecodeMesh(int meshIndex) {
    const tinygltf::Mesh& mesh = m_.meshes[meshIndex];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      std::string name = "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(p) + "]";
      if (prim.mode < TINYGLTF_MODE_POINTS || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        Fail(name + ".mode " + std::to_string(prim.mode) + " is not valid");
      if (prim.material != -1) CheckIndex(prim.material, m_.materials, name + ".material");
      auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) Fail(name + " has no POSITION attribute");
      for (const auto& [attr, acc] : prim.attributes)
        CheckIndex(acc, m_.accessors, name + ".attributes." + attr);
      for (size_t t = 0; t < prim.targets.size(); ++t)
        for (const auto& [attr, acc] : prim.targets[t])
          CheckIndex(acc, m_.accessors, name + ".targets[" + std::to_string(t) + "]." + attr);
      const tinygltf::Accessor& pa = m_.accessors[pos->second];
      std::string pan = "accessors[" + std::to_string(pos->second) + "]";
      if (pa.type != TINYGLTF_TYPE_VEC3 ||
          (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !quantized_))
        Fail(name + ".attributes.POSITION (" + pan + ") must be a FLOAT VEC3 accessor");
      for (const auto& [attr, acc] : prim.attributes)
        if (m_.accessors[acc].count != pa.count)
          Fail(name + ": attribute " + attr + " has " + std::to_string(m_.accessors[acc].count) +
               " elements but POSITION has " + std::to_string(pa.count));
      if (prim.mode < TINYGLTF_MODE_TRIANGLES) {
        scene_.warnings.push_back(name + ": points/lines primitive skipped (only triangles are rendered)");
        continue;
      }
      DecodedPrimitive out;
      std::vector<double> raw = ReadAccessor(pos->second);
      out.positions.resize(pa.count);
      for (size_t v = 0; v < pa.count; ++v) {
        for (int c = 0; c < 3; ++c) {
          double x = raw[v * 3 + c];
          if (!Finite(x) || std::abs(x) > 1e30)
            Fail(name + ".attributes.POSITION (" + pan + ") element " + std::to_string(v) +
                 " is not a finite position");
          out.positions[v][c] = float(x);
        }
      }
      out.indices = TriangleList(prim, pa.count, name);
      out.material = prim.material >= 0 ? uint32_t(prim.material) : defaultMaterial_;
      meshes_[meshIndex].push_back(std::move(out));
    }
  }

  void CheckCameras() {
    for (size_t i = 0; i < m_.cameras.size(); ++i) {
      const tinygltf::Camera& c = m_.cameras[i];
      std::string name = "cameras[" + std::to_string(i) + "]";
      if (c.type == "perspective") {
        const auto& p = c.perspective;
        if (!Finite(p.yfov) || p.yfov <= 0.0 || p.yfov >= 3.14159)
          Fail(name + ".perspective.yfov must be in (0, π)");
        if (!Finite(p.aspectRatio) || p.aspectRatio < 0.0)
          Fail(name + ".perspective.aspectRatio must be > 0");
      } else if (c.type == "orthographic") {
        const auto& o = c.orthographic;
        if (!Finite(o.xmag) || !Finite(o.ymag) || o.xmag == 0.0 || o.ymag == 0.0)
          Fail(name + ".orthographic xmag/ymag must be finite and non-zero");
      } else {
        Fail(name + ".type \"" + c.type + "\" is neither perspective nor orthographic");
      }
    }
  }

  glm::dmat4 LocalTransform(int nodeIndex) const {
    const tinygltf::Node& n = m_.nodes[nodeIndex];
    std::string name = "nodes[" + std::to_string(nodeIndex) + "]";
    auto finite = [&](const std::vector<double>& v, size_t size, const char* field) {
      if (v.empty()) return false;
      if (v.size() != size) Fail(name + "." + field + " must have " + std::to_string(size) + " numbers");
      for (double x : v)
        if (!Finite(x)) Fail(name + "." + field + " has a non-finite value");
      return true;
    };
    if (finite(n.matrix, 16, "matrix")) return glm::make_mat4(n.matrix.data());  // column-major
    glm::dmat4 t(1.0);
    if (finite(n.translation, 3, "translation"))
      t = glm::translate(glm::dmat4(1.0), glm::make_vec3(n.translation.data()));
    glm::dmat4 r(1.0);
    if (finite(n.rotation, 4, "rotation")) {
      glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // (w, x, y, z)
      double len = glm::length(q);
      if (len < 1e-6) Fail(name + ".rotation is not a unit quaternion");
      r = glm::mat4_cast(q / len);
    }
    glm::dmat4 s(1.0);
    if (finite(n.scale, 3, "scale")) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(n.scale.data()));
    return t * r * s;
  }

  void AddCamera(int cameraIndex, const glm::dmat4& world, const std::string& nodeName) {
    const tinygltf::Camera& src = m_.cameras[cameraIndex];
    Camera cam;
    cam.name = src.name.empty() ? nodeName : src.name;
    cam.position = glm::vec3(world[3]);
    // The camera looks down its local −Z with +Y up; scale in the node is ignored.
    glm::dvec3 fwd = -glm::dvec3(world[2]);
    glm::dvec3 up = glm::dvec3(world[1]);
    if (glm::length(fwd) < 1e-12 || glm::length(up) < 1e-12)
      Fail(nodeName + ": camera transform is degenerate");
    fwd = glm::normalize(fwd);
    up = glm::normalize(up - fwd * glm::dot(up, fwd));
    cam.forward = glm::vec3(fwd);
    cam.up = glm::vec3(up);
    cam.right = glm::vec3(glm::normalize(glm::cross(fwd, up)));
    if (src.type == "perspective") {
      cam.yfov = float(src.perspective.yfov);
      cam.aspectRatio = float(src.perspective.aspectRatio);
    } else {
      cam.orthographic = true;
      cam.xmag = float(std::abs(src.orthographic.xmag));
      cam.ymag = float(std::abs(src.orthographic.ymag));
      cam.aspectRatio = cam.xmag / cam.ymag;
    }
    scene_.cameras.push_back(cam);
  }

  // Instantiates a root and its subtree. Iterative: a hierarchy thousands of levels
  // deep must not overflow the call stack.
  void InstantiateTree(int root) {
    std::vector<std::pair<int, glm::dmat4>> work{{root, glm::dmat4(1.0)}};
    while (!work.empty()) {
      auto [node, parent] = work.back();
      work.pop_back();
      glm::dmat4 world = InstantiateNode(node, parent);
      const std::vector<int>& children = m_.nodes[node].children;
      for (auto it = children.rbegin(); it != children.rend(); ++it) work.push_back({*it, world});
    }
  }

  // Adds one node's camera and mesh; returns its world transform.
  glm::dmat4 InstantiateNode(int nodeIndex, const glm::dmat4& parent) {
    const tinygltf::Node& n = m_.nodes[nodeIndex];
    std::string name = "nodes[" + std::to_string(nodeIndex) + "]";
    glm::dmat4 world = parent * LocalTransform(nodeIndex);
    if (n.camera != -1) {
      CheckIndex(n.camera, m_.cameras, name + ".camera");
      AddCamera(n.camera, world, name);
    }
    if (n.mesh != -1) {
      CheckIndex(n.mesh, m_.meshes, name + ".mesh");
      // A mirroring transform (negative determinant) flips the winding; swap two
      // vertices so the front face stays the one the author meant (glTF spec §3.7.4).
      bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
      for (const DecodedPrimitive& prim : meshes_[n.mesh]) {
        std::vector<glm::vec3> p(prim.positions.size());
        for (size_t v = 0; v < p.size(); ++v) {
          glm::dvec4 w = world * glm::dvec4(glm::dvec3(prim.positions[v]), 1.0);
          if (!Finite(w.x) || !Finite(w.y) || !Finite(w.z) || glm::any(glm::greaterThan(glm::abs(glm::dvec3(w)), glm::dvec3(1e30))))
            Fail(name + ": transformed position is not finite (mesh " + std::to_string(n.mesh) + ")");
          p[v] = glm::vec3(w);
        }
        for (size_t k = 0; k < prim.indices.size(); k += 3) {
          SceneTriangle t{p[prim.indices[k]], p[prim.indices[k + 1]], p[prim.indices[k + 2]], prim.material};
          if (mirrored) std::swap(t.v1, t.v2);
          scene_.bounds.Extend(t.v0);
          scene_.bounds.Extend(t.v1);
          scene_.bounds.Extend(t.v2);
          scene_.triangles.push_back(t);
        }
      }
    }
    return world;
  }

  // Child indices in range, no cycles, no node with two parents (the node graph must be
  // a forest): checked before any recursion so a loop cannot overflow the stack.
  void CheckNodeGraph() {
    std::vector<int> parent(m_.nodes.size(), -1);
    for (size_t i = 0; i < m_.nodes.size(); ++i) {
      for (int c : m_.nodes[i].children) {
        CheckIndex(c, m_.nodes, "nodes[" + std::to_string(i) + "].children");
        if (parent[c] != -1 || c == int(i))
          Fail("nodes[" + std::to_string(c) + "] has more than one parent or is its own child (node graph must be a tree)");
        parent[c] = int(i);
      }
    }
    roots_.clear();
    for (size_t i = 0; i < m_.nodes.size(); ++i)
      if (parent[i] == -1) roots_.push_back(int(i));
    // With at most one parent each, the nodes reachable from the roots form a forest; a
    // node not reached lies on a cycle (its parent chain never ends). Linear time.
    std::vector<char> reached(m_.nodes.size(), 0);
    std::vector<int> work = roots_;
    while (!work.empty()) {
      int n = work.back();
      work.pop_back();
      reached[n] = 1;
      for (int c : m_.nodes[n].children) work.push_back(c);
    }
    for (size_t i = 0; i < m_.nodes.size(); ++i)
      if (!reached[i]) Fail("nodes[" + std::to_string(i) + "] is part of a cycle in the node hierarchy");
    parent_ = std::move(parent);
  }

  void InstantiateScene() {
    CheckNodeGraph();
    for (size_t s = 0; s < m_.scenes.size(); ++s)
      for (int n : m_.scenes[s].nodes) {
        CheckIndex(n, m_.nodes, "scenes[" + std::to_string(s) + "].nodes");
        if (parent_[n] != -1) Fail("scenes[" + std::to_string(s) + "] lists nodes[" + std::to_string(n) + "], which is not a root node");
      }
    std::vector<int> roots;
    if (m_.defaultScene != -1) {
      CheckIndex(m_.defaultScene, m_.scenes, "scene");
      roots = m_.scenes[m_.defaultScene].nodes;
    } else if (!m_.scenes.empty()) {
      roots = m_.scenes[0].nodes;
    } else {
      roots = roots_;
      if (!roots.empty()) scene_.warnings.push_back("the file defines no scene; rendering all root nodes");
    }
    for (int r : roots) InstantiateTree(r);
  }

  void NoteIgnoredFeatures() {
    auto& ig = scene_.ignoredFeatures;
    if (!m_.textures.empty())
      ig.push_back(std::to_string(m_.textures.size()) + " texture(s): materials use their constant factors");
    bool normalTex = false, transparent = false, metallic = false;
    for (const tinygltf::Material& mat : m_.materials) {
      normalTex |= mat.normalTexture.index >= 0;
      transparent |= mat.alphaMode != "OPAQUE";
      metallic |= mat.pbrMetallicRoughness.metallicFactor > 0.0;
    }
    if (metallic) ig.push_back("metallic/roughness: every surface is rendered as Lambertian (diffuse)");
    if (transparent) ig.push_back("alphaMode MASK/BLEND: surfaces are rendered opaque");
    if (normalTex) ig.push_back("normal maps");
    if (!m_.animations.empty()) ig.push_back(std::to_string(m_.animations.size()) + " animation(s): the static pose is rendered");
    if (!m_.skins.empty()) ig.push_back("skins: meshes are rendered unskinned");
    bool morph = false;
    for (const auto& mesh : m_.meshes)
      for (const auto& p : mesh.primitives) morph |= !p.targets.empty();
    if (morph) ig.push_back("morph targets: the base mesh is rendered");
    if (!m_.lights.empty()) ig.push_back(std::to_string(m_.lights.size()) + " KHR_lights_punctual light(s): only emissive triangles emit");
    for (const std::string& ext : m_.extensionsUsed)
      if (ext != "KHR_materials_emissive_strength" && ext != "KHR_lights_punctual" && ext != "KHR_mesh_quantization")
        ig.push_back("extension " + ext);
  }

  std::string path_;
  const tinygltf::Model& m_;
  Scene& scene_;
  bool quantized_ = false;
  uint32_t defaultMaterial_ = 0;
  std::vector<std::vector<DecodedPrimitive>> meshes_;
  std::vector<int> parent_;
  std::vector<int> roots_;
};

}  // namespace

Scene LoadGltf(const std::string& path) {
  std::string bytes = ReadFileBytes(path);
  if (bytes.empty()) throw Error(path + ": file is empty");
  // Binary or text by content, not by extension: the magic "glTF" starts every GLB.
  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  std::string_view json = bytes;
  if (binary) {
    json = CheckGlbHeader(path, bytes);
  } else if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0) {
    throw Error(path + ": not a binary glTF file (the GLB magic \"glTF\" is missing)");
  }
  if (json.size() >= 3 && std::memcmp(json.data(), "\xEF\xBB\xBF", 3) == 0)
    throw Error(path + ": the JSON starts with a UTF-8 byte-order mark, which glTF forbids");
  CheckGltfSchema(path, json);

  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(KeepImageUndecoded, nullptr);
  gltf.SetFsCallbacks({&RegularFileExists, &tinygltf::ExpandFilePath, &ReadRegularFile, &tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  std::string baseDir;
  if (size_t slash = path.find_last_of('/'); slash != std::string::npos) baseDir = path.substr(0, slash);
  bool ok = false;
  // tinygltf reports most problems through `err`, but some malformed input makes it
  // throw (std::bad_alloc on a bogus URI, nlohmann-json exceptions): contain them all.
  try {
    ok = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn,
                                            reinterpret_cast<const unsigned char*>(bytes.data()),
                                            unsigned(bytes.size()), baseDir)
                : gltf.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir);
  } catch (const std::exception& e) {
    throw Error(path + ": malformed glTF (" + e.what() + ")");
  }
  auto trim = [](std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    std::replace(s.begin(), s.end(), '\n', ';');
    return s;
  };
  if (!ok) throw Error(path + ": " + (err.empty() ? std::string("malformed glTF") : trim(err)));

  Scene scene;
  scene.path = path;
  if (!warn.empty()) scene.warnings.push_back("tinygltf: " + trim(warn));
  Loader(path, model, scene).Run();
  return scene;
}

}  // namespace vkpt
