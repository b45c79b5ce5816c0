#include "render/light_table.h"

#include "shared/sampling.h"

namespace vkpt {
namespace {

// Turns the lights' power estimates into the pmf and inclusive CDF the shaders search.
void SetDistribution(const std::vector<double>& power, std::vector<shader::Light>& lights) {
  double total = 0.0;
  for (double p : power) total += p;
  double running = 0.0;
  float prevCdf = 0.0f;
  for (size_t k = 0; k < lights.size(); ++k) {
    running += power[k];
    float cdf = k + 1 == lights.size() ? 1.0f : float(running / total);
    lights[k].cdf = cdf;
    // The probability a uniform u ∈ [0,1) really lands in [prevCdf, cdf): what the
    // estimator must divide by.
    lights[k].pmf = cdf - prevCdf;
    prevCdf = cdf;
  }
}

}  // namespace

void BuildLightTable(size_t sceneTriangles, RenderScene& rs) {
  std::vector<double> power;
  std::vector<uint32_t> lightOfSource(sceneTriangles, shader::kInvalidIndex);
  for (uint32_t i = 0; i < rs.triangles.size(); ++i) {
    shader::Triangle& t = rs.triangles[i];
    t.light = lightOfSource[t.sourceIndex];
    if (t.light != shader::kInvalidIndex) continue;  // a spatial-split copy of a listed light
    const shader::Material& m = rs.materials[t.material];
    glm::dvec3 n = glm::cross(glm::dvec3(t.e1), glm::dvec3(t.e2));
    double area = 0.5 * glm::length(n);
    double lum = shader::Luminance(m.emission);
    if (!(area > 0.0) || !(lum > 0.0) || (m.flags & shader::kMaterialUnlit)) continue;
    bool twoSided = (m.flags & shader::kMaterialDoubleSided) != 0;
    shader::Light l{};
    l.type = twoSided ? shader::kLightTwoSidedTriangle : shader::kLightTriangle;
    l.triangle = i;
    l.direction = glm::vec3(glm::normalize(n));
    l.radiance = m.emission;
    l.extent = float(area);
    t.light = lightOfSource[t.sourceIndex] = uint32_t(rs.lights.size());
    rs.lights.push_back(l);
    power.push_back(shader::kPi * area * lum * (twoSided ? 2.0 : 1.0));
  }
  rs.totalEmittedPower = 0.0;
  for (double p : power) rs.totalEmittedPower += p;
  SetDistribution(power, rs.lights);
}

}  // namespace vkpt
