// The light table of shared/lights.h: every light of the scene in one distribution,
// chosen with probability ∝ estimated power.
#pragma once

#include "render/render_scene.h"

namespace vkpt {

// Fills rs.lights from the emissive triangles of rs.triangles (one entry per scene
// triangle: spatial-split copies are one light) and sets each triangle's `light`.
// Power estimates: a triangle emits π · area · luminance(Le), twice that when it is
// two-sided (pbrt-v4's DiffuseAreaLight::Phi).
void BuildLightTable(size_t sceneTriangles, RenderScene& rs);

}  // namespace vkpt
