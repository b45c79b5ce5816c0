#include "image/aov_files.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "image/image_encode.h"
#include "util/atomic_write.h"

namespace vkpt::internal {
namespace {

// Google's Turbo colour map (Mikhailov 2019) by its polynomial fit, for x in [0, 1]:
// dark blue for 0, through green and yellow, to dark red for 1.
glm::vec3 Turbo(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  auto poly = [x](const std::array<float, 6>& c) {
    return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * (c[4] + x * c[5]))));
  };
  return glm::clamp(
      glm::vec3(poly({0.13572138f, 4.61539260f, -42.66032258f, 132.13108234f, -152.94239396f, 59.28637943f}),
                poly({0.09140261f, 2.19418839f, 4.84296658f, -14.18503333f, 4.27729857f, 2.82956604f}),
                poly({0.10667330f, 12.64194608f, -60.58204836f, 110.36276771f, -89.90310912f, 27.34824973f})),
      0.0f, 1.0f);
}

uint8_t Byte(float unit) { return uint8_t(std::lround(std::clamp(unit, 0.0f, 1.0f) * 255.0f)); }

// The PNG colour of an id: black for −1 (nothing), else a bright colour hashed from the
// id (a PCG step), so that neighbouring ids stand apart.
glm::vec3 IdColour(float id) {
  if (id < 0.0f) return glm::vec3(0.0f);
  uint32_t h = uint32_t(id) * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  h = (h >> 22u) ^ h;
  return glm::vec3(0.25f) + 0.75f * glm::vec3(h & 0xFFu, (h >> 8) & 0xFFu, (h >> 16) & 0xFFu) / 255.0f;
}

// The PNG picture of an AOV: albedo through the sRGB curve; normals as n/2 + 1/2 (a
// normal map's colours); positions scaled per axis to the image's range; depth as grey
// from black (0) to white (the farthest); variance (the channels' mean), spp and the
// heat map through Turbo from 0 to the image's largest value; ids as colours (IdColour).
std::vector<uint8_t> Picture(const AovLayer& layer, size_t pixels) {
  const size_t channels = layer.suffixes.size();
  std::vector<uint8_t> rgb(pixels * 3);
  auto scalar = [&](size_t i) {
    if (channels == 1) return layer.values[i];
    return (layer.values[3 * i] + layer.values[3 * i + 1] + layer.values[3 * i + 2]) / 3.0f;
  };
  float largest = 0.0f;
  glm::vec3 lo(0.0f), hi(0.0f);
  for (size_t i = 0; i < pixels; ++i) {
    largest = std::max(largest, scalar(i));
    if (layer.aov == Aov::kPosition) {
      const glm::vec3 v(layer.values[3 * i], layer.values[3 * i + 1], layer.values[3 * i + 2]);
      lo = i == 0 ? v : glm::min(lo, v);
      hi = i == 0 ? v : glm::max(hi, v);
    }
  }
  const float scale = largest > 0.0f ? 1.0f / largest : 0.0f;
  for (size_t i = 0; i < pixels; ++i) {
    glm::vec3 bytes;
    switch (layer.aov) {
      case Aov::kAlbedo:
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = LinearToSrgb8(layer.values[3 * i + c]);
        continue;
      case Aov::kNormal:
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = Byte(layer.values[3 * i + c] * 0.5f + 0.5f);
        continue;
      case Aov::kPosition:
        for (int c = 0; c < 3; ++c)
          rgb[3 * i + c] = Byte(hi[c] > lo[c] ? (layer.values[3 * i + c] - lo[c]) / (hi[c] - lo[c]) : 0.0f);
        continue;
      case Aov::kDepth: bytes = glm::vec3(scalar(i) * scale); break;
      case Aov::kObjectId:
      case Aov::kMaterialId:
      case Aov::kInstanceId: bytes = IdColour(scalar(i)); break;
      default: bytes = Turbo(scalar(i) * scale); break;
    }
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = Byte(bytes[c]);
  }
  return rgb;
}

// The AOV as an RGB float image (a single channel in all three), for PFM.
Image AsImage(const AovLayer& layer, uint32_t width, uint32_t height) {
  Image im(width, height);
  const size_t channels = layer.suffixes.size();
  for (size_t i = 0; i < im.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) im.pixels[i][c] = layer.values[i * channels + (channels == 1 ? 0 : c)];
  return im;
}

// `out` split into NAME and .EXT (.EXT empty when its last component has no dot).
std::pair<std::string, std::string> StemAndExtension(const std::string& out) {
  const size_t dot = out.find_last_of('.');
  const size_t slash = out.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {out, ""};
  return {out.substr(0, dot), out.substr(dot)};
}

// WriteImageWithAovs without the ids' names.
std::vector<std::string> WriteImageAndLayers(const Image& image, const std::vector<AovLayer>& layers,
                                             const std::string& out, const DisplayTransform& display) {
  const ImageFormat format = FormatFromPath(out);
  if (format != ImageFormat::Exr || layers.empty()) {
    WriteImage(image, out, display);
    std::vector<std::string> files = {out};
    for (const AovLayer& layer : layers) {
      const std::string path = AovPath(out, layer.aov);
      if (format == ImageFormat::Png)
        WriteFileAtomically(path, EncodePngRgb8(image.width, image.height, Picture(layer, image.pixels.size())));
      else WriteImage(AsImage(layer, image.width, image.height), path);
      files.push_back(path);
    }
    return files;
  }
  std::vector<ExrChannel> channels = RgbChannels(image);
  for (const AovLayer& layer : layers) {
    const size_t n = layer.suffixes.size();
    for (size_t c = 0; c < n; ++c) {
      ExrChannel ch{std::string(AovName(layer.aov)) + "." + layer.suffixes[c], std::vector<float>(image.pixels.size())};
      for (size_t i = 0; i < image.pixels.size(); ++i) ch.values[i] = layer.values[i * n + c];
      channels.push_back(std::move(ch));
    }
  }
  WriteFileAtomically(out, EncodeExrChannels(image.width, image.height, std::move(channels), out));
  return {out};
}

}  // namespace

std::string SiblingPath(const std::string& out, const std::string& tag) {
  const auto [stem, extension] = StemAndExtension(out);
  return stem + "." + tag + extension;
}

std::string AovPath(const std::string& out, Aov aov) { return SiblingPath(out, AovName(aov)); }

std::string IdsPath(const std::string& out) { return StemAndExtension(out).first + ".ids.json"; }

std::vector<std::string> WriteImageWithAovs(const Image& image, const std::vector<AovLayer>& layers,
                                            const std::string& out, const DisplayTransform& display,
                                            const std::string& idsJson) {
  std::vector<std::string> files = WriteImageAndLayers(image, layers, out, display);
  if (!idsJson.empty()) {
    files.push_back(IdsPath(out));
    WriteFileAtomically(files.back(), {reinterpret_cast<const uint8_t*>(idsJson.data()), idsJson.size()});
  }
  return files;
}

}  // namespace vkpt::internal
