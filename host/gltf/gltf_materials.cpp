#include "gltf/gltf_materials.h"

#include <algorithm>
#include <cmath>

namespace vkpt::internal {
namespace {

// Reads one material's factors, each checked against the range its schema gives.
class MaterialReader {
 public:
  MaterialReader(const GltfSource& src, const tinygltf::Material& in, std::string name)
      : src_(src), in_(in), name_(std::move(name)) {}

  Material Read() const {
    const auto& pbr = in_.pbrMetallicRoughness;
    Material mat{};
    mat.baseColor = Color(pbr.baseColorFactor, 4, "pbrMetallicRoughness.baseColorFactor", 1.0);
    mat.metallic = float(Unit(pbr.metallicFactor, "pbrMetallicRoughness.metallicFactor"));
    mat.roughness = float(Unit(pbr.roughnessFactor, "pbrMetallicRoughness.roughnessFactor"));
    const double strength = ExtensionNumber("KHR_materials_emissive_strength", "emissiveStrength", 1.0);
    if (strength < 0.0) Fail("KHR_materials_emissive_strength.emissiveStrength must be >= 0");
    mat.emission = Color(in_.emissiveFactor, 3, "emissiveFactor", 1.0) * float(strength);

    mat.specular = float(Unit(ExtensionNumber("KHR_materials_specular", "specularFactor", 1.0),
                              "KHR_materials_specular.specularFactor"));
    mat.specularColor = glm::vec3(1.0f);
    if (const tinygltf::Value* c = ExtensionField("KHR_materials_specular", "specularColorFactor"))
      mat.specularColor = Color(NumberArray(*c, "KHR_materials_specular.specularColorFactor"), 3,
                                "KHR_materials_specular.specularColorFactor", INFINITY);
    const double ior = ExtensionNumber("KHR_materials_ior", "ior", 1.5);
    if (!IorHolds(ior)) Fail("KHR_materials_ior.ior must be 0 or in [1, 1e6]");
    mat.ior = float(ior);
    mat.transmission = float(Unit(ExtensionNumber("KHR_materials_transmission", "transmissionFactor", 0.0),
                                  "KHR_materials_transmission.transmissionFactor"));
    ReadClearcoat(mat);
    ReadSheen(mat);
    ReadDiffuseTransmission(mat);
    ReadIridescence(mat);
    ReadAnisotropy(mat);
    ReadDispersion(mat);
    mat.doubleSided = in_.doubleSided;
    mat.unlit = in_.extensions.count("KHR_materials_unlit") != 0;
    ReadVolume(mat);
    ReadAlpha(mat);
    return mat;
  }

 private:
  // glTF §3.9.4 alpha coverage: baseColorFactor's alpha and the mode and cutoff that say
  // how it is used.
  void ReadAlpha(Material& mat) const {
    const double alpha =
        in_.pbrMetallicRoughness.baseColorFactor.size() == 4 ? in_.pbrMetallicRoughness.baseColorFactor[3] : 1.0;
    if (!(alpha >= 0.0 && alpha <= 1.0)) Fail("pbrMetallicRoughness.baseColorFactor[3] is not in [0, 1]");
    if (!(in_.alphaCutoff >= 0.0 && std::isfinite(in_.alphaCutoff))) Fail("alphaCutoff must be a finite number >= 0");
    mat.alpha = float(alpha);
    mat.alphaCutoff = float(in_.alphaCutoff);
    const auto* mode = std::find(std::begin(kAlphaModeNames), std::end(kAlphaModeNames), in_.alphaMode);
    if (mode == std::end(kAlphaModeNames)) Fail("alphaMode \"" + in_.alphaMode + "\" is not OPAQUE, MASK or BLEND");
    mat.alphaMode = AlphaMode(mode - std::begin(kAlphaModeNames));
  }

  // KHR_materials_volume: a thickness > 0 makes the transmissive surface the boundary of
  // a volume (rays refract, and attenuate inside by Beer–Lambert); without it the surface
  // is thin-walled. Sets mat.volume and mat.attenuation.
  void ReadVolume(Material& mat) const {
    mat.attenuation = glm::vec3(0.0f);
    const double thickness = ExtensionNumber("KHR_materials_volume", "thicknessFactor", 0.0);
    if (thickness < 0.0) Fail("KHR_materials_volume.thicknessFactor must be >= 0");
    const double distance = ExtensionNumber("KHR_materials_volume", "attenuationDistance", INFINITY);
    if (!(distance > 0.0)) Fail("KHR_materials_volume.attenuationDistance must be > 0");
    glm::vec3 color(1.0f);
    if (const tinygltf::Value* c = ExtensionField("KHR_materials_volume", "attenuationColor"))
      color = Color(NumberArray(*c, "KHR_materials_volume.attenuationColor"), 3,
                    "KHR_materials_volume.attenuationColor", 1.0);
    // A colour channel of 0 absorbs everything: the largest finite σ keeps the buffers free of inf.
    for (int i = 0; i < 3; ++i)
      mat.attenuation[i] = color[i] > 0.0f ? float(std::min(-std::log(double(color[i])) / distance, 3.0e38)) : 3.0e38f;
    mat.volume = thickness > 0.0;
  }

  // KHR_materials_clearcoat's factors and its normal texture's scale (its textures are
  // gltf_textures.cpp's).
  void ReadClearcoat(Material& mat) const {
    const char* ext = "KHR_materials_clearcoat";
    mat.clearcoat =
        float(Unit(ExtensionNumber(ext, "clearcoatFactor", 0.0), "KHR_materials_clearcoat.clearcoatFactor"));
    mat.clearcoatRoughness = float(Unit(ExtensionNumber(ext, "clearcoatRoughnessFactor", 0.0),
                                        "KHR_materials_clearcoat.clearcoatRoughnessFactor"));
    mat.clearcoatNormalScale = 1.0f;
    const tinygltf::Value* normal = ExtensionField(ext, "clearcoatNormalTexture");
    if (!normal || !normal->IsObject() || !normal->Has("scale")) return;
    const tinygltf::Value& scale = normal->Get("scale");
    if (!scale.IsNumber() || !(std::abs(scale.GetNumberAsDouble()) <= 1e6))
      Fail("KHR_materials_clearcoat.clearcoatNormalTexture.scale is not a finite number of at most 1e6");
    mat.clearcoatNormalScale = float(scale.GetNumberAsDouble());
  }

  // KHR_materials_sheen's factors (its textures are gltf_textures.cpp's).
  void ReadSheen(Material& mat) const {
    const char* ext = "KHR_materials_sheen";
    mat.sheenColor = glm::vec3(0.0f);
    if (const tinygltf::Value* c = ExtensionField(ext, "sheenColorFactor"))
      mat.sheenColor = Color(NumberArray(*c, "KHR_materials_sheen.sheenColorFactor"), 3,
                             "KHR_materials_sheen.sheenColorFactor", 1.0);
    mat.sheenRoughness =
        float(Unit(ExtensionNumber(ext, "sheenRoughnessFactor", 0.0), "KHR_materials_sheen.sheenRoughnessFactor"));
  }

  // KHR_materials_diffuse_transmission's factors (its textures are gltf_textures.cpp's).
  void ReadDiffuseTransmission(Material& mat) const {
    const char* ext = "KHR_materials_diffuse_transmission";
    mat.diffuseTransmission = float(Unit(ExtensionNumber(ext, "diffuseTransmissionFactor", 0.0),
                                         "KHR_materials_diffuse_transmission.diffuseTransmissionFactor"));
    mat.diffuseTransmissionColor = glm::vec3(1.0f);
    if (const tinygltf::Value* c = ExtensionField(ext, "diffuseTransmissionColorFactor"))
      mat.diffuseTransmissionColor =
          Color(NumberArray(*c, "KHR_materials_diffuse_transmission.diffuseTransmissionColorFactor"), 3,
                "KHR_materials_diffuse_transmission.diffuseTransmissionColorFactor", 1.0);
  }

  // KHR_materials_iridescence's factors (its textures are gltf_textures.cpp's).
  void ReadIridescence(Material& mat) const {
    const char* ext = "KHR_materials_iridescence";
    mat.iridescence =
        float(Unit(ExtensionNumber(ext, "iridescenceFactor", 0.0), "KHR_materials_iridescence.iridescenceFactor"));
    const double ior = ExtensionNumber(ext, "iridescenceIor", 1.3);
    if (!(ior >= 1.0 && ior <= 1e6)) Fail("KHR_materials_iridescence.iridescenceIor is not in [1, 1e6]");
    mat.iridescenceIor = float(ior);
    mat.iridescenceThicknessMin = Thickness(ExtensionNumber(ext, "iridescenceThicknessMinimum", 100.0),
                                            "KHR_materials_iridescence.iridescenceThicknessMinimum");
    mat.iridescenceThicknessMax = Thickness(ExtensionNumber(ext, "iridescenceThicknessMaximum", 400.0),
                                            "KHR_materials_iridescence.iridescenceThicknessMaximum");
  }

  // KHR_materials_anisotropy's factors (its texture is gltf_textures.cpp's).
  void ReadAnisotropy(Material& mat) const {
    const char* ext = "KHR_materials_anisotropy";
    mat.anisotropyStrength =
        float(Unit(ExtensionNumber(ext, "anisotropyStrength", 0.0), "KHR_materials_anisotropy.anisotropyStrength"));
    const double rotation = ExtensionNumber(ext, "anisotropyRotation", 0.0);
    if (!(std::abs(rotation) <= 1e6))
      Fail("KHR_materials_anisotropy.anisotropyRotation is not a finite number of at most 1e6");
    mat.anisotropyRotation = float(std::remainder(rotation, 2.0 * 3.14159265358979323846));
  }

  // KHR_materials_dispersion's factor: 20/Vd, realistic up to about 1 (Vd = 20); larger
  // values exaggerate, and beyond 1000 (Vd = 0.02) nothing is left to exaggerate.
  void ReadDispersion(Material& mat) const {
    const double dispersion = ExtensionNumber("KHR_materials_dispersion", "dispersion", 0.0);
    if (!(dispersion >= 0.0 && dispersion <= 1000.0)) Fail("KHR_materials_dispersion.dispersion is not in [0, 1000]");
    mat.dispersion = float(dispersion);
  }

  // A film's thickness in nm: at most 1 mm, where its colours have long averaged out.
  float Thickness(double v, const char* field) const {
    if (!(v >= 0.0 && v <= 1e6)) Fail(std::string(field) + " is not in [0, 1e6] nm");
    return float(v);
  }

  [[noreturn]] void Fail(const std::string& what) const { src_.Fail(name_ + "." + what); }

  double Unit(double v, const char* field) const {
    if (!std::isfinite(v) || v < 0.0 || v > 1.0) Fail(std::string(field) + " is not in [0, 1]");
    return v;
  }

  // The first three numbers of a colour factor of `size` numbers, each in [0, max].
  glm::vec3 Color(const std::vector<double>& v, size_t size, const char* field, double max) const {
    if (v.size() != size) Fail(std::string(field) + " must have " + std::to_string(size) + " numbers");
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(v[i]) || v[i] < 0.0 || v[i] > max)
        Fail(std::string(field) + "[" + std::to_string(i) + "] is " +
             (max == 1.0 ? "not in [0, 1]" : "negative or not finite"));
      c[i] = float(v[i]);
    }
    return c;
  }

  const tinygltf::Value* ExtensionField(const char* extension, const char* field) const {
    auto it = in_.extensions.find(extension);
    if (it == in_.extensions.end() || !it->second.IsObject() || !it->second.Has(field)) return nullptr;
    return &it->second.Get(field);
  }

  double ExtensionNumber(const char* extension, const char* field, double absent) const {
    const tinygltf::Value* v = ExtensionField(extension, field);
    if (!v) return absent;
    if (!v->IsNumber() || !std::isfinite(v->GetNumberAsDouble()))
      Fail(std::string(extension) + "." + field + " is not a finite number");
    return v->GetNumberAsDouble();
  }

  std::vector<double> NumberArray(const tinygltf::Value& v, const char* field) const {
    if (!v.IsArray()) Fail(std::string(field) + " is not an array");
    std::vector<double> out;
    for (size_t i = 0; i < v.ArrayLen(); ++i) {
      if (!v.Get(int(i)).IsNumber()) Fail(std::string(field) + " holds a value that is not a number");
      out.push_back(v.Get(int(i)).GetNumberAsDouble());
    }
    return out;
  }

  const GltfSource& src_;
  const tinygltf::Material& in_;
  std::string name_;
};

}  // namespace

uint32_t LoadMaterials(const GltfSource& src, Scene& scene) {
  for (size_t i = 0; i < src.m.materials.size(); ++i) {
    const tinygltf::Material& in = src.m.materials[i];
    std::string name = "materials[" + std::to_string(i) + "]";
    scene.materials.push_back(MaterialReader(src, in, name).Read());
    scene.materialNames.push_back(in.name.empty() ? name : in.name);
  }
  // glTF's default material for primitives without one: the defaults of every factor,
  // a white, fully rough metal, one-sided.
  const uint32_t defaultMaterial = uint32_t(scene.materials.size());
  tinygltf::Material def;
  def.emissiveFactor = {0.0, 0.0, 0.0};  // set by tinygltf's parser, not its constructor
  scene.materials.push_back(MaterialReader(src, def, "(default material)").Read());
  scene.materialNames.push_back("(default)");
  return defaultMaterial;
}

}  // namespace vkpt::internal
