// The light table of shared/lights.h: every light of the scene in one distribution,
// chosen with probability ∝ estimated power.
#pragma once

#include "render/light_tree.h"
#include "render/render_scene.h"

namespace vkpt::internal {

// Fills rs.lights from the emissive triangles of rs.triangles (one entry per scene
// triangle: spatial-split copies are one light) and the scene's punctual lights, and sets
// each triangle's `light`. Power estimates (pbrt-v4's Light::Phi), in luminance:
//   triangle     π · area · Le (times its emissive texture's mean; a triangle whose
//                texture is black is no light), twice that when two-sided
//   point        4π · I
//   spot         2π · (1 − (cos inner + cos outer)/2) · I
//   directional  π · R² · E, R the radius of the scene's bounding sphere
void BuildLightTable(const Scene& scene, RenderScene& rs);

// Adds rs.environment (which must hold a map) to the table as one more light, of power
// 4π² R² · L̄ · intensity with L̄ its mean luminance per solid angle (pbrt-v4's
// ImageInfiniteLight::Phi), and renormalises the distribution.
void AddEnvironmentLight(RenderScene& rs, float intensity);

// With the tree, reorders rs.lights (and lightPower, and the triangles' `light`) to the
// tree's leaf order with the directional lights and the environment after them, and sets
// rs.lightTree. The table's distribution keeps each light's power-proportional share in
// total: the finite lights' together is the tree's, the rest keep theirs. A tree needs two
// lights; with fewer, or kPower, the table stays as it is.
void ChooseLightSampler(RenderScene& rs, LightSampler sampler);

// The bounds of finite light `l` (its power estimate `power`) for the light tree.
LightBounds LightBoundsOf(const RenderScene& rs, const shader::Light& l, double power);

}  // namespace vkpt::internal
