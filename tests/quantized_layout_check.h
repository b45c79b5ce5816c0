// The GPU's BVH layout (bvh/quantized_layout.h) checked against the triangles it indexes:
// each copy a complete tree over every leaf-order triangle, parent links and slots that
// lead back up, quantised boxes that contain everything below them.
#pragma once

#include "render/render_scene.h"
#include "util/bounds.h"

namespace vkpt::internal::test {

// The box of a leaf-order triangle's three vertices.
Bounds3f TriangleBounds(const shader::Triangle& t);

// With `spatial` a leaf's triangles need only overlap its box (spatial splits clip them).
void CheckQuantizedLayout(const RenderScene& rs, bool spatial);

}  // namespace vkpt::internal::test
