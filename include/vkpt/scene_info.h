// What a loaded vkpt::Scene holds, as small read-only records: its materials, cameras,
// lights, animations and variants as the file declares them, and the counts of the
// scene as last built for a render. Standard C++ only; included by vkpt/vkpt.h.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vkpt {
inline namespace v1 {

using Rgb = std::array<float, 3>;
using Vec3 = std::array<float, 3>;
using Quat = std::array<float, 4>;  // a rotation as glTF writes it: x, y, z, w

// A material's factors as the renderer reads them (glTF's defaults where the file is
// silent), one X(type, member, Python name, lo, hi, doc) per field: MaterialInfo holds
// them, the Python binding lists them, and Scene::Parameters() offers each for editing as
// "materials/<index>/<Python name>", within [lo, hi] (each channel of an Rgb; a bool is 0
// or 1).
#define VKPT_MATERIAL_FACTORS(X)                                                                                    \
  X(Rgb, baseColor, "base_color", 0, 1, "baseColorFactor's RGB")                                                    \
  X(float, alpha, "alpha", 0, 1, "baseColorFactor's alpha")                                                         \
  X(float, metallic, "metallic", 0, 1, "metallicFactor")                                                            \
  X(float, roughness, "roughness", 0, 1, "roughnessFactor")                                                         \
  X(Rgb, emission, "emission", 0, 3.4e38, "emitted radiance: emissiveFactor times KHR_materials_emissive_strength") \
  X(float, specular, "specular", 0, 1, "KHR_materials_specular's specularFactor (0: no specular layer)")            \
  X(Rgb, specularColor, "specular_color", 0, 3.4e38, "KHR_materials_specular's specularColorFactor")                \
  X(float, ior, "ior", 0, 1e6, "KHR_materials_ior (1.5 when absent)")                                               \
  X(float, transmission, "transmission", 0, 1, "KHR_materials_transmission's transmissionFactor")                   \
  X(bool, volume, "volume", 0, 1, "KHR_materials_volume: the surface bounds a volume (thickness > 0)")              \
  X(Rgb, attenuation, "attenuation", 0, 3.4e38, "the volume's attenuation coefficient per unit length")             \
  X(float, normalScale, "normal_scale", -1e6, 1e6, "normalTexture.scale")                                           \
  X(float, alphaCutoff, "alpha_cutoff", 0, 3.4e38, "alphaCutoff (alpha_mode MASK)")                                 \
  X(bool, doubleSided, "double_sided", 0, 1, "doubleSided")                                                         \
  X(bool, unlit, "unlit", 0, 1, "KHR_materials_unlit")                                                              \
  X(float, clearcoat, "clearcoat", 0, 1, "KHR_materials_clearcoat's clearcoatFactor (0: no coat)")                  \
  X(float, clearcoatRoughness, "clearcoat_roughness", 0, 1, "KHR_materials_clearcoat's roughness")                  \
  X(float, clearcoatNormalScale, "clearcoat_normal_scale", -1e6, 1e6, "clearcoatNormalTexture.scale")               \
  X(Rgb, sheenColor, "sheen_color", 0, 1, "KHR_materials_sheen's sheenColorFactor (black: no sheen)")               \
  X(float, sheenRoughness, "sheen_roughness", 0, 1, "KHR_materials_sheen's sheenRoughnessFactor")                   \
  X(float, diffuseTransmission, "diffuse_transmission", 0, 1, "KHR_materials_diffuse_transmission's factor")        \
  X(Rgb, diffuseTransmissionColor, "diffuse_transmission_color", 0, 1, "its diffuseTransmissionColorFactor")        \
  X(float, iridescence, "iridescence", 0, 1, "KHR_materials_iridescence's iridescenceFactor (0: no film)")          \
  X(float, iridescenceIor, "iridescence_ior", 1, 1e6, "the film's index of refraction")                             \
  X(float, iridescenceThicknessMin, "iridescence_thickness_min", 0, 1e6, "the film's least thickness, nm")          \
  X(float, iridescenceThicknessMax, "iridescence_thickness_max", 0, 1e6, "the film's greatest thickness, nm")       \
  X(float, anisotropyStrength, "anisotropy_strength", 0, 1, "KHR_materials_anisotropy's strength")                  \
  X(float, anisotropyRotation, "anisotropy_rotation", -3.14159275, 3.14159275,                                      \
    "its rotation, radians from the tangent")                                                                       \
  X(float, dispersion, "dispersion", 0, 1000, "KHR_materials_dispersion: 20 / the Abbe number (0: none)")

// A material's use of a texture: which of the file's textures (glTF textures[i]), read at
// which TEXCOORD set.
struct MaterialTextureInfo {
  uint32_t texture = 0;
  uint32_t texCoord = 0;
};

struct MaterialInfo {
  uint32_t index = 0;  // the glTF material's (the last one: vkpt's default material)
  std::string name;
#define VKPT_MATERIAL_FIELD(type, member, python, lo, hi, doc) type member{};
  VKPT_MATERIAL_FACTORS(VKPT_MATERIAL_FIELD)
#undef VKPT_MATERIAL_FIELD
  std::string alphaMode;  // "OPAQUE", "MASK" or "BLEND"
  // By slot ("baseColor", "metallicRoughness", "normal", "clearcoat", …): the slots used.
  std::map<std::string, MaterialTextureInfo> textures;
};

struct CameraInfo {
  uint32_t index = 0;
  std::string name;
  Vec3 position{}, forward{}, up{};  // world space; forward and up unit
  bool orthographic = false;
  double yfovDegrees = 0.0;  // perspective
  double ymag = 0.0;         // orthographic: half the view height
  double aspectRatio = 0.0;  // width / height from the file; 0 when absent
};

// A KHR_lights_punctual light as placed in the scene by a node.
struct LightInfo {
  uint32_t index = 0;
  uint32_t light = 0;  // the file's KHR_lights_punctual lights[light]: "lights/<light>/…" edits it
  std::string name;
  std::string type;                                       // "point", "spot" or "directional"
  Rgb color{};                                            // linear, in [0, 1]
  double intensity = 0.0;                                 // candela (point, spot) or lux (directional)
  Vec3 position{};                                        // world space (not for a directional light)
  Vec3 direction{};                                       // unit, the way the light travels (spot, directional)
  double range = 0.0;                                     // 0: unbounded
  double innerConeDegrees = 0.0, outerConeDegrees = 0.0;  // spot
};

// A node of the file (glTF nodes[index]): what it places and its local transform, which
// "nodes/<index>/translation", "…/rotation" and "…/scale" edit.
struct NodeInfo {
  uint32_t index = 0;
  std::string name;  // "" where the file gives none
  // The file's meshes[i], cameras[i] and KHR_lights_punctual lights[i] the node places.
  std::optional<uint32_t> mesh, camera, light;
  std::vector<uint32_t> children;
  Vec3 translation{};
  Quat rotation{0.0f, 0.0f, 0.0f, 1.0f};  // unit
  Vec3 scale{1.0f, 1.0f, 1.0f};
  // Placed by a matrix: the three above are its decomposition (without any shear), and an
  // edit of one of them replaces the matrix by all three.
  bool matrix = false;
};

// A triangle primitive of a mesh: its material (in the variant chosen) and triangles.
struct PrimitiveInfo {
  uint32_t material = 0;
  uint64_t triangles = 0;
};

// A mesh of the file (glTF meshes[index]), its points and lines left out.
struct MeshInfo {
  uint32_t index = 0;
  std::string name;  // "" where the file gives none
  std::vector<PrimitiveInfo> primitives;
};

struct AnimationInfo {
  uint32_t index = 0;
  std::string name;
  double duration = 0.0;  // seconds
};

// The BVH of the scene as last built.
struct BvhInfo {
  std::string splits;  // "object" or "spatial"
  uint32_t nodes = 0, leaves = 0, depth = 0, references = 0;
  double sahCost = 0.0;
  double rejectedSahCost = 0.0;  // the cost of the split kind not kept (splits "auto"); else 0
  double buildMs = 0.0;
};

// The counts of a scene: as loaded, and (lights, degenerate triangles, BVH, texture
// bytes) as last built for a render, zero before the first.
struct SceneStats {
  std::string path;
  uint64_t contentHash = 0;  // FNV-1a of the file and what it references
  uint64_t triangles = 0;
  uint64_t degenerateTriangles = 0;  // of zero area, left out of the BVH
  uint64_t materials = 0;            // the file's, and vkpt's default material
  uint64_t lights = 0;               // emissive triangles and punctual lights sampled
  uint64_t textures = 0, images = 0;
  uint64_t texels = 0;                      // of the images at full size
  uint64_t textureBytes = 0;                // of every texture with its mip levels, as rendered
  bool vertexColors = false;                // COLOR_0 multiplies the base colour
  uint32_t generatedTangentPrimitives = 0;  // normal-mapped primitives given MikkTSpace tangents
  Vec3 boundsMin{}, boundsMax{};
  uint64_t memoryCounted = 0, memoryLimit = 0;  // bytes
  std::optional<uint32_t> variant, animation;   // as chosen (SceneOptions or Update)
  double animationTime = 0.0;                   // the pose last built
  std::vector<std::string> warnings;
  std::vector<std::string> ignoredFeatures;  // what the file uses that vkpt does not render
  BvhInfo bvh;
};

}  // namespace v1
}  // namespace vkpt
