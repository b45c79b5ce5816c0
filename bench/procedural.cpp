#include "procedural.h"

#include <cmath>

namespace vkpt::internal::bench {
namespace {

// Smooth deterministic "noise": a few incommensurate sine waves (no RNG state, so the
// scene never depends on library versions).
float Bumps(float x, float y, float z) {
  return 0.5f * std::sin(3.1f * x + 1.3f) * std::sin(2.7f * y + 0.4f) * std::sin(3.3f * z + 2.1f) +
         0.25f * std::sin(11.0f * x + 5.0f * z) * std::sin(9.0f * y + 0.7f) +
         0.12f * std::sin(29.0f * y + 23.0f * x) * std::cos(31.0f * z);
}

void AddQuad(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t m) {
  s.triangles.push_back({a, b, c, m});
  s.triangles.push_back({a, c, d, m});
}

}  // namespace

Scene ProceduralScene(uint32_t triangles) {
  Scene s;
  s.path = "(procedural " + std::to_string(triangles) + ")";
  auto material = [&](glm::vec3 albedo, glm::vec3 emission, const char* name) {
    Material m{};
    m.baseColor = albedo;
    m.emission = emission;
    m.roughness = 1.0f;
    s.materials.push_back(m);
    s.materialNames.push_back(name);
    return uint32_t(s.materials.size() - 1);
  };
  const uint32_t grey = material(glm::vec3(0.7f), glm::vec3(0.0f), "grey");
  const uint32_t orange = material(glm::vec3(0.8f, 0.45f, 0.2f), glm::vec3(0.0f), "orange");
  const uint32_t light = material(glm::vec3(0.0f), glm::vec3(20.0f, 18.0f, 15.0f), "light");

  // Box walls (open towards +Z, where the camera is) and the light: 12 triangles.
  const float w = 4.0f;
  AddQuad(s, {-w, -1, -w}, {-w, -1, w}, {-w, 2 * w, w}, {-w, 2 * w, -w}, grey);
  AddQuad(s, {w, -1, -w}, {w, 2 * w, -w}, {w, 2 * w, w}, {w, -1, w}, grey);
  AddQuad(s, {-w, -1, -w}, {-w, 2 * w, -w}, {w, 2 * w, -w}, {w, -1, -w}, grey);
  AddQuad(s, {-w, 2 * w, -w}, {-w, 2 * w, w}, {w, 2 * w, w}, {w, 2 * w, -w}, grey);
  AddQuad(s, {-1, 2 * w - 0.01f, -1}, {1, 2 * w - 0.01f, -1}, {1, 2 * w - 0.01f, 1}, {-1, 2 * w - 0.01f, 1}, light);

  const uint32_t budget = triangles > s.triangles.size() + 8 ? triangles - uint32_t(s.triangles.size()) : 8;
  // Terrain: an n×n grid of quads over [-w, w]², height from the bump function.
  const uint32_t n = std::max(2u, uint32_t(std::sqrt(double(budget / 2) / 2.0)));
  auto terrain = [&](uint32_t i, uint32_t j) {
    float x = -w + 2 * w * float(i) / n, z = -w + 2 * w * float(j) / n;
    return glm::vec3(x, -1.0f + 0.3f * Bumps(0.3f * x, 0.0f, 0.3f * z), z);
  };
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = 0; j < n; ++j) AddQuad(s, terrain(i, j), terrain(i, j + 1), terrain(i + 1, j + 1), terrain(i + 1, j), grey);
  // Sphere: a UV sphere of m×2m quads (2·m·2m triangles), radius displaced by the bumps.
  const uint32_t rest = triangles > s.triangles.size() ? triangles - uint32_t(s.triangles.size()) : 8;
  const uint32_t m = std::max(2u, uint32_t(std::sqrt(double(rest) / 4.0)));
  auto sphere = [&](uint32_t i, uint32_t j) {
    float theta = 3.14159265f * float(i) / m, phi = 6.2831853f * float(j % (2 * m)) / (2 * m);
    glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    return glm::vec3(0.0f, 1.2f, 0.0f) + d * (1.6f + 0.15f * Bumps(d.x, d.y, d.z));
  };
  for (uint32_t i = 0; i < m; ++i)
    for (uint32_t j = 0; j < 2 * m; ++j) AddQuad(s, sphere(i, j), sphere(i + 1, j), sphere(i + 1, j + 1), sphere(i, j + 1), orange);

  for (const SceneTriangle& t : s.triangles) {
    s.bounds.Extend(t.v0);
    s.bounds.Extend(t.v1);
    s.bounds.Extend(t.v2);
  }
  Camera cam;
  cam.name = "procedural";
  cam.position = glm::vec3(0.0f, 2.5f, 11.0f);
  cam.forward = glm::normalize(glm::vec3(0.0f, 1.2f, 0.0f) - cam.position);
  cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
  cam.up = glm::cross(cam.right, cam.forward);
  cam.yfov = 0.75f;
  s.cameras.push_back(cam);
  return s;
}

}  // namespace vkpt::internal::bench
