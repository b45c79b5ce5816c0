// Where a render's AOVs are written beside its image, and the writing itself: layers of
// the same EXR, or one file each (a picture of the values in PNG, the values in PFM).
#pragma once

#include <string>
#include <vector>

#include "image/aov_layer.h"
#include "image/image.h"

namespace vkpt::internal {

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
