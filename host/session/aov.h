// The AOVs of a render (image/aov_layer.h names them) from its sums: which need the AOV
// pass, and each one's values per pixel.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/aov_layer.h"
#include "image/image.h"
#include "render/film.h"

namespace vkpt::internal {

// Whether the AOV comes from the AOV pass (FrameRenderer::RenderAovs); variance and spp
// come from the render's own sums.
bool NeedsAovPass(Aov aov);
bool NeedsAovPass(const std::vector<Aov>& aovs);  // any of them

// The ids of a scene triangle (AovPixelSums::triangle) for the id AOVs: object, material,
// instance, −1 for none; the caller knows the scene (engine/loaded_scene.h).
using TriangleIdsOf = std::function<std::array<int64_t, 3>(uint32_t triangle)>;

// Float channels of these AOVs' layers (3 for albedo, 1 for depth, …).
uint32_t AovChannels(const std::vector<Aov>& aovs);

// The requested AOVs of a render: `aovSums` (read only if some AOV needs the pass),
// the render's sums and its image (for the variance), the ids of a triangle (called only
// for an id AOV). Throws Error for an id beyond float32's exact integers (2^24).
std::vector<AovLayer> ResolveAovs(const std::vector<Aov>& wanted, const AovSums& aovSums, const FrameSums& sums,
                                  const Image& image, const TriangleIdsOf& idsOf);

}  // namespace vkpt::internal
