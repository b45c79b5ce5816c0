// AOVs (arbitrary output variables, shaders/shared/aov.h) as images: which ones there
// are, their names and channels, and one AOV's values per pixel (AovLayer). What fills
// them from a render is session/aov.h; how they are written, image/aov_files.h.
//
// Conventions (docs/aovs.md): linear values, NaN-free, row 0 at the top.
//   albedo    RGB   linear base colour of the first non-specular hit (see aov.h)
//   normal    XYZ   its world-space shading normal facing the camera, averaged (0: none)
//   depth     Z     distance along the camera ray to the first hit (0: nothing hit)
//   position  XYZ   the first hit's world position (0: nothing hit)
//   variance  RGB   variance of the pixel's mean radiance (the image's noise)
//   spp       Y     samples the pixel took (adaptive sampling varies it)
//   heatmap   Y     BVH boxes tested per camera ray (the backend's own walk)
//   object_id, material_id, instance_id
//             ID    the glTF node, material and mesh instance of what a ray through the
//                   pixel's centre hits first, an exact integer (−1: nothing)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vkpt::internal {

enum class Aov : uint8_t {
  kAlbedo,
  kNormal,
  kDepth,
  kPosition,
  kVariance,
  kSpp,
  kHeatmap,
  kObjectId,
  kMaterialId,
  kInstanceId
};
constexpr int kAovCount = 10;

const char* AovName(Aov aov);  // "albedo", …
std::optional<Aov> AovFromName(std::string_view name);

// The AOVs named, in order, each once; "all" names every AOV. Throws Error for an
// unknown name, listing the known ones.
std::vector<Aov> AovsFromNames(const std::vector<std::string>& names);

// Whether the AOV is an id (object_id, material_id, instance_id); any of them.
bool IsIdAov(Aov aov);
bool WantsIds(const std::vector<Aov>& aovs);

// The channel suffixes of the AOV's values, in their order: {"R", "G", "B"},
// {"X", "Y", "Z"}, {"Z"}, {"Y"} or {"ID"}.
std::vector<std::string> AovSuffixes(Aov aov);

// One AOV of the image: `channels` values per pixel, interleaved, named in EXR as
// "<name>.<channel suffix>".
struct AovLayer {
  Aov aov;
  std::vector<std::string> suffixes;  // {"R", "G", "B"}, {"X", "Y", "Z"}, {"Z"} or {"Y"}
  std::vector<float> values;          // width · height · suffixes.size()
};

}  // namespace vkpt::internal
