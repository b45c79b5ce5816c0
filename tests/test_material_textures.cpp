// Textures from glTF to the render: textureInfo → TextureRef (texture, TEXCOORD set,
// KHR_texture_transform), samplers → mode bits, one decoded image per glTF image,
// TEXCOORD_0/1 per triangle, the errors bad images get, and a textured quad rendered
// texel for texel. (The GPU twin of the render test is in test_gpu.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cpu/cpu_path.h"
#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "gltf_builder.h"
#include "png_writer.h"
#include "render/material_packing.h"
#include "render/render_scene.h"
#include "render/scene_access.h"
#include "render/texture_store.h"
#include "shared/material_textures.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using namespace test;

// A 2 × 2 RGBA PNG: red, green / blue, white with alpha 128.
std::vector<unsigned char> SmallPng() {
  return MakePng(2, 2, 8, 6, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128});
}

std::string AsString(const std::vector<unsigned char>& bytes) { return std::string(bytes.begin(), bytes.end()); }

// The unit triangle with TEXCOORD_0 = (0,0), (1,0), (0,1) and TEXCOORD_1 = (0.5,0.5),
// (0.25,0.75), (1,2), material 0 = `material`, and images[0] = `image` in a bufferView
// (`mimeType` "image/png"), used by textures[0] with samplers[0] = `sampler` (if any).
GltfBuilder TexturedTriangle(const std::string& material, const std::vector<unsigned char>& image = SmallPng(),
                             const std::string& sampler = "") {
  GltfBuilder b;
  const int positions = b.Positions(kUnitTriangle);
  const int uv0 = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, 1, 0, 0, 1})), kFloat, 3, "VEC2");
  const int uv1 = b.Accessor(b.View(Bytes(std::vector<float>{0.5f, 0.5f, 0.25f, 0.75f, 1, 2})), kFloat, 3, "VEC2");
  b.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(positions) + R"(,"TEXCOORD_0":)" +
                     std::to_string(uv0) + R"(,"TEXCOORD_1":)" + std::to_string(uv1) + R"(},"material":0}]})");
  b.materials.push_back(material);
  b.images.push_back(R"({"bufferView":)" + std::to_string(b.View(AsString(image))) + R"(,"mimeType":"image/png"})");
  b.textures.push_back(sampler.empty() ? R"({"source":0})" : R"({"source":0,"sampler":0})");
  if (!sampler.empty()) b.extraTopLevel += R"(,"samplers":[)" + sampler + "]";
  b.Node(R"({"mesh":0})");
  return b;
}

// Slot `slot` of the material as the shaders read it.
shader::TextureRef Ref(const Scene& s, uint32_t material, uint32_t slot) {
  return PackMaterials(s).textureRefs.at(material * shader::kTextureSlots + slot);
}

TEST(MaterialTextures, BaseColorTextureWithItsSamplerAndCoordinates) {
  Scene s = Load(TexturedTriangle(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"texCoord":1}}})",
                                  SmallPng(), R"({"magFilter":9728,"minFilter":9985,"wrapS":33071,"wrapT":33648})"));
  ASSERT_EQ(s.textures.size(), 1u);
  ASSERT_EQ(s.images.size(), 1u);
  using namespace shader;
  EXPECT_TRUE(s.textures[0].srgb);
  EXPECT_EQ(PackSampler(s.textures[0]), kWrapClampToEdge << kTextureWrapSShift |
                                            kWrapMirroredRepeat << kTextureWrapTShift | kTextureMinLinear |
                                            kTextureMipNearest);
  EXPECT_EQ(s.images[0].width, 2u);
  EXPECT_EQ(s.images[0].rgba,
            (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128}));
  const std::vector<shader::Material> packed = PackMaterials(s).materials;
  EXPECT_NE(packed[0].flags & kMaterialTextured, 0u);
  EXPECT_EQ(packed.back().flags & kMaterialTextured, 0u);  // glTF's default material
  const TextureRef& r = Ref(s, 0, kSlotBaseColor);
  EXPECT_EQ(r.texture, 0u);
  EXPECT_EQ(r.texCoord, 1u);
  EXPECT_EQ(glm::vec3(r.m00, r.m01, r.m02), glm::vec3(1, 0, 0));
  EXPECT_EQ(glm::vec3(r.m10, r.m11, r.m12), glm::vec3(0, 1, 0));
  EXPECT_EQ(Ref(s, 0, kSlotMetallicRoughness).texture, kInvalidIndex);
  EXPECT_EQ(Ref(s, 0, kSlotEmissive).texture, kInvalidIndex);
  ASSERT_EQ(s.uvs.size(), 1u);
  EXPECT_EQ(s.uvs[0].set0[1], glm::vec2(1, 0));
  EXPECT_EQ(s.uvs[0].set1[2], glm::vec2(1, 2));
}

// Without a sampler glTF leaves filtering to the renderer: repeat, trilinear.
// Every slot scales its factors by its own channels: one 1 × 1 image whose four bytes
// differ, read as colour (sRGB) by the colour slots and as data by the others.
TEST(MaterialTextures, EverySlotScalesItsFactorsByItsChannels) {
  using namespace shader;
  Scene s;
  s.images.push_back({"texel", 1, 1, {51, 102, 153, 204}});
  s.textures = {TextureWithMode(0, 0u), TextureWithMode(0, 0u, true)};
  RenderScene rs = TexturesOnly(s);
  const bool colour[kTextureSlots] = {true,  false, true,  false, false, false, true,  false, false,
                                      false, true,  false, false, true,  false, false, false};
  for (uint32_t slot = 0; slot < kTextureSlots; ++slot)
    rs.textureRefs.push_back({colour[slot] ? 1u : 0u, 0, 1, 0, 0, 0, 1, 0});
  rs.uvs.push_back({});
  shader::Material m{};
  m.baseColor = m.emission = m.specularColor = glm::vec3(1.0f);
  m.metallic = m.roughness = m.transmission = m.specular = m.clearcoat = m.clearcoatRoughness = 1.0f;
  m.flags = kMaterialTextured | kMaterialExtensionTextured;
  ApplyMaterialTextures(rs, m, 0, rs.uvs[0], 0.25f, 0.25f, vec2(kLevelZero));
  const std::vector<float> table = TexelDecodeTable();
  const glm::vec3 srgb(table[51], table[102], table[153]);
  auto data = [](int byte) { return float(byte / 255.0); };
  EXPECT_EQ(m.baseColor, srgb);
  EXPECT_EQ(m.roughness, data(102));  // G
  EXPECT_EQ(m.metallic, data(153));   // B
  EXPECT_EQ(m.emission, srgb);
  EXPECT_EQ(m.transmission, data(51));  // R
  EXPECT_EQ(m.specular, data(204));     // A
  EXPECT_EQ(m.specularColor, srgb);
  EXPECT_EQ(m.clearcoat, data(51));            // R
  EXPECT_EQ(m.clearcoatRoughness, data(102));  // G
  // Without kMaterialExtensionTextured the extensions' slots are not read.
  shader::Material plain{};
  plain.transmission = plain.specular = 1.0f;
  plain.specularColor = glm::vec3(1.0f);
  plain.flags = kMaterialTextured;
  ApplyMaterialTextures(rs, plain, 0, rs.uvs[0], 0.25f, 0.25f, vec2(kLevelZero));
  EXPECT_EQ(plain.transmission, 1.0f);
  EXPECT_EQ(plain.specular, 1.0f);
}

// The material extensions' textureInfos reach their slots; thicknessTexture, which a path
// tracer does not need, is listed as not applied.
TEST(MaterialTextures, ExtensionTexturesFillTheirSlots) {
  Scene s = Load(TexturedTriangle(
      R"({"extensions":{"KHR_materials_transmission":{"transmissionTexture":{"index":0,"texCoord":1}},)"
      R"("KHR_materials_specular":{"specularTexture":{"index":0},"specularColorTexture":{"index":0,)"
      R"("extensions":{"KHR_texture_transform":{"offset":[0.5,0]}}}},)"
      R"("KHR_materials_volume":{"thicknessFactor":1,"thicknessTexture":{"index":0}}}})"));
  using namespace shader;
  EXPECT_NE(PackMaterials(s).materials[0].flags & kMaterialExtensionTextured, 0u);
  EXPECT_EQ(Ref(s, 0, kSlotTransmission).texCoord, 1u);
  EXPECT_EQ(Ref(s, 0, kSlotSpecular).texture, Ref(s, 0, kSlotTransmission).texture);  // both data
  EXPECT_FALSE(s.textures[Ref(s, 0, kSlotTransmission).texture].srgb);
  EXPECT_TRUE(s.textures[Ref(s, 0, kSlotSpecularColor).texture].srgb);
  EXPECT_EQ(Ref(s, 0, kSlotSpecularColor).m02, 0.5f);
  EXPECT_EQ(Ref(s, 0, kSlotBaseColor).texture, kInvalidIndex);
  std::string ignored;
  for (const std::string& f : s.ignoredFeatures) ignored += f + "\n";
  EXPECT_NE(ignored.find("KHR_materials_volume.thicknessTexture: not applied (a path tracer measures"),
            std::string::npos)
      << ignored;
  EXPECT_EQ(ignored.find("transmissionTexture"), std::string::npos) << ignored;
  EXPECT_EQ(ignored.find("specularTexture"), std::string::npos) << ignored;
}

// A textured triangle whose material has `extension` (required) with `properties`.
Scene LoadExtension(const char* extension, const std::string& properties) {
  GltfBuilder b = TexturedTriangle(std::string(R"({"extensions":{")") + extension + R"(":{)" + properties + "}}}");
  b.extensionsUsed = b.extensionsRequired = {extension};
  return Load(b);
}

// Slots `slots` of material 0 hold data (linear) textures.
void ExpectDataSlots(const Scene& s, std::initializer_list<uint32_t> slots) {
  for (uint32_t slot : slots) {
    ASSERT_NE(Ref(s, 0, slot).texture, shader::kInvalidIndex) << slot;
    EXPECT_FALSE(s.textures[Ref(s, 0, slot).texture].srgb) << slot;
  }
}

// KHR_materials_clearcoat: its factors, its three textures in their slots (data, not
// colour), its normal texture's scale and the tangents it needs; the extension is neither
// ignored nor refused when required.
TEST(MaterialTextures, ClearcoatFactorsAndTexturesAreRead) {
  Scene s = LoadExtension("KHR_materials_clearcoat",
                          R"("clearcoatFactor":0.7,"clearcoatRoughnessFactor":0.2,"clearcoatTexture":{"index":0},)"
                          R"("clearcoatRoughnessTexture":{"index":0,"texCoord":1},)"
                          R"("clearcoatNormalTexture":{"index":0,"scale":0.5})");
  using namespace shader;
  const vkpt::internal::Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.clearcoat, 0.7f);
  EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.2f);
  EXPECT_FLOAT_EQ(m.clearcoatNormalScale, 0.5f);
  EXPECT_EQ(Ref(s, 0, kSlotClearcoatRoughness).texCoord, 1u);
  ExpectDataSlots(s, {kSlotClearcoat, kSlotClearcoatRoughness, kSlotClearcoatNormal});
  const shader::Material packed = PackMaterials(s).materials[0];
  EXPECT_EQ(packed.clearcoat, 0.7f);
  EXPECT_EQ(packed.clearcoatNormalScale, 0.5f);
  EXPECT_NE(packed.flags & kMaterialExtensionTextured, 0u);
  EXPECT_FALSE(PrepareRenderScene(s).tangents.empty()) << "the coat's normal texture needs tangents";
  for (const std::string& f : s.ignoredFeatures) EXPECT_EQ(f.find("clearcoat"), std::string::npos) << f;
  // Absent, the coat is off and its normal texture's scale is 1.
  const vkpt::internal::Material plain = Load(TexturedTriangle("{}")).materials[0];
  EXPECT_EQ(plain.clearcoat, 0.0f);
  EXPECT_EQ(plain.clearcoatNormalScale, 1.0f);
}

// Slots `data` (linear, from TEXCOORD_1) and `colour` (sRGB) of material 0 hold textures.
void ExpectDataAndColourSlots(const Scene& s, uint32_t data, uint32_t colour) {
  ASSERT_NE(Ref(s, 0, data).texture, shader::kInvalidIndex);
  ASSERT_NE(Ref(s, 0, colour).texture, shader::kInvalidIndex);
  EXPECT_FALSE(s.textures[Ref(s, 0, data).texture].srgb);
  EXPECT_TRUE(s.textures[Ref(s, 0, colour).texture].srgb);
  EXPECT_EQ(Ref(s, 0, data).texCoord, 1u);
}

// KHR_materials_sheen: its factors, its colour texture (sRGB) and roughness texture (data)
// in their slots; the extension is neither ignored nor refused when required.
TEST(MaterialTextures, SheenFactorsAndTexturesAreRead) {
  Scene s =
      LoadExtension("KHR_materials_sheen",
                    R"("sheenColorFactor":[0.9,0.5,0.2],"sheenRoughnessFactor":0.4,"sheenColorTexture":{"index":0},)"
                    R"("sheenRoughnessTexture":{"index":0,"texCoord":1})");
  using namespace shader;
  EXPECT_EQ(s.materials[0].sheenColor, glm::vec3(0.9f, 0.5f, 0.2f));
  EXPECT_FLOAT_EQ(s.materials[0].sheenRoughness, 0.4f);
  ExpectDataAndColourSlots(s, kSlotSheenRoughness, kSlotSheenColor);
  const shader::Material packed = PackMaterials(s).materials[0];
  EXPECT_EQ(packed.sheenColor, vec3(0.9f, 0.5f, 0.2f));
  EXPECT_EQ(packed.sheenRoughness, 0.4f);
  EXPECT_NE(packed.flags & kMaterialExtensionTextured, 0u);
  for (const std::string& f : s.ignoredFeatures) EXPECT_EQ(f.find("sheen"), std::string::npos) << f;
  const vkpt::internal::Material plain = Load(TexturedTriangle("{}")).materials[0];
  EXPECT_EQ(plain.sheenColor, glm::vec3(0.0f));
  EXPECT_FALSE(IsLambertian(PackMaterials(s).materials[0]));
}

// KHR_materials_diffuse_transmission: its factors (colour white when absent), its factor
// texture (data, A) and colour texture (sRGB) in their slots; not ignored, not refused.
TEST(MaterialTextures, DiffuseTransmissionFactorsAndTexturesAreRead) {
  Scene s = LoadExtension("KHR_materials_diffuse_transmission",
                          R"("diffuseTransmissionFactor":0.25,"diffuseTransmissionColorFactor":[1,0.9,0.85],)"
                          R"("diffuseTransmissionTexture":{"index":0,"texCoord":1},)"
                          R"("diffuseTransmissionColorTexture":{"index":0})");
  using namespace shader;
  EXPECT_FLOAT_EQ(s.materials[0].diffuseTransmission, 0.25f);
  EXPECT_EQ(s.materials[0].diffuseTransmissionColor, glm::vec3(1.0f, 0.9f, 0.85f));
  ExpectDataAndColourSlots(s, kSlotDiffuseTransmission, kSlotDiffuseTransmissionColor);
  const shader::Material packed = PackMaterials(s).materials[0];
  EXPECT_EQ(packed.diffuseTransmission, 0.25f);
  EXPECT_EQ(packed.diffuseTransmissionColor, vec3(1.0f, 0.9f, 0.85f));
  EXPECT_FALSE(IsLambertian(packed));
  for (const std::string& f : s.ignoredFeatures) EXPECT_EQ(f.find("diffuse_transmission"), std::string::npos) << f;
  const vkpt::internal::Material plain = Load(TexturedTriangle("{}")).materials[0];
  EXPECT_EQ(plain.diffuseTransmission, 0.0f);
  EXPECT_EQ(plain.diffuseTransmissionColor, glm::vec3(1.0f));
}

// KHR_materials_iridescence: its factors (the extension's defaults when absent), its
// factor (R) and thickness (G) textures in their slots as data; not ignored, not refused.
TEST(MaterialTextures, IridescenceFactorsAndTexturesAreRead) {
  Scene s = LoadExtension(
      "KHR_materials_iridescence",
      R"("iridescenceFactor":0.8,"iridescenceIor":1.6,"iridescenceThicknessMinimum":150,"iridescenceThicknessMaximum":900,)"
      R"("iridescenceTexture":{"index":0},"iridescenceThicknessTexture":{"index":0,"texCoord":1})");
  using namespace shader;
  const vkpt::internal::Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.iridescence, 0.8f);
  EXPECT_FLOAT_EQ(m.iridescenceIor, 1.6f);
  EXPECT_FLOAT_EQ(m.iridescenceThicknessMin, 150.0f);
  EXPECT_FLOAT_EQ(m.iridescenceThicknessMax, 900.0f);
  ExpectDataSlots(s, {kSlotIridescence, kSlotIridescenceThickness});
  EXPECT_EQ(Ref(s, 0, kSlotIridescenceThickness).texCoord, 1u);
  const shader::Material packed = PackMaterials(s).materials[0];
  EXPECT_EQ(packed.iridescence, 0.8f);
  EXPECT_EQ(packed.iridescenceIor, 1.6f);
  EXPECT_EQ(packed.iridescenceThicknessMin, 150.0f);
  EXPECT_EQ(packed.iridescenceThickness, 900.0f);
  EXPECT_FALSE(IsLambertian(packed));
  for (const std::string& f : s.ignoredFeatures) EXPECT_EQ(f.find("iridescence"), std::string::npos) << f;
  const vkpt::internal::Material plain =
      Load(TexturedTriangle(R"({"extensions":{"KHR_materials_iridescence":{}}})")).materials[0];
  EXPECT_EQ(plain.iridescence, 0.0f);
  EXPECT_EQ(plain.iridescenceIor, 1.3f);
  EXPECT_EQ(plain.iridescenceThicknessMin, 100.0f);
  EXPECT_EQ(plain.iridescenceThicknessMax, 400.0f);
}

// KHR_materials_anisotropy: its factors (rotation taken to (−π, π]), its texture (data)
// in its slot, the direction packed as the rotation's (cos, sin), and tangents generated
// for it without a normal map; not ignored, not refused.
TEST(MaterialTextures, AnisotropyFactorsAndTextureAreRead) {
  Scene s = LoadExtension("KHR_materials_anisotropy",
                          R"("anisotropyStrength":0.6,"anisotropyRotation":7.85398,"anisotropyTexture":{"index":0})");
  using namespace shader;
  const vkpt::internal::Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.anisotropyStrength, 0.6f);
  EXPECT_NEAR(m.anisotropyRotation, 0.5f * kPi, 1e-5f) << "7.85398 rad is a quarter turn and two half turns";
  ExpectDataSlots(s, {kSlotAnisotropy});
  const shader::Material packed = PackMaterials(s).materials[0];
  EXPECT_EQ(packed.anisotropy, 0.6f);
  EXPECT_NEAR(packed.anisotropyDirection.x, 0.0f, 1e-5f);
  EXPECT_NEAR(packed.anisotropyDirection.y, 1.0f, 1e-5f);
  EXPECT_EQ(s.generatedTangentPrimitives, 1u);
  EXPECT_FALSE(PrepareRenderScene(s).tangents.empty()) << "the anisotropic lobe needs tangents";
  for (const std::string& f : s.ignoredFeatures) EXPECT_EQ(f.find("anisotropy"), std::string::npos) << f;
  const vkpt::internal::Material plain = Load(TexturedTriangle("{}")).materials[0];
  EXPECT_EQ(plain.anisotropyStrength, 0.0f);
}

// KHR_materials_dispersion: its factor is read (a file that requires it loads), and
// packed for the renderers only where the material refracts as a volume's boundary, so
// that no other material draws a wavelength.
TEST(MaterialTextures, DispersionIsReadAndPackedWhereItRefracts) {
  Scene s = LoadExtension("KHR_materials_dispersion", R"("dispersion":0.5)");
  EXPECT_EQ(s.materials[0].dispersion, 0.5f);
  for (const std::string& f : s.ignoredFeatures) EXPECT_EQ(f.find("dispersion"), std::string::npos) << f;
  EXPECT_EQ(PackMaterials(s).materials[0].dispersion, 0.0f) << "no transmission, no volume";
  for (float ior : {1.0f, 1.5f}) {
    GltfBuilder b = TexturedTriangle(R"({"extensions":{"KHR_materials_dispersion":{"dispersion":0.5},)"
                                     R"("KHR_materials_transmission":{"transmissionFactor":1},)"
                                     R"("KHR_materials_volume":{"thicknessFactor":1},)"
                                     R"("KHR_materials_ior":{"ior":)" +
                                     std::to_string(ior) + "}}}");
    b.extensionsUsed = {"KHR_materials_dispersion", "KHR_materials_transmission", "KHR_materials_volume",
                        "KHR_materials_ior"};
    const Scene glass = Load(b);
    EXPECT_EQ(PackMaterials(glass).materials[0].dispersion, ior > 1.0f ? 0.5f : 0.0f) << "ior " << ior;
  }
  EXPECT_EQ(Load(TexturedTriangle("{}")).materials[0].dispersion, 0.0f);
}

TEST(MaterialTextures, ExtensionFactorsOutOfRangeAreNamed) {
  const std::pair<const char*, const char*> kBad[] = {
      {"KHR_materials_clearcoat", R"("clearcoatFactor":1.5)"},
      {"KHR_materials_clearcoat", R"("clearcoatRoughnessFactor":-0.1)"},
      {"KHR_materials_clearcoat", R"("clearcoatNormalTexture":{"index":0,"scale":"big"})"},
      {"KHR_materials_sheen", R"("sheenColorFactor":[1.5,0,0])"},
      {"KHR_materials_sheen", R"("sheenColorFactor":"red")"},
      {"KHR_materials_sheen", R"("sheenColorFactor":[1,1])"},
      {"KHR_materials_sheen", R"("sheenRoughnessFactor":2)"},
      {"KHR_materials_diffuse_transmission", R"("diffuseTransmissionFactor":-0.5)"},
      {"KHR_materials_diffuse_transmission", R"("diffuseTransmissionColorFactor":[0.5,2,0.5])"},
      {"KHR_materials_iridescence", R"("iridescenceFactor":1.2)"},
      {"KHR_materials_iridescence", R"("iridescenceIor":0.5)"},
      {"KHR_materials_iridescence", R"("iridescenceThicknessMinimum":-1)"},
      {"KHR_materials_iridescence", R"("iridescenceThicknessMaximum":1e9)"},
      {"KHR_materials_anisotropy", R"("anisotropyStrength":-0.2)"},
      {"KHR_materials_anisotropy", R"("anisotropyRotation":1e300)"},
      {"KHR_materials_dispersion", R"("dispersion":-1)"},
      {"KHR_materials_dispersion", R"("dispersion":1e4)"}};
  for (const auto& [extension, bad] : kBad) {
    try {
      Load(TexturedTriangle(std::string(R"({"extensions":{")") + extension + R"(":{)" + bad + "}}}"));
      ADD_FAILURE() << bad << " loaded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("materials[0].") + extension + "."), std::string::npos)
          << e.what();
    }
  }
}

TEST(MaterialTextures, ExtensionTextureIndicesAreChecked) {
  try {
    Load(TexturedTriangle(R"({"extensions":{"KHR_materials_transmission":{"transmissionTexture":{"index":3}}}})"));
    FAIL() << "an out-of-range index loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("KHR_materials_transmission.transmissionTexture.index refers to index 3"),
              std::string::npos)
        << e.what();
  }
}

TEST(MaterialTextures, NoSamplerMeansRepeatAndTrilinear) {
  Scene s = Load(TexturedTriangle(R"({"emissiveTexture":{"index":0}})"));
  ASSERT_EQ(s.textures.size(), 1u);
  using namespace shader;
  EXPECT_TRUE(s.textures[0].srgb);
  EXPECT_EQ(PackSampler(s.textures[0]), kTextureMagLinear | kTextureMinLinear | kTextureMipLinear);
  EXPECT_EQ(Ref(s, 0, kSlotEmissive).texture, 0u);
}

// Colour (sRGB) and data (linear) uses of one texture are two textures of one image.
TEST(MaterialTextures, ColourAndDataUsesOfOneImage) {
  Scene s = Load(TexturedTriangle(
      R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicRoughnessTexture":{"index":0}}})"));
  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.images.size(), 1u);
  EXPECT_TRUE(s.textures[Ref(s, 0, shader::kSlotBaseColor).texture].srgb);
  EXPECT_FALSE(s.textures[Ref(s, 0, shader::kSlotMetallicRoughness).texture].srgb);
  EXPECT_EQ(s.textures[0].image, s.textures[1].image);
}

// T · R · S with offset (0.5, 0.25), rotation π/2 and scale (2, 3): u' = 3v + 0.5,
// v' = −2u + 0.25; its texCoord overrides the textureInfo's.
TEST(MaterialTextures, TextureTransformIsTheExtensionsMatrix) {
  Scene s = Load(TexturedTriangle(
      R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"texCoord":0,"extensions":{"KHR_texture_transform":)"
      R"({"offset":[0.5,0.25],"rotation":1.5707963267948966,"scale":[2,3],"texCoord":1}}}}})"));
  const shader::TextureRef& r = Ref(s, 0, shader::kSlotBaseColor);
  EXPECT_EQ(r.texCoord, 1u);
  EXPECT_NEAR(r.m00, 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(r.m01, 3.0f);
  EXPECT_FLOAT_EQ(r.m02, 0.5f);
  EXPECT_FLOAT_EQ(r.m10, -2.0f);
  EXPECT_NEAR(r.m11, 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(r.m12, 0.25f);
  EXPECT_TRUE(s.ignoredFeatures.empty()) << ::testing::PrintToString(s.ignoredFeatures);
}

TEST(MaterialTextures, UnusableReferencesWarnAndKeepTheFactor) {
  Scene s = Load(TexturedTriangle(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"texCoord":2}}})"));
  EXPECT_TRUE(s.textures.empty());
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("TEXCOORD_2"), std::string::npos) << s.warnings[0];
  // A texture whose only image is in an extension vkpt does not know (AVIF).
  GltfBuilder avif = TexturedTriangle(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})");
  avif.textures[0] = R"({"extensions":{"EXT_texture_avif":{"source":0}}})";
  avif.extensionsUsed.push_back("EXT_texture_avif");
  Scene w = Load(avif);
  EXPECT_TRUE(w.textures.empty());
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_NE(w.warnings[0].find("textures[0] has no image; the factor is used alone"), std::string::npos)
      << w.warnings[0];
}

TEST(MaterialTextures, BadImagesNameTheImageAndTheMaterial) {
  const std::string material = R"({"name":"Floor","pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
  const std::vector<std::string> where = {"images[0]", "materials[0] \"Floor\"", "baseColorTexture"};
  std::vector<unsigned char> cut = SmallPng();
  cut.resize(cut.size() - 20);
  EXPECT_TRUE(FailsWith(TexturedTriangle(material, cut), {where[0], where[1], where[2], "truncated"}));
  EXPECT_TRUE(
      FailsWith(TexturedTriangle(material, MakePng(60000, 60000, 8, 6, {})), {where[0], where[1], "60000", "16384"}));
  const std::string webp("RIFF\x10\0\0\0WEBPVP8 ", 16);  // declares 24 bytes
  EXPECT_TRUE(FailsWith(TexturedTriangle(material, std::vector<unsigned char>(webp.begin(), webp.end())),
                        {where[0], where[1], "is truncated (WebP"}));
  EXPECT_TRUE(FailsWith(TexturedTriangle(material, {'G', 'I', 'F', '8', '9', 'a'}),
                        {where[0], where[1], "is not PNG, JPEG or WebP"}));
  EXPECT_TRUE(FailsWith(TexturedTriangle(material, SmallPng(), R"({"wrapS":1234})"), {"samplers[0].wrapS", "1234"}));
}

// Texels are counted from the headers against --max-texels, memory against
// --max-memory, before anything is decoded.
TEST(MaterialTextures, TexelAndMemoryBudgetsAreCheckedFromTheHeader) {
  const std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
  TempFile small(TexturedTriangle(material).Json());
  LoadLimits limits;
  limits.maxTextureTexels = 4;
  EXPECT_EQ(LoadGltf(small.path, limits).images.size(), 1u);
  limits.maxTextureTexels = 3;
  try {
    LoadGltf(small.path, limits);
    ADD_FAILURE() << "4 texels loaded with --max-texels 3";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--max-texels 3"), std::string::npos) << e.what();
  }
  // 512² texels (44 bytes each through to the device) within 8 MiB: refused from the
  // header, before the image is decoded. The image is a file beside the glTF, charged by
  // its size (an embedded one would cost the JSON parse more than that).
  const std::vector<unsigned char> png = MakePng(512, 512, 8, 6, std::vector<uint8_t>(512 * 512 * 4, 7));
  TempFile image(AsString(png), ".png");
  GltfBuilder b = TexturedTriangle(material);
  b.images[0] = R"({"uri":")" + std::filesystem::path(image.path).filename().string() + R"("})";
  TempFile big(b.Json());
  limits = LoadLimits{};
  limits.maxMemory = uint64_t(8) << 20;
  try {
    LoadGltf(big.path, limits);
    ADD_FAILURE() << "a 512² texture loaded within 8 MiB";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("512 × 512 texels"), std::string::npos) << e.what();
  }
}

// A decompression bomb: a 100-byte PNG whose header claims 16384² pixels (1 GiB decoded)
// is refused from its size, before stb would allocate the image.
TEST(MaterialTextures, PngTooSmallForItsHeaderIsRefused) {
  const std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
  EXPECT_TRUE(FailsWith(TexturedTriangle(material, MakePng(16384, 16384, 8, 6, {})),
                        {"images[0]", "bytes of compressed image data cannot hold 16384 × 16384 pixels"}));
}

TEST(MaterialTextures, TexCoordsMustBeFiniteVec2) {
  GltfBuilder b = TexturedTriangle(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})");
  const int bad = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, NAN, 0, 0, 1})), kFloat, 3, "VEC2");
  b.meshes[0] =
      R"({"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":)" + std::to_string(bad) + R"(},"material":0}]})";
  EXPECT_TRUE(FailsWith(b, {"TEXCOORD_0", "element 1", "not a finite texture coordinate"}));
  b.meshes[0] = R"({"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":0},"material":0}]})";  // VEC3
  EXPECT_TRUE(FailsWith(b, {"TEXCOORD_0", "must be a VEC2 accessor"}));
}

// Untextured scenes keep no texture coordinates (nor pay for them).
TEST(MaterialTextures, UntexturedScenesHaveNoCoordinates) {
  GltfBuilder b = TexturedTriangle(R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1]}})");
  Scene s = Load(b);
  EXPECT_TRUE(s.uvs.empty());
  EXPECT_FALSE(HasMaterialTextures(s));
  EXPECT_TRUE(s.images.empty());
}

// Bit for bit, every pixel its texel (the footprint of each lies inside one texel).
// Vertices paired with the wrong coordinates (b1 and b2 swapped in InterpolatedUV) put
// 3107 of 4096 pixels off, here and on the GPU (checked).
// TextureCoordinateTest (gltf-corpus/ of the test data): four squares facing −Z, each showing a
// corner region of one image. Seen from −Z (+x to the left), the texture's (0, 0) must be
// at the top left of the top-left square and v must grow downwards: probes on a 25 × 25 grid
// in each square, by rays along +Z, must find the base colour factor times the image at the
// coordinates this hand-made map gives (level 0), where a v or u flipped the wrong way
// would read the image's other corner, its text and checkers elsewhere.
TEST(MaterialTextures, TextureCoordinateTestShowsEachCornerUpright) {
  VKPT_REQUIRE_SHARED_DATA();
  const std::string path = CorpusPath("valid/TextureCoordinateTest/glTF/TextureCoordinateTest.gltf");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const RenderScene rs = PrepareRenderScene(LoadGltf(path));
  ASSERT_EQ(rs.textures.size(), 1u);
  struct Square {
    float left, top;  // the screen's left edge is its largest x
    glm::vec2 uv;     // at that corner
  };
  const Square squares[] = {{1.2f, 1.2f, {0.0f, 0.0f}},     // top left
                            {-0.2f, 1.2f, {0.6f, 0.0f}},    // top right
                            {1.2f, -0.2f, {0.0f, 0.6f}},    // bottom left
                            {-0.2f, -0.2f, {0.6f, 0.6f}}};  // bottom right
  int probes = 0, off = 0, dark = 0;
  for (const Square& sq : squares)
    for (int i = 0; i < 25; ++i)
      for (int j = 0; j < 25; ++j) {
        const float dx = 0.02f + 0.96f * float(i) / 24.0f, dy = 0.02f + 0.96f * float(j) / 24.0f;
        const shader::Ray ray{glm::vec3(sq.left - dx, sq.top - dy, -5.0f), glm::vec3(0, 0, 1)};
        const Hit hit = IntersectClosest(rs, ray.origin, ray.dir, shader::kInfinity);
        ASSERT_GE(hit.t, 0.0f);
        const shader::SurfaceHit sh = shader::MakeSurfaceHit(rs, ray, hit, glm::vec2(0.0f));
        const glm::vec2 uv = sq.uv + 0.4f * glm::vec2(dx, dy);  // the squares are 1 wide, their regions 0.4
        const glm::vec3 factor = rs.materials[rs.triangles[hit.triangle].material].baseColor;
        const glm::vec3 expected =
            factor *
            glm::vec3(shader::SampleTexture(rs, rs.textures[0], uv, 0.0f, shader::SlotIsSrgb(shader::kSlotBaseColor)));
        off += glm::any(glm::greaterThan(glm::abs(sh.material.baseColor - expected), glm::vec3(2e-3f)));
        dark += shader::MaxComponent(expected) < 0.5f * shader::MaxComponent(factor);
        ++probes;
      }
  std::printf("TextureCoordinateTest: %d of %d probes off the hand-mapped texel (%d of them dark)\n", off, probes,
              dark);
  EXPECT_EQ(off, 0);
  EXPECT_GT(dark, 80);  // the probes see the checkers, crosses and text, not only the white
}

TEST(MaterialTextures, TexturedQuadShowsItsTexels) {
  Scene s = TexturedQuadScene();
  RenderScene rs = PrepareRenderScene(s);
  EXPECT_EQ(PixelsOffTexturedQuad(RenderCpu(rs, TestFrame(rs, s, 64, 2, 3, 4)).image), 0);
}

}  // namespace
}  // namespace vkpt::internal
