#include "image/image.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // Debian's tinygltf links its own copy; keep ours private
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop
#include <tinyexr.h>

#include "util/error.h"

namespace vkpt {
namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Each writer writes `file` (a temporary) and names `shown` (the user's path) in errors.
void WritePfm(const Image& img, const std::string& file, const std::string& shown) {
  FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) throw Error(shown + ": cannot create file: " + std::strerror(errno));
  // PFM: "PF" = RGB, negative scale = little-endian, rows stored bottom to top.
  std::fprintf(f, "PF\n%u %u\n-1.0\n", img.width, img.height);
  bool ok = true;
  for (uint32_t y = img.height; y-- > 0;)
    ok &= std::fwrite(&img.pixels[size_t(y) * img.width], sizeof(glm::vec3), img.width, f) == img.width;
  ok &= std::fclose(f) == 0;
  if (!ok) throw Error(shown + ": write failed: " + std::strerror(errno));
}

void WritePng(const Image& img, const std::string& file, const std::string& shown, float exposure) {
  const float scale = std::exp2(exposure);
  std::vector<uint8_t> rgb(size_t(img.width) * img.height * 3);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = LinearToSrgb8(img.pixels[i][c] * scale);
  errno = 0;
  if (!stbi_write_png(file.c_str(), int(img.width), int(img.height), 3, rgb.data(), int(img.width * 3)))
    throw Error(shown + ": PNG write failed" + (errno ? std::string(": ") + std::strerror(errno) : ""));
}

void WriteExr(const Image& img, const std::string& file, const std::string& shown) {
  const char* err = nullptr;
  int rc = SaveEXR(&img.pixels[0].x, int(img.width), int(img.height), 3, /*save_as_fp16=*/0, file.c_str(), &err);
  if (rc != TINYEXR_SUCCESS) {
    std::string msg = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw Error(shown + ": EXR write failed: " + msg);
  }
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
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p(path);
  if (fs::is_directory(p, ec)) throw Error(path + ": is a directory, not an image file name");
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw Error(path + ": directory " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw Error(path + ": cannot write to directory " + dir.string() + ": " + std::strerror(errno));
}

uint8_t LinearToSrgb8(float linear) {
  float v = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
  float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(s * 255.0f));
}

void WriteImage(const Image& image, const std::string& path, float exposure) {
  ImageFormat format = FormatFromPath(path);
  if (image.pixels.empty()) throw Error(path + ": refusing to write an empty image");
  std::string tmp = path + ".partial-" + std::to_string(::getpid());
  // The temporary keeps the real extension last so writers that check it are happy.
  tmp += path.substr(path.find_last_of('.'));
  try {
    switch (format) {
      case ImageFormat::Png: WritePng(image, tmp, path, exposure); break;
      case ImageFormat::Pfm: WritePfm(image, tmp, path); break;
      case ImageFormat::Exr: WriteExr(image, tmp, path); break;
    }
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    int e = errno;
    std::remove(tmp.c_str());
    throw Error(path + ": cannot write file: " + std::strerror(e));
  }
}

Image ReadPfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open file: " + std::strerror(errno));
  std::string magic;
  long long w = 0, h = 0;
  double scale = 0.0;
  in >> magic >> w >> h >> scale;
  in.get();  // the single whitespace after the scale
  if (!in || magic != "PF" || w <= 0 || h <= 0 || w > 65536 || h > 65536 || scale == 0.0)
    throw Error(path + ": not a 3-channel PFM image");
  Image img{uint32_t(w), uint32_t(h)};
  const bool swap = scale > 0.0;  // positive scale: big-endian data
  for (uint32_t y = img.height; y-- > 0;) {
    in.read(reinterpret_cast<char*>(&img.pixels[size_t(y) * img.width]), std::streamsize(sizeof(glm::vec3) * img.width));
    if (!in) throw Error(path + ": PFM data is truncated");
  }
  if (swap)
    for (glm::vec3& p : img.pixels)
      for (int c = 0; c < 3; ++c) {
        uint32_t u;
        std::memcpy(&u, &p[c], 4);
        u = __builtin_bswap32(u);
        std::memcpy(&p[c], &u, 4);
      }
  return img;
}

}  // namespace vkpt
