// View transforms against the values published with each: Khronos PBR Neutral's LUT
// (PBR_Neutral/pbrNeutral.cube, KhronosGroup/ToneMapping), Blender's AgX LUT
// (luts/AgX_Base_sRGB.cube, EaryChow/AgX, as shipped in Blender 4+), and for the ACES fit,
// whose author published only the code, its own constants' consequences.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "image/image.h"
#include "image/image_encode.h"
#include "image/view_transform.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

struct Published {
  glm::dvec3 in, out;
};

using Curve = std::function<glm::dvec3(glm::dvec3)>;

double WorstError(const Curve& curve, const std::vector<Published>& table, double encodingPower = 1.0) {
  double worst = 0.0;
  for (const Published& p : table) {
    const glm::dvec3 shown = glm::pow(glm::clamp(curve(p.in), 0.0, 1.0), glm::dvec3(1.0 / encodingPower));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(shown[c] - p.out[c]));
  }
  return worst;
}

// PBR Neutral's LUT node i has input 2^(−9 + 19 i / 56); its values have 7 decimals.
double NeutralNode(int i) { return std::exp2(-9.0 + 19.0 * i / 56.0); }

std::vector<Published> NeutralLut() {
  auto node = [](int r, int g, int b, glm::dvec3 out) {
    return Published{{NeutralNode(r), NeutralNode(g), NeutralNode(b)}, out};
  };
  return {
      node(0, 0, 0, glm::dvec3(0.0000238)),
      node(14, 14, 14, glm::dvec3(0.0172633)),
      node(20, 20, 20, glm::dvec3(0.1754932)),
      node(24, 24, 24, glm::dvec3(0.5120448)),
      node(26, 26, 26, glm::dvec3(0.8219901)),
      node(28, 28, 28, glm::dvec3(0.9325696)),
      node(32, 32, 32, glm::dvec3(0.9811943)),
      node(40, 40, 40, glm::dvec3(0.9975189)),
      node(56, 56, 56, glm::dvec3(0.9999437)),
      node(28, 20, 10, {0.9342712, 0.1842041, 0.062202}),
      node(40, 24, 8, {0.997522, 0.7767186, 0.7715919}),
      node(56, 0, 0, {0.9999437, 0.9934695, 0.9934695}),
      node(20, 24, 28, {0.1696351, 0.3838358, 0.9325696}),
      node(30, 29, 12, {0.9664615, 0.7943688, 0.1571937}),
  };
}

TEST(ViewTransform, NeutralMatchesItsPublishedLut) {
  EXPECT_LT(WorstError(PbrNeutral, NeutralLut()), 1e-7);
  // Teeth: an exposure off by 0.1 % and the mix towards 1 of one engine's port both fail.
  EXPECT_GT(WorstError([](glm::dvec3 c) { return PbrNeutral(c * 1.001); }, NeutralLut()), 1e-5);
  EXPECT_GT(WorstError(
                [](glm::dvec3 c) {
                  const glm::dvec3 d = PbrNeutral(c);
                  const double peak = std::max(d.r, std::max(d.g, d.b));
                  return peak < 0.76 ? d : glm::mix(d, glm::dvec3(1.0), 0.001);
                },
                NeutralLut()),
            1e-5);
}

// The specification's own properties: inside [0.08, 0.8] a colour only loses the 0.04
// Fresnel offset; everywhere the result lies in the plane of the input and grey (no hue shift).
TEST(ViewTransform, NeutralKeepsMidtonesAndHue) {
  for (int i = 0; i < 50; ++i) {
    const glm::dvec3 c(0.08 + 0.72 * std::fmod(i * 0.618034, 1.0), 0.08 + 0.72 * std::fmod(i * 0.414214, 1.0),
                       0.08 + 0.72 * std::fmod(i * 0.732051, 1.0));
    const glm::dvec3 d = PbrNeutral(c) - (c - 0.04);
    EXPECT_LT(std::abs(d.r) + std::abs(d.g) + std::abs(d.b), 1e-12) << i;
    const glm::dvec3 bright = c * 20.0;
    EXPECT_LT(std::abs(glm::dot(PbrNeutral(bright), glm::cross(bright, glm::dvec3(1.0)))), 1e-9 * glm::length(bright))
        << i;
  }
}

// Blender's LUT holds Rec.1886-encoded values (display-linear ^ (1/2.4)); the inputs are the
// Rec.709 preimages of its nodes (all ≥ 0, so nothing is clipped before the curve).
std::vector<Published> AgxLut() {
  return {
      {{0.024842011, 0.024842016, 0.0248420149}, {0.1893466, 0.1893459, 0.1893614}},
      {{0.21672324, 0.216723285, 0.216723275}, {0.5280727, 0.528071, 0.5281054}},
      {{3.51075889, 3.5107596, 3.51075945}, {0.9085853, 0.9085846, 0.9085976}},
      {{0.206065956, 0.00222688201, 0.00566449166}, {0.5006584, 0.0271117, 0}},
      {{0.000377616107, 0.0314711497, 0.00010937819}, {0.0628655, 0.1985618, 0}},
      {{0.00611710631, 0.509809738, 0.00177184713}, {0.3030596, 0.6795349, 0.1493059}},
      {{1.59987727, 0.325291243, 0.177887646}, {0.8817801, 0.6262569, 0.5596984}},
      {{1.44497024, 0.170474064, 1.1630963}, {0.8494651, 0.626493, 0.8105721}},
      {{0.12207966, 1.09458631, 1.07818559}, {0.6175679, 0.7964896, 0.7961566}},
      {{65.5763682, 13.3331592, 7.29132536}, {1, 0.9956293, 0.9805665}},
  };
}

TEST(ViewTransform, AgxMatchesBlendersLut) {
  EXPECT_LT(WorstError(AgxBase, AgxLut(), 2.4), 1e-4);
  // Middle grey stays middle grey: AgX's pivot.
  EXPECT_NEAR(AgxBase(glm::dvec3(0.18)).g, 0.18, 1e-6);
  // Teeth: a 2.2 display power (the common approximation) and a 1 % exposure error fail.
  EXPECT_GT(WorstError([](glm::dvec3 c) { return glm::pow(AgxBase(c), glm::dvec3(2.2 / 2.4)); }, AgxLut(), 2.4), 5e-3);
  EXPECT_GT(WorstError([](glm::dvec3 c) { return AgxBase(c * 1.01); }, AgxLut(), 2.4), 1e-3);
}

// Hill's fit has no published outputs; these follow from its published constants (float64),
// and 0.18 → 0.106 is where ACES 1.0's sRGB output puts middle grey.
TEST(ViewTransform, AcesFitFollowsItsConstants) {
  const std::vector<Published> table = {
      {glm::dvec3(0.18), {0.1055912, 0.1055912, 0.1055902}}, {glm::dvec3(1.0), {0.6191154, 0.6191154, 0.6191092}},
      {glm::dvec3(4.0), {0.9090138, 0.9090138, 0.9090047}},  {{1, 0, 0}, {0.6880279, 0, 0.0026390}},
      {{0, 1, 0}, {0.1016133, 0.6236590, 0.0288437}},        {{0.5, 0.2, 0.1}, {0.3652267, 0.1288062, 0.0536373}},
  };
  EXPECT_LT(WorstError(AcesFitted, table), 1e-6);
  // Teeth: the 1/0.6 pre-exposure some engines add fails.
  EXPECT_GT(WorstError([](glm::dvec3 c) { return AcesFitted(c / 0.6); }, table), 1e-2);
}

TEST(ViewTransform, MiddleGreyCodesAndStrayValues) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<std::pair<View, int>> grey = {
      {View::kClamp, 118}, {View::kNeutral, 105}, {View::kAgx, 118}, {View::kAces, 91}};
  for (const auto& [view, code] : grey) {
    const DisplayTransform t{view, 0.0f};
    EXPECT_EQ(LinearToSrgb8(t.Apply(glm::vec3(0.18f)).g), code) << ViewName(view);
    EXPECT_EQ(t.Apply(glm::vec3(nan)), glm::vec3(0.0f)) << ViewName(view);
    EXPECT_EQ(t.Apply(glm::vec3(-1.0f)), glm::vec3(0.0f)) << ViewName(view);
    const glm::vec3 white = t.Apply(glm::vec3(inf));
    for (int c = 0; c < 3; ++c) EXPECT_EQ(LinearToSrgb8(white[c]), 255) << ViewName(view);
    // Exposure is a power of two on the radiance: exact.
    for (float v : {0.01f, 0.3f, 2.5f, 40.0f}) {
      const DisplayTransform up{view, 1.0f};
      EXPECT_EQ(up.Apply(glm::vec3(v)), t.Apply(glm::vec3(2.0f * v))) << ViewName(view) << " " << v;
    }
    EXPECT_EQ(ViewFromName(ViewName(view)), view);
  }
  EXPECT_FALSE(ViewFromName("filmic"));
}

// `clamp` is the PNG vkpt wrote before it had views, byte for byte.
TEST(ViewTransform, ClampIsTheClippedSrgbEncoding) {
  Image img{64, 1};
  for (uint32_t x = 0; x < 64; ++x) img.At(x, 0) = glm::vec3(x / 40.0f, std::exp2(x * 0.25f - 10.0f), -0.01f * x);
  const std::vector<uint8_t> png = EncodePng(img, {View::kClamp, -1.5f});
  std::vector<uint8_t> rgb;
  for (const glm::vec3& p : img.pixels)
    for (int c = 0; c < 3; ++c) rgb.push_back(LinearToSrgb8(p[c] * std::exp2(-1.5f)));
  EXPECT_EQ(png, EncodePngRgb8(64, 1, rgb));
}

// The CLI's PNG is its linear image through `--view` (default neutral) and `--exposure`;
// a .pfm of the same render is untouched by either.
TEST(ViewTransform, CliPngIsTheLinearImageThroughTheView) {
  const std::string dir = test::FreshTempDirectory("view-cli");
  auto render = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"--scene",   test::SourcePath("scenes/cornell.gltf"),
                                     "--backend", "cpu",
                                     "--width",   "24",
                                     "--height",  "24",
                                     "--spp",     "2",
                                     "--out",     dir + "/" + out};
    args.insert(args.end(), extra.begin(), extra.end());
    const test::ProcessResult r = test::RunVkpt(args);
    EXPECT_TRUE(r.ExitedWith(0)) << r.Describe();
    return test::ReadFile(dir + "/" + out);
  };
  const std::string pfm = render("a.pfm", {});
  EXPECT_EQ(render("b.pfm", {"--view", "agx", "--exposure", "2"}), pfm);
  const Image linear = ReadPfm(dir + "/a.pfm");
  auto bytes = [](const std::vector<uint8_t>& v) { return std::string(v.begin(), v.end()); };
  EXPECT_EQ(render("n.png", {}), bytes(EncodePng(linear, {View::kNeutral, 0.0f})));
  EXPECT_EQ(render("x.png", {"--view", "agx", "--exposure", "1.5"}), bytes(EncodePng(linear, {View::kAgx, 1.5f})));
  EXPECT_EQ(render("c.png", {"--view", "clamp"}), bytes(EncodePng(linear, {View::kClamp, 0.0f})));
  EXPECT_NE(bytes(EncodePng(linear, {View::kNeutral, 0.0f})), bytes(EncodePng(linear, {View::kClamp, 0.0f})));
}

}  // namespace
}  // namespace vkpt::internal
