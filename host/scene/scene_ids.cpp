#include "scene/scene_ids.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "util/error.h"

namespace vkpt::internal {

TriangleIds IdsOfTriangle(const Scene& scene, uint32_t triangle) {
  TriangleIds ids;
  if (triangle >= scene.triangles.size()) return ids;
  ids.material = scene.triangles[triangle].material;
  // The last run starting at or before the triangle (runs are in triangle order).
  const std::vector<TriangleRun>& runs = scene.triangleRuns;
  auto after = std::upper_bound(runs.begin(), runs.end(), triangle,
                                [](uint32_t t, const TriangleRun& run) { return t < run.firstTriangle; });
  if (after == runs.begin()) return ids;
  const uint32_t instance = std::prev(after)->instance;
  ids.instance = instance;
  ids.object = scene.meshInstances.at(instance).node;
  return ids;
}

IdCounts IdCountsOf(const Scene& scene) {
  return {scene.nodeNames.size(), scene.materials.size(), scene.meshInstances.size()};
}

void CheckIdsAreExact(const IdCounts& counts, const std::string& file) {
  const std::pair<const char*, uint64_t> kinds[] = {
      {"nodes", counts.objects}, {"materials", counts.materials}, {"mesh instances", counts.instances}};
  for (const auto& [kind, count] : kinds)
    if (count > uint64_t(kLargestExactId) + 1)
      throw Error(file + ": the id AOVs cannot label " + std::to_string(count) + " " + kind +
                  ": ids beyond 2^24 are not exact in float32");
}

std::string IdsJson(const Scene& scene) {
  nlohmann::ordered_json objects = nlohmann::ordered_json::array(), materials = nlohmann::ordered_json::array(),
                         instances = nlohmann::ordered_json::array();
  std::vector<bool> listed(scene.nodeNames.size(), false);
  for (size_t i = 0; i < scene.meshInstances.size(); ++i) {
    const MeshInstance& m = scene.meshInstances[i];
    instances.push_back({{"id", i}, {"object_id", m.node}, {"placement", m.placement}});
    if (m.node < listed.size() && !listed[m.node]) {
      listed[m.node] = true;
      objects.push_back({{"id", m.node}, {"name", scene.nodeNames[m.node]}, {"mesh", scene.meshNames.at(m.mesh)}});
    }
  }
  std::sort(objects.begin(), objects.end(),
            [](const nlohmann::ordered_json& a, const nlohmann::ordered_json& b) { return a["id"] < b["id"]; });
  for (size_t i = 0; i < scene.materialNames.size(); ++i)
    materials.push_back({{"id", i}, {"name", scene.materialNames[i]}});
  nlohmann::ordered_json doc = {
      {"none", -1}, {"object_id", objects}, {"material_id", materials}, {"instance_id", instances}};
  // Names are the file's (UTF-8 checked by the parser); replace anything else rather than throw.
  return doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace vkpt::internal
