#include "image/image_encode.h"

#include <cmath>
#include <cstdlib>
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

namespace vkpt {

std::vector<uint8_t> EncodePng(const Image& img, float exposure) {
  const float scale = std::exp2(exposure);
  std::vector<uint8_t> rgb(size_t(img.width) * img.height * 3);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = LinearToSrgb8(img.pixels[i][c] * scale);
  std::vector<uint8_t> bytes;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const uint8_t* p = static_cast<const uint8_t*>(data);
    out->insert(out->end(), p, p + size);
  };
  // stb fails only when its own malloc does.
  if (!stbi_write_png_to_func(append, &bytes, int(img.width), int(img.height), 3, rgb.data(), int(img.width * 3)))
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
  // EXR stores one plane per channel, by convention in B, G, R order (what viewers expect).
  const size_t n = img.pixels.size();
  std::vector<float> planes[3];
  float* planePointers[3];
  EXRChannelInfo channels[3] = {};
  int pixelTypes[3];
  for (int c = 0; c < 3; ++c) {
    planes[c].resize(n);
    for (size_t i = 0; i < n; ++i) planes[c][i] = img.pixels[i][2 - c];
    planePointers[c] = planes[c].data();
    channels[c].name[0] = "BGR"[c];
    pixelTypes[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = pixelTypes;            // what we hand over
  header.requested_pixel_types = pixelTypes;  // what the file stores: no precision lost
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
  EXRImage exr;
  InitEXRImage(&exr);
  exr.num_channels = 3;
  exr.width = int(img.width);
  exr.height = int(img.height);
  exr.images = reinterpret_cast<unsigned char**>(planePointers);

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

}  // namespace vkpt
