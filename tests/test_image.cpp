#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <tinyexr.h>

#include "image/image.h"
#include "test_util.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

TEST(Image, PfmRoundTripIsLossless) {
  Image img{5, 3};
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 5; ++x) img.At(x, y) = glm::vec3(x * 0.1f + 1e-7f, y * 123.456f, -0.5f * x * y);
  std::string path = test::TempPath("rt.pfm");
  WriteImage(img, path);
  Image back = ReadPfm(path);
  ASSERT_EQ(back.width, 5u);
  ASSERT_EQ(back.height, 3u);
  EXPECT_EQ(0, std::memcmp(back.pixels.data(), img.pixels.data(), img.pixels.size() * sizeof(glm::vec3)));
  std::filesystem::remove(path);
}

// The EXR encoder builds tinyexr's header by hand: channels, order and precision must
// come back exactly (small images and ones of several ZIP blocks of 16 rows).
TEST(Image, ExrRoundTripIsLossless) {
  for (glm::uvec2 size : {glm::uvec2(5, 3), glm::uvec2(40, 37)}) {
    Image img{size.x, size.y};
    for (uint32_t y = 0; y < size.y; ++y)
      for (uint32_t x = 0; x < size.x; ++x) img.At(x, y) = glm::vec3(x * 0.1f + 1e-7f, y * 123.456f, -0.5f * x * y);
    std::string path = test::TempPath("rt.exr");
    WriteImage(img, path);
    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    ASSERT_EQ(LoadEXR(&rgba, &w, &h, path.c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
    ASSERT_EQ(w, int(size.x));
    ASSERT_EQ(h, int(size.y));
    for (size_t i = 0; i < img.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(rgba[i * 4 + c], img.pixels[i][c]) << "pixel " << i << " channel " << c;
    std::free(rgba);
    std::filesystem::remove(path);
  }
}

TEST(Image, SrgbTransferCurve) {
  EXPECT_EQ(LinearToSrgb8(0.0f), 0);
  EXPECT_EQ(LinearToSrgb8(1.0f), 255);
  EXPECT_EQ(LinearToSrgb8(7.0f), 255);
  EXPECT_EQ(LinearToSrgb8(-1.0f), 0);
  EXPECT_EQ(LinearToSrgb8(0.5f), 188);       // 1.055·0.5^(1/2.4) − 0.055 = 0.7354
  EXPECT_EQ(LinearToSrgb8(0.0031308f), 10);  // the linear segment's end: 0.04045
  EXPECT_EQ(LinearToSrgb8(std::nanf("")), 0);
}

TEST(Image, FailedWriteLeavesNoFile) {
  Image img{2, 2};
  std::string dir = test::TempPath("no-such-dir");
  EXPECT_THROW(WriteImage(img, dir + "/out.png"), Error);
  EXPECT_FALSE(std::filesystem::exists(dir));
  EXPECT_THROW(WriteImage(img, test::TempPath("x.jpg")), Error);
  EXPECT_FALSE(std::filesystem::exists(test::TempPath("x.jpg")));
}

TEST(Image, WriteReplacesAtomically) {
  std::string path = test::TempPath("atomic.exr");
  Image img{4, 4};
  WriteImage(img, path);
  ASSERT_TRUE(std::filesystem::exists(path));
  // Only the final file remains in the directory, no ".partial-" sibling.
  for (const auto& e : std::filesystem::directory_iterator("/tmp"))
    EXPECT_EQ(e.path().string().find(path + ".partial-"), std::string::npos);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace vkpt::internal
