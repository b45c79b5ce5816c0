// One deliberately broken file per decoder vkpt runs on untrusted bytes — environment
// maps (.hdr through stb, .exr through tinyexr), texture images (PNG, JPEG, as a glTF's
// image) and the PFM of --diff — each cut short, each with garbage after a valid start
// and each declaring 16384 × 16384 pixels: vkpt exits 1 with a message naming the file,
// within a second and 300 MB, and leaves no image.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "image/image_encode.h"
#include "png_writer.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;
using test::ProcessResult;

constexpr uint32_t kSide = 64;

Image Gradient() {
  Image img(kSide, kSide);
  for (uint32_t i = 0; i < kSide * kSide; ++i) img.pixels[i] = glm::vec3(i % kSide, i / kSide, 7) / float(kSide);
  return img;
}

Bytes Rgb8() {
  Bytes rgb(kSide * kSide * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t(i * 31 + (i >> 7));
  return rgb;
}

Bytes StbWritten(bool hdr) {
  Bytes out;
  auto append = [](void* context, void* data, int size) {
    auto* b = static_cast<Bytes*>(context);
    b->insert(b->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  if (hdr) {
    const Image img = Gradient();
    stbi_write_hdr_to_func(append, &out, kSide, kSide, 3, &img.pixels[0].x);
  } else {
    const Bytes rgb = Rgb8();
    stbi_write_jpg_to_func(append, &out, kSide, kSide, 3, rgb.data(), 90);
  }
  return out;
}

size_t Find(const Bytes& b, const std::string& text) {
  const Bytes what(text.begin(), text.end());
  const auto at = std::search(b.begin(), b.end(), what.begin(), what.end());
  EXPECT_NE(at, b.end()) << text;
  return size_t(at - b.begin());
}

void PutBigEndian16(Bytes& b, size_t at, uint16_t v) {
  b[at] = uint8_t(v >> 8);
  b[at + 1] = uint8_t(v);
}

// The file as written, then with its size declared as 16384 × 16384 in its own header.
struct Format {
  const char* ext;
  Bytes (*valid)();
  Bytes (*huge)();
};

const Format kFormats[] = {
    {"hdr", [] { return StbWritten(true); },
     [] {
       Bytes b = StbWritten(true);
       const size_t at = Find(b, "-Y 64 +X 64");
       const std::string big = "-Y 16384 +X 16384";
       b.erase(b.begin() + at, b.begin() + at + 11);
       b.insert(b.begin() + at, big.begin(), big.end());
       return b;
     }},
    {"exr", [] { return EncodeExr(Gradient(), "gradient.exr"); },
     [] {
       Bytes b = EncodeExr(Gradient(), "gradient.exr");
       // dataWindow: box2i xMin, yMin, xMax, yMax after its name, type and size.
       const size_t at = Find(b, std::string("dataWindow\0box2i\0", 17)) + 17 + 4;
       const int32_t window[4] = {0, 0, 16383, 16383};
       std::memcpy(&b[at], window, sizeof window);
       return b;
     }},
    {"png", [] { return test::MakePng(kSide, kSide, 8, 2, Rgb8()); },
     [] { return test::MakePng(16384, 16384, 8, 2, Rgb8()); }},
    {"jpg", [] { return StbWritten(false); },
     [] {
       Bytes b = StbWritten(false);
       const size_t sof = Find(b, "\xFF\xC0");  // baseline frame: length, precision, height, width
       PutBigEndian16(b, sof + 5, 16384);
       PutBigEndian16(b, sof + 7, 16384);
       return b;
     }},
    {"pfm", [] { return EncodePfm(Gradient()); },
     [] {
       Bytes b = EncodePfm(Gradient());
       const std::string big = "PF\n16384 16384\n";
       const size_t header = Find(b, "64 64\n") + 6;
       b.erase(b.begin(), b.begin() + header);
       b.insert(b.begin(), big.begin(), big.end());
       return b;
     }},
};

enum class Damage { kTruncated, kGarbageAfterStart, kHugeSize };
const char* Name(Damage d) {
  return d == Damage::kTruncated ? "Truncated" : d == Damage::kGarbageAfterStart ? "GarbageAfterStart" : "HugeSize";
}

Bytes Broken(const Format& f, Damage d) {
  if (d == Damage::kHugeSize) return f.huge();
  Bytes b = f.valid();
  if (d == Damage::kTruncated) {
    b.resize(b.size() * 3 / 5);
    return b;
  }
  // The first quarter (every header here is shorter), then random bytes to the same size
  // (a PFM's are floats, some of them NaN or infinite).
  std::mt19937 random(29);
  for (size_t i = b.size() / 4; i < b.size(); ++i) b[i] = uint8_t(random());
  return b;
}

struct Case {
  const Format* format;
  Damage damage;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.format->ext << " " << Name(c.damage); }

class BrokenFile : public ::testing::TestWithParam<Case> {};

// The command that decodes the file: --env, a glTF's base-colour texture, or --diff.
std::vector<std::string> CommandFor(const std::string& ext, const std::string& file, const std::string& dir) {
  const std::string cornell = test::SourcePath("scenes/cornell.gltf");
  const std::vector<std::string> render = {"--backend", "cpu", "--width", "8", "--spp", "1", "--out", dir + "/o.png"};
  std::vector<std::string> args;
  if (ext == "hdr" || ext == "exr") {
    args = {"--scene", cornell, "--env", file};
  } else if (ext == "pfm") {
    const std::string good = dir + "/good.pfm";
    const Bytes valid = EncodePfm(Gradient());
    std::ofstream(good, std::ios::binary)
        .write(reinterpret_cast<const char*>(valid.data()), std::streamsize(valid.size()));
    return {"--diff", file, good, "--out", dir + "/o.png"};
  } else {
    const std::string scene = dir + "/textured.gltf";
    std::ofstream(scene)
        << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":60,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"}],
      "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],
      "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
      "textures":[{"source":0}],"images":[{"uri":")" +
               fs::path(file).filename().string() + R"("}],
      "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
    args = {"--scene", scene};
  }
  args.insert(args.end(), render.begin(), render.end());
  return args;
}

TEST_P(BrokenFile, ExitsOneNamingTheFileWithinASecondAnd300MB) {
  const Case& c = GetParam();
  const test::TempFolder dir(std::string("broken-") + c.format->ext + "-" + Name(c.damage));
  const std::string file = dir / (std::string("broken.") + c.format->ext);
  const Bytes bytes = Broken(*c.format, c.damage);
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  ProcessResult r = test::RunVkpt(CommandFor(c.format->ext, file, dir.path), 20.0);
  ASSERT_TRUE(r.ExitedWith(1)) << r.Describe();
  EXPECT_NE(r.err.find("broken." + std::string(c.format->ext)), std::string::npos)
      << "the file is not named: " << r.err;
  EXPECT_LT(r.seconds, 1.0 * test::kTimeScale) << r.err;
  EXPECT_LT(r.peakRssKiB, 300 << 10) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
  std::printf("  %s\n", r.err.c_str());
}

std::vector<Case> AllCases() {
  std::vector<Case> cases;
  for (const Format& f : kFormats)
    for (Damage d : {Damage::kTruncated, Damage::kGarbageAfterStart, Damage::kHugeSize}) cases.push_back({&f, d});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Decoders, BrokenFile, ::testing::ValuesIn(AllCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.format->ext) + Name(info.param.damage);
                         });

}  // namespace
}  // namespace vkpt::internal
