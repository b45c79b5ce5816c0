// Writes small generated seed files for the image fuzz targets into OUTDIR/env,
// OUTDIR/pfm and OUTDIR/texture (run.sh calls it; the real files of the test data are
// read in place besides). EXR and PFM seeds come from vkpt's own writers
// (image/image_encode.h), so they are what vkpt writes; HDR, PNG and JPEG seeds from
// stb_image_write, in each pixel layout the decoders distinguish; WebP ones from libwebp.
//   usage: fuzz_seeds OUTDIR
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>

#include <webp/encode.h>

#include "image/image.h"
#include "image/image_encode.h"

namespace {

std::string out;

void Write(const std::string& name, const std::vector<uint8_t>& bytes) {
  const std::string path = out + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fclose(f) != 0) {
    std::fprintf(stderr, "fuzz_seeds: cannot write %s\n", path.c_str());
    std::exit(1);
  }
}

void Append(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<uint8_t>*>(context);
  bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}

vkpt::Image Gradient(uint32_t w, uint32_t h) {
  vkpt::Image img{w, h};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) img.At(x, y) = glm::vec3(0.1f * x, 0.25f * y, std::exp2(float(x) - 3.0f));
  return img;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds OUTDIR\n");
    return 2;
  }
  out = argv[1];
  for (const char* dir : {"env", "pfm", "texture"}) std::filesystem::create_directories(out + "/" + dir);

  // Environment maps: EXR as vkpt writes it (RGB; RGB with AOV channels), Radiance HDR
  // flat (narrow) and run-length encoded (8 to 32767 wide).
  const vkpt::Image small = Gradient(5, 3), wide = Gradient(16, 2);
  Write("env/rgb.exr", vkpt::EncodeExr(small, "rgb.exr"));
  std::vector<vkpt::ExrChannel> channels = vkpt::RgbChannels(small);
  channels.push_back({"A", std::vector<float>(15, 1.0f)});
  channels.push_back({"depth.Z", std::vector<float>(15, 2.5f)});
  Write("env/aovs.exr", vkpt::EncodeExrChannels(5, 3, channels, "aovs.exr"));
  for (const vkpt::Image* img : {&small, &wide}) {
    std::vector<uint8_t> bytes;
    stbi_write_hdr_to_func(Append, &bytes, int(img->width), int(img->height), 3, &img->pixels[0].x);
    Write(img == &small ? "env/flat.hdr" : "env/rle.hdr", bytes);
  }

  // PFM: little-endian as vkpt writes it, and the same big-endian (positive scale).
  std::vector<uint8_t> le = vkpt::EncodePfm(small);
  Write("pfm/little-endian.pfm", le);
  const std::string header = "PF\n5 3\n1.0\n";
  std::vector<uint8_t> be(header.begin(), header.end());
  for (uint32_t y = small.height; y-- > 0;)
    for (uint32_t x = 0; x < small.width; ++x)
      for (int c = 0; c < 3; ++c) {
        uint32_t u;
        std::memcpy(&u, &small.At(x, y)[c], 4);
        for (int b = 3; b >= 0; --b) be.push_back(uint8_t(u >> (8 * b)));
      }
  Write("pfm/big-endian.pfm", be);

  // Textures: PNG grey, grey+alpha, RGB, RGBA; JPEG grey and RGB.
  std::vector<uint8_t> texels(6 * 5 * 4);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 37);
  for (int comp = 1; comp <= 4; ++comp) {
    std::vector<uint8_t> bytes;
    stbi_write_png_to_func(Append, &bytes, 6, 5, comp, texels.data(), 6 * comp);
    Write("texture/" + std::to_string(comp) + "-channel.png", bytes);
  }
  for (int comp : {1, 3}) {
    std::vector<uint8_t> bytes;
    stbi_write_jpg_to_func(Append, &bytes, 6, 5, comp, texels.data(), 90);
    Write("texture/" + std::to_string(comp) + "-channel.jpg", bytes);
  }
  // WebP lossless (RGBA) and lossy (RGB), as libwebp encodes them.
  uint8_t* webp = nullptr;
  size_t size = WebPEncodeLosslessRGBA(texels.data(), 6, 5, 6 * 4, &webp);
  Write("texture/lossless.webp", std::vector<uint8_t>(webp, webp + size));
  WebPFree(webp);
  size = WebPEncodeRGB(texels.data(), 6, 5, 6 * 3, 80.0f, &webp);
  Write("texture/lossy.webp", std::vector<uint8_t>(webp, webp + size));
  WebPFree(webp);
  return 0;
}
