// The scene's textures as both renderers read them (shared/texture.h): one array of
// 32-bit words holding, per image and colour space, a table of level offsets and the
// RGBA8 texels of every mip level; the Texture table; the byte → float tables.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "shared/layout.h"

namespace vkpt::internal {

struct TextureStore {
  std::vector<shader::Texture> textures;  // parallel to Scene::textures
  std::vector<uint32_t> words;            // level tables and texels (R in the low byte)
};

// Builds every texture's mip chain: each level from the one above by a box filter
// that conserves the mean for any size (odd ones too), averaging in linear space (sRGB
// colour is decoded first and encoded again), then rounded to bytes.
TextureStore BuildTextureStore(const Scene& scene, unsigned threads);

// The texture's sampler as shader::Texture mode bits (wrap modes, filters);
// the level count is BuildTextureStore's to add.
uint32_t PackSampler(const SceneTexture& texture);

// The mip levels of one image: level 0 as given, then down to 1 × 1; RGBA8 words.
std::vector<std::vector<uint32_t>> MipChain(const TextureImage& image, bool srgb);

// kTexelDecodeSize floats: sRGB → linear for bytes 0…255, then byte / 255, each exactly
// rounded from double precision (the GPU computes the second: shared/texture.h's UnormByte).
std::vector<float> TexelDecodeTable();

// The sRGB transfer functions (IEC 61966-2-1), in double precision.
double SrgbToLinear(double encoded);
double LinearToSrgb(double linear);

}  // namespace vkpt::internal
