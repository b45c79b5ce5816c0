#include "image/image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>

#include "image/image_encode.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/regular_file.h"

namespace vkpt::internal {
namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

ImageFormat FormatFromPath(const std::string& path) {
  std::string p = Lower(path);
  if (EndsWith(p, ".png")) return ImageFormat::Png;
  if (EndsWith(p, ".pfm")) return ImageFormat::Pfm;
  if (EndsWith(p, ".exr")) return ImageFormat::Exr;
  throw Error(path + ": unknown image format (use .png, .pfm or .exr)");
}

void CheckOutputPath(const std::string& path) {
  FormatFromPath(path);
  CheckWritablePath(path, "an image");
}

uint8_t LinearToSrgb8(float linear) {
  float v = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
  float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(s * 255.0f));
}

void WriteImage(const Image& image, const std::string& path, const DisplayTransform& display) {
  ImageFormat format = FormatFromPath(path);
  if (image.pixels.empty()) throw Error(path + ": refusing to write an empty image");
  std::vector<uint8_t> bytes;
  switch (format) {
    case ImageFormat::Png: bytes = EncodePng(image, display); break;
    case ImageFormat::Pfm: bytes = EncodePfm(image); break;
    case ImageFormat::Exr: bytes = EncodeExr(image, path); break;
  }
  WriteFileAtomically(path, bytes);
}

Image ReadPfm(const std::string& path) {
  std::string problem;
  std::optional<RegularFile> file = RegularFile::Open(path, &problem);
  if (!file) throw Error(path + ": " + problem);
  // The header is three text lines; nothing is allocated for pixels until the file's
  // size has shown that they are there.
  std::string head(size_t(std::min<uint64_t>(file->Size(), 256)), '\0');
  if (!file->ReadAt(0, head.data(), head.size(), &problem)) throw Error(path + ": " + problem);
  std::istringstream in(head);
  std::string magic;
  long long w = 0, h = 0;
  double scale = 0.0;
  in >> magic >> w >> h >> scale;
  in.get();  // the single whitespace after the scale
  if (!in || magic != "PF" || w <= 0 || h <= 0 || w > 65536 || h > 65536 || scale == 0.0)
    throw Error(path + ": not a 3-channel PFM image");
  const uint64_t offset = uint64_t(in.tellg()), bytes = uint64_t(w) * uint64_t(h) * sizeof(glm::vec3);
  if (file->Size() - offset < bytes)
    throw Error(path + ": PFM data is truncated (" + std::to_string(w) + "x" + std::to_string(h) + " needs " +
                std::to_string(bytes) + " bytes, the file holds " + std::to_string(file->Size() - offset) + ")");
  Image img{uint32_t(w), uint32_t(h)};
  const size_t row = sizeof(glm::vec3) * img.width;
  for (uint32_t y = img.height; y-- > 0;)  // PFM stores the bottom row first
    if (!file->ReadAt(offset + uint64_t(img.height - 1 - y) * row, &img.pixels[size_t(y) * img.width], row, &problem))
      throw Error(path + ": " + problem);
  if (scale > 0.0)  // positive scale: big-endian data
    for (glm::vec3& p : img.pixels)
      for (int c = 0; c < 3; ++c) {
        uint32_t u;
        std::memcpy(&u, &p[c], 4);
        u = __builtin_bswap32(u);
        std::memcpy(&p[c], &u, 4);
      }
  // A radiance image holds finite values (vkpt writes no others); NaN or infinity would
  // turn every statistic of --diff into NaN.
  for (size_t i = 0; i < img.pixels.size(); ++i)
    if (!std::isfinite(img.pixels[i].x) || !std::isfinite(img.pixels[i].y) || !std::isfinite(img.pixels[i].z))
      throw Error(path + ": pixel (" + std::to_string(i % img.width) + ", " + std::to_string(i / img.width) +
                  ") is not a finite number (NaN or infinity)");
  return img;
}

}  // namespace vkpt::internal
