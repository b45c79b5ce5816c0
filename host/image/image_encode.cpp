#include "image/image_encode.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // Debian's tinygltf links its own copy; keep ours private
// Only the in-memory encoder is used: stb's file writers ignore fwrite/fclose errors.
#define STBI_WRITE_NO_STDIO
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop
#include <tinyexr.h>

#include "util/error.h"

namespace vkpt::internal {

std::vector<uint8_t> EncodePng(const Image& img, const DisplayTransform& display) {
  std::vector<uint8_t> rgb(size_t(img.width) * img.height * 3);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const glm::vec3 shown = display.Apply(img.pixels[i]);
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = LinearToSrgb8(shown[c]);
  }
  return EncodePngRgb8(img.width, img.height, rgb);
}

std::vector<uint8_t> EncodePngRgb8(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb) {
  std::vector<uint8_t> bytes;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const uint8_t* p = static_cast<const uint8_t*>(data);
    out->insert(out->end(), p, p + size);
  };
  // stb fails only when its own malloc does.
  if (!stbi_write_png_to_func(append, &bytes, int(width), int(height), 3, rgb.data(), int(width * 3)))
    throw std::bad_alloc();
  return bytes;
}

std::vector<uint8_t> EncodePfm(const Image& img) {
  // "PF" = RGB, negative scale = little-endian (the host's order), rows bottom to top.
  const std::string header = "PF\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n-1.0\n";
  const size_t rowBytes = sizeof(glm::vec3) * img.width;
  std::vector<uint8_t> bytes(header.begin(), header.end());
  bytes.reserve(header.size() + rowBytes * img.height);
  for (uint32_t y = img.height; y-- > 0;) {
    const uint8_t* row = reinterpret_cast<const uint8_t*>(&img.pixels[size_t(y) * img.width]);
    bytes.insert(bytes.end(), row, row + rowBytes);
  }
  return bytes;
}

std::vector<uint8_t> EncodeExr(const Image& img, const std::string& path) {
  return EncodeExrChannels(img.width, img.height, RgbChannels(img), path);
}

std::vector<ExrChannel> RgbChannels(const Image& img) {
  std::vector<ExrChannel> channels(3);
  for (int c = 0; c < 3; ++c) {
    channels[c].name = std::string(1, "RGB"[c]);
    channels[c].values.resize(img.pixels.size());
    for (size_t i = 0; i < img.pixels.size(); ++i) channels[c].values[i] = img.pixels[i][c];
  }
  return channels;
}

std::vector<uint8_t> EncodeExrChannels(uint32_t width, uint32_t height, std::vector<ExrChannel> channels,
                                       const std::string& path) {
  // The EXR format lists channels sorted by name (B, G, R; albedo.B, …), as readers expect.
  std::sort(channels.begin(), channels.end(), [](const ExrChannel& a, const ExrChannel& b) { return a.name < b.name; });
  const int n = int(channels.size());
  std::vector<float*> planePointers(n);
  std::vector<EXRChannelInfo> info(n);
  std::vector<int> pixelTypes(n, TINYEXR_PIXELTYPE_FLOAT);
  for (int c = 0; c < n; ++c) {
    if (channels[c].name.size() >= sizeof info[c].name || channels[c].values.size() != size_t(width) * height)
      throw Error(path + ": EXR channel \"" + channels[c].name + "\" is malformed");
    std::memcpy(info[c].name, channels[c].name.c_str(), channels[c].name.size() + 1);
    planePointers[c] = channels[c].values.data();
  }
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = n;
  header.channels = info.data();
  header.pixel_types = pixelTypes.data();            // what we hand over
  header.requested_pixel_types = pixelTypes.data();  // what the file stores: no precision lost
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
  EXRImage exr;
  InitEXRImage(&exr);
  exr.num_channels = n;
  exr.width = int(width);
  exr.height = int(height);
  exr.images = reinterpret_cast<unsigned char**>(planePointers.data());

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const size_t size = SaveEXRImageToMemory(&exr, &header, &memory, &err);
  if (size == 0) {
    std::string msg = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw Error(path + ": EXR encoding failed: " + msg);
  }
  std::vector<uint8_t> bytes(memory, memory + size);
  std::free(memory);
  return bytes;
}

}  // namespace vkpt::internal
