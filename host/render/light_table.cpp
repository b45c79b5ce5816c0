#include "render/light_table.h"

#include <algorithm>
#include <cmath>

#include "render/scene_access.h"
#include "shared/material_textures.h"
#include "shared/sampling.h"

namespace vkpt::internal {
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

// The mean of triangle t's emissive texture (1 without one), from 16 stratified points
// read at the mip level whose texels are about the size of a sixteenth of the
// triangle's footprint in the texture: what its emission is, on average, for choosing it
// as a light. Only an estimate (MIS keeps the image unbiased whatever it is), and 0 for a
// triangle whose texture is black, which light sampling then never picks.
glm::dvec3 MeanEmissiveTexture(const RenderScene& scene, const shader::Triangle& t) {
  if (scene.textureRefs.empty()) return glm::dvec3(1.0);
  const shader::TextureRef ref = scene.textureRefs[t.material * shader::kTextureSlots + shader::kSlotEmissive];
  if (ref.texture == shader::kInvalidIndex) return glm::dvec3(1.0);
  const shader::Texture& tex = scene.textures[ref.texture];
  const shader::TriangleUVs& uvs = scene.uvs[t.sourceIndex];
  auto uvAt = [&](float b1, float b2) {
    return shader::TransformUV(ref, shader::InterpolatedUV(uvs, ref.texCoord, b1, b2));
  };
  auto texelAt = [&](float b1, float b2) { return glm::dvec2(uvAt(b1, b2)) * glm::dvec2(tex.width, tex.height); };
  const glm::dvec2 e1 = texelAt(1, 0) - texelAt(0, 0), e2 = texelAt(0, 1) - texelAt(0, 0);
  const double texels = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
  const float lod = texels > 16.0 ? float(0.5 * std::log2(texels / 16.0)) : 0.0f;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      glm::vec2 b = shader::SampleUniformTriangle((i + 0.5f) / 4.0f, (j + 0.5f) / 4.0f);
      sum +=
          glm::dvec3(shader::SampleTexture(scene, tex, uvAt(b.x, b.y), lod, shader::SlotIsSrgb(shader::kSlotEmissive)));
    }
  return sum / 16.0;
}

}  // namespace

shader::Light PunctualLightEntry(const PunctualLight& p) {
  shader::Light l{};
  l.position = p.position;
  l.direction = p.direction;
  l.radiance = p.intensity;
  l.extent = p.range;
  l.cosInner = p.cosInner;
  l.cosOuter = p.cosOuter;
  l.triangle = shader::kInvalidIndex;
  switch (p.type) {
    case PunctualLight::Type::kPoint: l.type = shader::kLightPoint; break;
    case PunctualLight::Type::kSpot: l.type = shader::kLightSpot; break;
    case PunctualLight::Type::kDirectional: l.type = shader::kLightDirectional; break;
  }
  return l;
}

double PunctualPower(const shader::Light& l, double sceneRadius) {
  double lum = shader::Luminance(l.radiance);
  switch (l.type) {
    case shader::kLightPoint: return 4.0 * shader::kPi * lum;
    case shader::kLightSpot: return 2.0 * shader::kPi * (1.0 - 0.5 * (l.cosInner + l.cosOuter)) * lum;
    default: return shader::kPi * sceneRadius * sceneRadius * lum;
  }
}

void BuildLightTable(const Scene& scene, RenderScene& rs) {
  std::vector<double> power;
  std::vector<uint32_t> lightOfSource(scene.triangles.size(), shader::kInvalidIndex);
  for (uint32_t i = 0; i < rs.triangles.size(); ++i) {
    shader::Triangle& t = rs.triangles[i];
    t.light = lightOfSource[t.sourceIndex];
    if (t.light != shader::kInvalidIndex) continue;  // a spatial-split copy of a listed light
    const shader::Material& m = rs.materials[t.material];
    glm::dvec3 n = glm::cross(glm::dvec3(t.e1), glm::dvec3(t.e2));
    double area = 0.5 * glm::length(n);
    double lum = shader::Luminance(m.emission);
    if (!(area > 0.0) || !(lum > 0.0) || (m.flags & shader::kMaterialUnlit)) continue;
    lum = shader::Luminance(glm::vec3(glm::dvec3(m.emission) * MeanEmissiveTexture(rs, t)));
    if (!(lum > 0.0)) continue;
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
  const double sceneRadius = 0.5 * glm::length(glm::dvec3(scene.bounds.hi - scene.bounds.lo));
  for (const PunctualLight& p : scene.lights) {
    shader::Light l = PunctualLightEntry(p);
    double phi = PunctualPower(l, sceneRadius);
    if (!(phi > 0.0)) continue;  // black, or a spot of zero cone: it lights nothing
    rs.lights.push_back(l);
    power.push_back(phi);
  }
  rs.sceneRadius = sceneRadius;
  rs.lightPower = std::move(power);
  rs.totalEmittedPower = 0.0;
  for (double p : rs.lightPower) rs.totalEmittedPower += p;
  SetDistribution(rs.lightPower, rs.lights);
}

void AddEnvironmentLight(RenderScene& rs, float intensity) {
  const EnvironmentMap& env = rs.environment;
  double sum = 0.0, weight = 0.0;
  for (uint32_t y = 0; y < env.height; ++y) {
    double sinTheta = std::sin(shader::kPi * (y + 0.5) / env.height);
    for (uint32_t x = 0; x < env.width; ++x)
      sum += sinTheta * shader::Luminance(glm::vec3(env.texels[size_t(y) * env.width + x]));
    weight += sinTheta * env.width;
  }
  double phi = 4.0 * shader::kPi * shader::kPi * rs.sceneRadius * rs.sceneRadius * intensity * sum / weight;
  if (!(phi > 0.0)) return;  // a black map lights nothing: escaped rays still see it
  shader::Light l{};
  l.type = shader::kLightEnvironment;
  l.triangle = shader::kInvalidIndex;
  rs.lights.push_back(l);
  rs.lightPower.push_back(phi);
  rs.totalEmittedPower += phi;
  SetDistribution(rs.lightPower, rs.lights);
}

namespace {

bool IsFiniteLight(const shader::Light& l) {
  return l.type != shader::kLightDirectional && l.type != shader::kLightEnvironment;
}

}  // namespace

LightBounds LightBoundsOf(const RenderScene& rs, const shader::Light& l, double power) {
  LightBounds b;
  b.axis = glm::dvec3(l.direction);
  if (l.type == shader::kLightTriangle || l.type == shader::kLightTwoSidedTriangle) {
    const shader::Triangle& t = rs.triangles[l.triangle];
    glm::dvec3 v0(t.v0), v1 = v0 + glm::dvec3(t.e1), v2 = v0 + glm::dvec3(t.e2);
    b.lo = glm::min(v0, glm::min(v1, v2));
    b.hi = glm::max(v0, glm::max(v1, v2));
    b.twoSided = l.type == shader::kLightTwoSidedTriangle;
    b.intensity = power / (shader::kPi * (b.twoSided ? 2.0 : 1.0));  // Le · area, along the normal
    b.cosThetaO = 1.0;  // every point emits around the normal, cosine-weighted to θe = π/2
    b.cosThetaE = 0.0;
    return b;
  }
  b.lo = b.hi = glm::dvec3(l.position);
  b.intensity = shader::Luminance(l.radiance);
  if (l.type == shader::kLightSpot) {  // full within the inner cone, fading to the outer
    double inner = std::acos(std::clamp(double(l.cosInner), -1.0, 1.0));
    double outer = std::acos(std::clamp(double(l.cosOuter), -1.0, 1.0));
    b.cosThetaO = std::cos(inner);
    b.cosThetaE = std::cos(std::max(0.0, outer - inner));
  } else {  // a point light: every direction
    b.cosThetaO = -1.0;
    b.cosThetaE = 0.0;
  }
  return b;
}

void ChooseLightSampler(RenderScene& rs, LightSampler sampler) {
  std::vector<uint32_t> finite, infinite;
  for (uint32_t i = 0; i < rs.lights.size(); ++i) (IsFiniteLight(rs.lights[i]) ? finite : infinite).push_back(i);
  const size_t needed = sampler == LightSampler::kTree ? 2 : kLightTreeMinLights;
  if (sampler == LightSampler::kPower || finite.size() < needed) return;
  std::vector<LightBounds> bounds;
  bounds.reserve(finite.size());
  for (uint32_t i : finite) bounds.push_back(LightBoundsOf(rs, rs.lights[i], rs.lightPower[i]));
  LightTree tree = BuildLightTree(bounds);
  std::vector<uint32_t> order;  // new index → old
  order.reserve(rs.lights.size());
  for (uint32_t k : tree.order) order.push_back(finite[k]);
  order.insert(order.end(), infinite.begin(), infinite.end());
  std::vector<uint32_t> newIndex(rs.lights.size());
  std::vector<shader::Light> lights(rs.lights.size());
  std::vector<double> power(rs.lights.size());
  for (uint32_t k = 0; k < order.size(); ++k) {
    newIndex[order[k]] = k;
    lights[k] = rs.lights[order[k]];
    power[k] = rs.lightPower[order[k]];
  }
  for (shader::Triangle& t : rs.triangles)
    if (t.light != shader::kInvalidIndex) t.light = newIndex[t.light];
  rs.lights = std::move(lights);
  rs.lightPower = std::move(power);
  SetDistribution(rs.lightPower, rs.lights);
  rs.lightTree = std::move(tree.nodes);
  rs.treeLights = uint32_t(finite.size());
  rs.lightTreeDepth = tree.depth;
}

}  // namespace vkpt::internal
