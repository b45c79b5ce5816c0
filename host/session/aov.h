// AOVs (arbitrary output variables, shaders/shared/aov.h): which ones there are, their
// values per pixel from a render's sums, and how they are written beside the image.
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

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"
#include "render/film.h"

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

// Whether the AOV comes from the AOV pass (FrameRenderer::RenderAovs); variance and spp
// come from the render's own sums.
bool NeedsAovPass(Aov aov);
bool NeedsAovPass(const std::vector<Aov>& aovs);  // any of them

// Whether the AOV is an id (object_id, material_id, instance_id); any of them.
bool IsIdAov(Aov aov);
bool WantsIds(const std::vector<Aov>& aovs);

// The ids of a scene triangle (AovPixelSums::triangle) for the id AOVs: object, material,
// instance, −1 for none; the caller knows the scene (engine/loaded_scene.h).
using TriangleIdsOf = std::function<std::array<int64_t, 3>(uint32_t triangle)>;

// Float channels of these AOVs' layers (3 for albedo, 1 for depth, …).
uint32_t AovChannels(const std::vector<Aov>& aovs);

// One AOV of the image: `channels` values per pixel, interleaved, named in EXR as
// "<name>.<channel suffix>".
struct AovLayer {
  Aov aov;
  std::vector<std::string> suffixes;  // {"R", "G", "B"}, {"X", "Y", "Z"}, {"Z"} or {"Y"}
  std::vector<float> values;          // width · height · suffixes.size()
};

// The requested AOVs of a render: `aovSums` (read only if some AOV needs the pass),
// the render's sums and its image (for the variance), the ids of a triangle (called only
// for an id AOV). Throws Error for an id beyond float32's exact integers (2^24).
std::vector<AovLayer> ResolveAovs(const std::vector<Aov>& wanted, const AovSums& aovSums, const FrameSums& sums,
                                  const Image& image, const TriangleIdsOf& idsOf);

// A file beside the image `out` = NAME.EXT: NAME.<tag>.EXT (NAME.raw.png, …).
std::string SiblingPath(const std::string& out, const std::string& tag);

// Where AOV `aov` of the image `out` goes when `out` is not an EXR: NAME.albedo.EXT beside it.
std::string AovPath(const std::string& out, Aov aov);

// Where the names of the ids go: NAME.ids.json beside the image `out` = NAME.EXT.
std::string IdsPath(const std::string& out);

// Writes the image to `out` and the AOVs with it: as layers of the same EXR when `out`
// is .exr, else each to AovPath (PNG: a picture of the values, see aov.cpp; PFM: the
// values, a single channel repeated in R, G and B); `idsJson`, unless empty, to IdsPath.
// Each file is written atomically. Returns the files written, `out` first.
std::vector<std::string> WriteImageWithAovs(const Image& image, const std::vector<AovLayer>& layers,
                                            const std::string& out, const DisplayTransform& display,
                                            const std::string& idsJson = "");

}  // namespace vkpt::internal
