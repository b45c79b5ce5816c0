// Texture lookups on the GPU return the CPU's bits: 65,536 random lookups (texture
// coordinate, level of detail, texture, colour or data) over textures of every wrap mode,
// filter and size, run by tests/shaders/texture_lookup.comp and by the C++ build of
// shared/texture.h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "gpu_test.h"
#include "render/scene_access.h"
#include "render/texture_store.h"
#include "shared/texture.h"
#include "test_util.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"

#include "kTextureLookupSpirv.h"

namespace vkpt::internal {
namespace {

struct TextureLookup {  // as in texture_lookup.comp (std430)
  glm::vec2 uv;
  float lod;
  uint32_t texture;
  uint32_t srgb;  // the texture's RGB read as colour (1) or data (0)
  uint32_t pad;
};

class TextureGpuTest : public test::ValidatedGpuTest {};

// Textures of every combination of wrap S, wrap T, magnification and minification
// filter, over random images of sizes that halve evenly and not.
RenderScene AllKindsOfTextures(std::mt19937& rng) {
  Scene s;
  const glm::uvec2 sizes[] = {{1, 1}, {2, 2}, {7, 5}, {64, 32}, {33, 17}, {1, 40}, {128, 128}};
  for (glm::uvec2 size : sizes) {
    TextureImage im{"random", size.x, size.y, std::vector<uint8_t>(size_t(4) * size.x * size.y)};
    for (uint8_t& b : im.rgba) b = uint8_t(rng() & 0xFF);
    s.images.push_back(im);
  }
  using namespace shader;
  const uint32_t minFilters[] = {0,
                                 kTextureMinLinear,
                                 kTextureMipNearest,
                                 kTextureMinLinear | kTextureMipNearest,
                                 kTextureMipLinear,
                                 kTextureMinLinear | kTextureMipLinear};
  for (uint32_t wrapS = 0; wrapS < 3; ++wrapS)
    for (uint32_t wrapT = 0; wrapT < 3; ++wrapT)
      for (uint32_t mag : {0u, kTextureMagLinear})
        for (uint32_t min : minFilters) {
          const uint32_t image = uint32_t(rng() % s.images.size());
          s.textures.push_back(
              test::TextureWithMode(image, wrapS << kTextureWrapSShift | wrapT << kTextureWrapTShift | mag | min));
        }
  return test::TexturesOnly(s);
}

// Random coordinates over several periods, with the cases where rounding decides:
// texel centres and edges, 0 and 1, integers, huge and non-finite values; levels of
// detail below 0, fractional, integral, half-integral and past the last level.
std::vector<TextureLookup> RandomLookups(const RenderScene& rs, uint32_t n, std::mt19937& rng) {
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f), lod(-2.0f, 10.0f);
  const float special[] = {0.0f,   1.0f,        -1.0f, 0.5f,   2.0f,     -0.0f, 1e-8f,
                           -1e-8f, 0.99999994f, 1e31f, -1e31f, INFINITY, NAN};
  std::vector<TextureLookup> lookups(n);
  for (TextureLookup& l : lookups) {
    l.texture = uint32_t(rng() % rs.textures.size());
    l.srgb = rng() % 2;
    const shader::Texture& t = rs.textures[l.texture];
    for (int c = 0; c < 2; ++c) {
      const uint32_t size = c == 0 ? t.width : t.height;
      switch (rng() % 4) {
        case 0: l.uv[c] = special[rng() % std::size(special)]; break;
        case 1: l.uv[c] = (float(rng() % (3 * size)) + (rng() % 2 ? 0.5f : 0.0f)) / float(size) - 1.0f; break;
        default: l.uv[c] = coord(rng);
      }
    }
    switch (rng() % 3) {
      case 0: l.lod = float(int(rng() % 20) - 4) * 0.5f; break;
      default: l.lod = lod(rng);
    }
  }
  return lookups;
}

// The lookups of RandomLookups on the GPU, with the texel store in at most
// `texelsPerBuffer` texels per buffer (0: the device's limit), written with branches that
// skip work or, `maskedBranches`, as one straight line; how many differ in any bit.
uint32_t DifferingLookups(const RenderScene& rs, const std::vector<TextureLookup>& lookups, uint32_t texelsPerBuffer,
                          bool maskedBranches) {
  const uint32_t n = uint32_t(lookups.size());
  vk::Context& ctx = test::Gpu();
  vk::TexelBuffer textures = vk::UploadTexelBuffer(ctx, rs.textures.data(), rs.textures.size() * 16, "texture table");
  vk::SplitTexelBuffer texels =
      vk::UploadSplitTexelBuffer(ctx, rs.texels.data(), rs.texels.size() * 4, 1, "texels", texelsPerBuffer);
  EXPECT_EQ(texels.twoBuffers, texelsPerBuffer != 0);
  vk::TexelBuffer decode = vk::UploadTexelBuffer(ctx, rs.texelDecode.data(), rs.texelDecode.size() * 4, "decode");
  vk::Buffer in = vk::UploadStorage(ctx, lookups.data(), n * sizeof(TextureLookup), "lookups");
  vk::Buffer out(ctx, n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "results");
  vk::Buffer host(ctx, out.Size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, "readback");
  vk::ComputePipeline pipe(ctx, kTextureLookupSpirv, sizeof(kTextureLookupSpirv),
                           {vk::TexelBinding(shader::kBindingTextures, textures),
                            vk::TexelBinding(shader::kBindingTexels, texels.low),
                            vk::TexelBinding(shader::kBindingTexelsHigh, texels.high),
                            vk::TexelBinding(shader::kBindingTexelDecode, decode),
                            {30, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, in.Handle()},
                            {31, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, out.Handle()}},
                           "texture lookups", sizeof(uint32_t),
                           {texels.twoBuffers ? 1u : 0u, maskedBranches ? 1u : 0u});
  ctx.Submit([&](VkCommandBuffer cb) {
    pipe.Dispatch(cb, n / 64, 1, 1, &texels.split);
    vk::CopyToHost(cb, {{&out, &host}});
  });
  const auto* gpu = static_cast<const glm::vec4*>(host.Mapped());
  uint32_t differing = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const TextureLookup& l = lookups[i];
    const shader::Texture& t = rs.textures[l.texture];
    const glm::vec4 cpu = shader::SampleTexture(rs, t, l.uv, l.lod, l.srgb != 0u);
    if (std::memcmp(&cpu, &gpu[i], sizeof cpu) == 0) continue;
    if (++differing <= 5)
      ADD_FAILURE() << "lookup " << i << ": texture " << l.texture << " mode 0x" << std::hex
                    << rs.textures[l.texture].mode << std::dec << (l.srgb ? " sRGB" : "") << ", uv (" << l.uv.x << ", "
                    << l.uv.y << "), lod " << l.lod << ": CPU (" << cpu.r << ", " << cpu.g << ", " << cpu.b << ", "
                    << cpu.a << "), GPU (" << gpu[i].r << ", " << gpu[i].g << ", " << gpu[i].b << ", " << gpu[i].a
                    << ")";
  }
  return differing;
}

TEST_F(TextureGpuTest, LookupsReturnTheCpusBits) {
  std::mt19937 rng(1234);
  const RenderScene rs = AllKindsOfTextures(rng);
  const std::vector<TextureLookup> lookups = RandomLookups(rs, 65536, rng);
  for (bool masked : {false, true}) {
    const char* form = masked ? "as one straight line" : "with branches";
    const uint32_t differing = DifferingLookups(rs, lookups, 0, masked);
    std::printf("%zu texture lookups over %zu textures, %s: %u differ in any bit between CPU and GPU\n", lookups.size(),
                rs.textures.size(), form, differing);
    EXPECT_EQ(differing, 0u) << form;
    // The store split over two texel buffers, as a device with a smaller
    // maxTexelBufferElements would need: the second begins inside some texture's levels.
    const uint32_t half = uint32_t(rs.texels.size() / 8);
    const uint32_t split = DifferingLookups(rs, lookups, half, masked);
    std::printf("with the store split after texel %u of %zu: %u differ\n", half, (rs.texels.size() + 3) / 4, split);
    EXPECT_EQ(split, 0u) << form;
  }
}

}  // namespace
}  // namespace vkpt::internal
