#include "image/image_load.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

// Only the Radiance decoder, with internal linkage: Debian's tinygltf links its own
// stb_image, and vkpt reads no other format through it.
#include "image/stb_source.h"
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 16384
#include <stb_image.h>
#include <tinyexr.h>

#include "util/error.h"
#include "util/regular_file.h"

namespace vkpt::internal {
namespace {

static_assert(sizeof(stbi__context::buffer_start) == StbSource::kRefillSize);
constexpr stbi_io_callbacks kStbCallbacks{&StbSource::Read, &StbSource::Skip, &StbSource::Eof};

// The signatures, checked before the rest of a file is read: stb_image accepts either
// Radiance header line; every OpenEXR file begins with its magic number.
bool LooksLike(const std::string& start, bool hdr) {
  if (hdr) return start.rfind("#?RADIANCE\n", 0) == 0 || start.rfind("#?RGBE\n", 0) == 0;
  return start.rfind("\x76\x2f\x31\x01", 0) == 0;
}

bool HasExtension(const std::string& path, const std::string& ext) {
  if (path.size() < ext.size()) return false;
  std::string tail = path.substr(path.size() - ext.size());
  for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
  return tail == ext;
}

void CheckSize(const std::string& path, int64_t width, int64_t height) {
  if (width < 1 || height < 1 || width > kMaxEnvironmentSide || height > kMaxEnvironmentSide)
    throw Error(path + ": the image is " + std::to_string(width) + " × " + std::to_string(height) +
                " pixels; an environment map must be 1 to " + std::to_string(kMaxEnvironmentSide) + " on each side");
}

Image DecodeHdr(const std::string& path, const std::vector<unsigned char>& bytes, const MemoryCharge& charge) {
  int width = 0, height = 0, channels = 0;
  StbHeap heap;
  StbSource header{bytes};
  try {
    if (!stbi_info_from_callbacks(&kStbCallbacks, &header, &width, &height, &channels))
      throw Error(path + ": not a Radiance HDR file (" + stbi_failure_reason() + ")");
  } catch (const StbEndOfData&) {
    throw Error(path + ": the file is truncated (it ends inside the header)");
  }
  CheckSize(path, width, height);
  // stb's float RGB, then our Image.
  charge(uint64_t(width) * uint64_t(height) * 2 * sizeof(glm::vec3), "its decoded texels");
  StbSource body{bytes};
  float* rgb = nullptr;  // freed with the heap
  try {
    rgb = stbi_loadf_from_callbacks(&kStbCallbacks, &body, &width, &height, &channels, 3);
  } catch (const StbEndOfData&) {
    throw Error(path + ": the file is truncated (it ends inside the pixel data)");
  }
  if (!rgb) throw Error(path + ": cannot decode the Radiance HDR data (" + stbi_failure_reason() + ")");
  Image image{uint32_t(width), uint32_t(height)};
  std::copy_n(rgb, image.pixels.size() * 3, &image.pixels[0].x);
  return image;
}

// tinyexr's header and image, freed however DecodeExr leaves (tinyexr's own
// LoadEXRFromMemory leaks both when the data is refused after the header).
struct ExrHeader : EXRHeader {
  ExrHeader() { InitEXRHeader(this); }
  ~ExrHeader() { FreeEXRHeader(this); }  // also frees what a failed parse left allocated
  ExrHeader(const ExrHeader&) = delete;
  ExrHeader& operator=(const ExrHeader&) = delete;
};
struct ExrImage : EXRImage {
  bool owned = true;  // LoadEXRImageFromMemory frees the image itself when it fails
  ExrImage() { InitEXRImage(this); }
  ~ExrImage() {
    if (owned) FreeEXRImage(this);
  }
  ExrImage(const ExrImage&) = delete;
  ExrImage& operator=(const ExrImage&) = delete;
};

[[noreturn]] void FailExr(const std::string& path, const std::string& what, const char* err) {
  std::string detail = err ? err : "";
  detail.erase(detail.find_last_not_of(" \n") + 1);  // tinyexr ends its messages with a newline
  std::string message = path + ": " + what + (detail.empty() ? "" : " (tinyexr: " + detail + ")");
  FreeEXRErrorMessage(err);
  throw Error(message);
}

// The header of a single-part OpenEXR file, every channel requested as 32-bit float; its
// R, G and B channels (or the one channel of a grey image, three times) go to *rgb.
void ReadExrHeader(const std::string& path, const std::vector<unsigned char>& bytes, ExrHeader& header,
                   std::array<int, 3>* rgb) {
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS)
    throw Error(path + ": not an OpenEXR file");
  if (version.multipart || version.non_image)
    throw Error(path + ": multi-part and deep OpenEXR files are not supported");
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&header, &version, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS)
    FailExr(path, "cannot read the OpenEXR header", err);
  *rgb = {-1, -1, -1};
  for (int c = 0; c < header.num_channels; ++c) {
    const std::string name = header.channels[c].name;
    for (int k = 0; k < 3; ++k)
      if (name == std::string(1, "RGB"[k])) (*rgb)[k] = c;
  }
  if (header.num_channels == 1) *rgb = {0, 0, 0};
  if ((*rgb)[0] < 0 || (*rgb)[1] < 0 || (*rgb)[2] < 0)
    throw Error(path + ": the OpenEXR image has no R, G and B channels");
  for (int c = 0; c < header.num_channels; ++c) {
    if (header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT)
      throw Error(path + ": channel " + header.channels[c].name + " holds integers; an environment map needs floats");
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
}

// The R, G and B channels of an OpenEXR file as 32-bit float: what tinyexr's
// LoadEXRFromMemory picks, without its RGBA copy.
Image DecodeExr(const std::string& path, const std::vector<unsigned char>& bytes, const MemoryCharge& charge) {
  ExrHeader header;
  std::array<int, 3> rgb;
  ReadExrHeader(path, bytes, header, &rgb);
  const int64_t width = int64_t(header.data_window.max_x) - header.data_window.min_x + 1;
  const int64_t height = int64_t(header.data_window.max_y) - header.data_window.min_y + 1;
  CheckSize(path, width, height);
  // tinyexr's float plane per channel (tiles may round it up a little), then our Image.
  const uint64_t channels = uint64_t(header.num_channels);
  charge(uint64_t(width * height) * (channels * sizeof(float) + sizeof(glm::vec3)), "its decoded texels");
  ExrImage exr;
  const char* err = nullptr;
  if (LoadEXRImageFromMemory(&exr, &header, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS) {
    exr.owned = false;
    FailExr(path, "cannot decode the OpenEXR data", err);
  }
  if (exr.width != width || exr.height != height || exr.num_channels != header.num_channels)
    throw Error(path + ": the OpenEXR data window does not match its pixels");
  Image image{uint32_t(width), uint32_t(height)};
  // w × h texels at (x0, y0) from planes of rows `stride` floats apart.
  auto copy = [&](unsigned char** planes, int64_t x0, int64_t y0, int w, int h, int stride) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (x0 + x < 0 || y0 + y < 0 || x0 + x >= width || y0 + y >= height) continue;  // past the image's edge
        glm::vec3& p = image.At(uint32_t(x0 + x), uint32_t(y0 + y));
        for (int k = 0; k < 3; ++k) p[k] = reinterpret_cast<const float*>(planes[rgb[k]])[size_t(y) * stride + x];
      }
  };
  if (header.tiled) {
    if (!exr.tiles) throw Error(path + ": the OpenEXR image has no tiles");
    for (int t = 0; t < exr.num_tiles; ++t) {
      const EXRTile& tile = exr.tiles[t];
      if (tile.level_x != 0 || tile.level_y != 0) continue;  // a smaller mip or rip level
      if (tile.width > header.tile_size_x || tile.height > header.tile_size_y)
        throw Error(path + ": an OpenEXR tile is larger than the tile size");
      copy(tile.images, int64_t(tile.offset_x) * header.tile_size_x, int64_t(tile.offset_y) * header.tile_size_y,
           tile.width, tile.height, header.tile_size_x);
    }
  } else {
    if (!exr.images) throw Error(path + ": the OpenEXR image has no pixels");
    copy(exr.images, 0, 0, int(width), int(height), int(width));
  }
  return image;
}

}  // namespace

Image ReadEnvironmentImage(const std::string& path, const MemoryCharge& charge, std::vector<std::string>* warnings) {
  const bool hdr = HasExtension(path, ".hdr"), exr = HasExtension(path, ".exr");
  if (!hdr && !exr) throw Error(path + ": unknown environment map format (use a Radiance .hdr or an OpenEXR .exr)");
  std::string problem;
  std::optional<RegularFile> file = RegularFile::Open(path, &problem);
  if (!file) throw Error(path + ": " + problem);
  std::string start(std::min<uint64_t>(file->Size(), 11), '\0');
  if (!file->ReadAt(0, start.data(), start.size(), &problem)) throw Error(path + ": " + problem);
  if (!LooksLike(start, hdr))
    throw Error(path + (hdr ? ": not a Radiance HDR file (no #?RADIANCE or #?RGBE line)" : ": not an OpenEXR file"));
  charge(file->Size(), "the file");
  std::vector<unsigned char> bytes(file->Size());
  if (!file->ReadAt(0, bytes.data(), bytes.size(), &problem)) throw Error(path + ": " + problem);
  Image image = hdr ? DecodeHdr(path, bytes, charge) : DecodeExr(path, bytes, charge);
  uint64_t negative = 0;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    glm::vec3& p = image.pixels[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Error(path + ": texel (" + std::to_string(i % image.width) + ", " + std::to_string(i / image.width) +
                  ") is not finite (NaN or infinity)");
    if (p.x < 0.0f || p.y < 0.0f || p.z < 0.0f) ++negative;
    p = glm::max(p, glm::vec3(0.0f));
  }
  if (negative)
    warnings->push_back(path + ": " + std::to_string(negative) + " texel(s) had negative components, set to 0");
  return image;
}

}  // namespace vkpt::internal
