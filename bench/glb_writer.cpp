#include "glb_writer.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "util/error.h"

namespace vkpt::internal::bench {
namespace {

void Append(std::vector<uint8_t>& out, const void* data, size_t bytes) {
  const auto* p = static_cast<const uint8_t*>(data);
  out.insert(out.end(), p, p + bytes);
}

void AppendU32(std::vector<uint8_t>& out, uint32_t v) { Append(out, &v, sizeof v); }

// The scene's materials as glTF materials; `strength` tells whether any needed
// KHR_materials_emissive_strength (an emission above 1).
nlohmann::json MaterialsJson(const Scene& scene, bool& strength) {
  using nlohmann::json;
  json materials = json::array();
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& mat = scene.materials[m];
    json j = {{"name", scene.materialNames.at(m)},
              {"pbrMetallicRoughness",
               {{"baseColorFactor", {mat.baseColor.x, mat.baseColor.y, mat.baseColor.z, 1.0}},
                {"metallicFactor", mat.metallic},
                {"roughnessFactor", mat.roughness}}}};
    const float peak = std::max({mat.emission.x, mat.emission.y, mat.emission.z});
    if (peak > 0.0f) {
      const float scale = std::max(peak, 1.0f);
      const glm::vec3 e = mat.emission / scale;
      j["emissiveFactor"] = {e.x, e.y, e.z};
      if (scale > 1.0f) {
        j["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", scale}}}};
        strength = true;
      }
    }
    materials.push_back(j);
  }
  return materials;
}

// The GLB container of a glTF document and its binary chunk.
std::vector<uint8_t> GlbBytes(std::string text, std::vector<uint8_t> bin) {
  text.resize((text.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  const uint64_t total = 12 + 8 + text.size() + 8 + bin.size();
  if (total > 0xFFFFFFFFull) throw Error("the scene is too large for one GLB file (4 GiB)");
  std::vector<uint8_t> out;
  out.reserve(total);
  AppendU32(out, 0x46546C67u);  // "glTF"
  AppendU32(out, 2);
  AppendU32(out, uint32_t(total));
  AppendU32(out, uint32_t(text.size()));
  AppendU32(out, 0x4E4F534Au);  // "JSON"
  Append(out, text.data(), text.size());
  AppendU32(out, uint32_t(bin.size()));
  AppendU32(out, 0x004E4942u);  // "BIN\0"
  Append(out, bin.data(), bin.size());
  return out;
}

}  // namespace

std::vector<uint8_t> EncodeGlb(const Scene& scene) {
  using nlohmann::json;
  // Triangles grouped by material, each group one accessor of its positions.
  std::vector<std::vector<uint32_t>> byMaterial(scene.materials.size());
  for (uint32_t i = 0; i < scene.triangles.size(); ++i) byMaterial.at(scene.triangles[i].material).push_back(i);
  std::vector<uint8_t> bin;
  json accessors = json::array(), views = json::array(), primitives = json::array();
  for (uint32_t m = 0; m < byMaterial.size(); ++m) {
    if (byMaterial[m].empty()) continue;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    const size_t offset = bin.size();
    for (uint32_t i : byMaterial[m]) {
      const SceneTriangle& t = scene.triangles[i];
      for (const glm::vec3& v : {t.v0, t.v1, t.v2}) {
        Append(bin, &v, sizeof v);
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    }
    const uint64_t count = uint64_t(byMaterial[m].size()) * 3;
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", count * 12}});
    accessors.push_back({{"bufferView", views.size() - 1},
                         {"componentType", 5126},
                         {"count", count},
                         {"type", "VEC3"},
                         {"min", {lo.x, lo.y, lo.z}},
                         {"max", {hi.x, hi.y, hi.z}}});
    primitives.push_back({{"attributes", {{"POSITION", accessors.size() - 1}}}, {"material", m}});
  }
  bool strength = false;  // some material needs KHR_materials_emissive_strength
  const nlohmann::json materials = MaterialsJson(scene, strength);
  json nodes = {{{"mesh", 0}}};
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "vkpt-bench"}}},
               {"scene", 0},
               {"buffers", {{{"byteLength", bin.size()}}}},
               {"bufferViews", views},
               {"accessors", accessors},
               {"materials", materials},
               {"meshes", {{{"primitives", primitives}}}}};
  if (!scene.cameras.empty()) {
    const Camera& c = scene.cameras[0];
    // The camera looks along its node's −Z with +Y up: columns right, up, −forward.
    const glm::quat q = glm::quat_cast(glm::mat3(c.right, c.up, -c.forward));
    nodes.push_back({{"camera", 0},
                     {"translation", {c.position.x, c.position.y, c.position.z}},
                     {"rotation", {q.x, q.y, q.z, q.w}}});
    gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", c.yfov}, {"znear", 0.01}}}}};
  }
  gltf["nodes"] = nodes;
  gltf["scenes"] = {{{"nodes", nodes.size() == 2 ? json{0, 1} : json{0}}}};
  if (strength) gltf["extensionsUsed"] = {"KHR_materials_emissive_strength"};

  return GlbBytes(gltf.dump(), std::move(bin));
}

}  // namespace vkpt::internal::bench
