#include "render/texture_store.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "util/error.h"
#include "util/parallel.h"

namespace vkpt::internal {
namespace {

// One source texel's share of a destination texel.
struct Tap {
  uint32_t src;
  double weight;
};

// The box filter from n texels to m ≤ n: destination i covers source [i·n/m, (i+1)·n/m),
// each source texel weighted by the length of its overlap. The weights of a destination
// sum to 1, and every source texel's weights to m/n, so the mean is kept exactly.
std::vector<std::vector<Tap>> BoxTaps(uint32_t n, uint32_t m) {
  std::vector<std::vector<Tap>> taps(m);
  const double scale = double(n) / double(m);
  for (uint32_t i = 0; i < m; ++i) {
    const double lo = i * scale, hi = (i + 1) * scale;
    for (uint32_t j = uint32_t(lo); j < n && double(j) < hi; ++j) {
      const double overlap = std::min(hi, j + 1.0) - std::max(lo, double(j));
      if (overlap > 0.0) taps[i].push_back({j, overlap / scale});
    }
  }
  return taps;
}

struct Rgba {
  double c[4] = {0.0, 0.0, 0.0, 0.0};
};

class LevelFilter {
 public:
  explicit LevelFilter(bool srgb) : srgb_(srgb) {
    for (int b = 0; b < 256; ++b) {
      linear_[b] = b / 255.0;
      decode_[b] = srgb ? SrgbToLinear(b / 255.0) : linear_[b];
    }
  }

  // The level below `level` (w × h words).
  std::vector<uint32_t> Next(const std::vector<uint32_t>& level, uint32_t w, uint32_t h) const {
    const uint32_t nw = std::max(w / 2, 1u), nh = std::max(h / 2, 1u);
    const auto xTaps = BoxTaps(w, nw), yTaps = BoxTaps(h, nh);
    std::vector<uint32_t> out(size_t(nw) * nh);
    std::vector<Rgba> row(nw), acc(nw);
    for (uint32_t y = 0; y < nh; ++y) {
      std::fill(acc.begin(), acc.end(), Rgba{});
      for (const Tap& ty : yTaps[y]) {
        FilterRow(&level[size_t(ty.src) * w], xTaps, row);
        for (uint32_t x = 0; x < nw; ++x)
          for (int c = 0; c < 4; ++c) acc[x].c[c] += ty.weight * row[x].c[c];
      }
      for (uint32_t x = 0; x < nw; ++x) out[size_t(y) * nw + x] = Encode(acc[x]);
    }
    return out;
  }

 private:
  void FilterRow(const uint32_t* src, const std::vector<std::vector<Tap>>& taps, std::vector<Rgba>& row) const {
    for (size_t x = 0; x < taps.size(); ++x) {
      Rgba v;
      for (const Tap& t : taps[x]) {
        const uint32_t word = src[t.src];
        for (int c = 0; c < 4; ++c) {
          const uint32_t byte = (word >> (8 * c)) & 0xFFu;
          v.c[c] += t.weight * (c < 3 ? decode_[byte] : linear_[byte]);
        }
      }
      row[x] = v;
    }
  }

  uint32_t Encode(const Rgba& v) const {
    uint32_t word = 0;
    for (int c = 0; c < 4; ++c) {
      const double x = std::clamp(c < 3 && srgb_ ? LinearToSrgb(v.c[c]) : v.c[c], 0.0, 1.0);
      word |= uint32_t(std::lround(x * 255.0)) << (8 * c);
    }
    return word;
  }

  bool srgb_;
  double decode_[256], linear_[256];
};

uint32_t LevelCount(uint32_t w, uint32_t h) {
  uint32_t levels = 1;
  while ((std::max(w, h) >> (levels - 1)) > 1) ++levels;
  return levels;
}

}  // namespace

double SrgbToLinear(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }

double LinearToSrgb(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

std::vector<float> TexelDecodeTable() {
  std::vector<float> table(shader::kTexelDecodeSize);
  for (uint32_t b = 0; b < 256; ++b) {
    table[b] = float(SrgbToLinear(b / 255.0));
    table[shader::kTexelDecodeLinear + b] = float(b / 255.0);
  }
  return table;
}

std::vector<std::vector<uint32_t>> MipChain(const TextureImage& image, bool srgb) {
  std::vector<std::vector<uint32_t>> levels(1);
  levels[0].resize(size_t(image.width) * image.height);
  for (size_t i = 0; i < levels[0].size(); ++i) {
    const uint8_t* p = &image.rgba[4 * i];
    levels[0][i] = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
  }
  const LevelFilter filter(srgb);
  uint32_t w = image.width, h = image.height;
  for (uint32_t l = 1; l < LevelCount(image.width, image.height); ++l) {
    levels.push_back(filter.Next(levels.back(), w, h));
    w = std::max(w / 2, 1u);
    h = std::max(h / 2, 1u);
  }
  return levels;
}

uint32_t PackSampler(const SceneTexture& texture) {
  auto wrap = [](TextureSampler::Wrap w) {
    switch (w) {
      case TextureSampler::Wrap::kClampToEdge: return shader::kWrapClampToEdge;
      case TextureSampler::Wrap::kMirroredRepeat: return shader::kWrapMirroredRepeat;
      default: return shader::kWrapRepeat;
    }
  };
  const TextureSampler& s = texture.sampler;
  uint32_t bits = wrap(s.wrapS) << shader::kTextureWrapSShift | wrap(s.wrapT) << shader::kTextureWrapTShift;
  if (s.magLinear) bits |= shader::kTextureMagLinear;
  if (s.minLinear) bits |= shader::kTextureMinLinear;
  if (s.mip == TextureSampler::Mip::kNearest) bits |= shader::kTextureMipNearest;
  if (s.mip == TextureSampler::Mip::kLinear) bits |= shader::kTextureMipLinear;
  return bits;
}

TextureStore BuildTextureStore(const Scene& scene, unsigned threads) {
  TextureStore store;
  // One chain per image and colour space, however many samplers use it.
  std::map<std::pair<uint32_t, bool>, size_t> chainOf;
  std::vector<std::pair<uint32_t, bool>> chains;
  for (const SceneTexture& t : scene.textures) {
    const std::pair<uint32_t, bool> key{t.image, t.srgb};
    if (chainOf.try_emplace(key, chains.size()).second) chains.push_back(key);
  }
  std::vector<std::vector<std::vector<uint32_t>>> built(chains.size());
  ParallelFor(chains.size(), ThreadCount(threads),
              [&](size_t k) { built[k] = MipChain(scene.images[chains[k].first], chains[k].second); });

  std::vector<uint32_t> offsets(chains.size());
  uint64_t size = 0;
  for (size_t k = 0; k < chains.size(); ++k) {
    offsets[k] = uint32_t(size);
    size += built[k].size();
    for (const auto& level : built[k]) size += level.size();
    if (size >= (uint64_t(1) << 32))
      throw Error(scene.path + ": the textures need more than 2^32 texels with their mip levels");
  }
  store.words.reserve(size);
  for (size_t k = 0; k < chains.size(); ++k) {
    uint32_t at = offsets[k] + uint32_t(built[k].size());
    for (const auto& level : built[k]) {
      store.words.push_back(at);
      at += uint32_t(level.size());
    }
    for (auto& level : built[k]) {
      store.words.insert(store.words.end(), level.begin(), level.end());
      std::vector<uint32_t>().swap(level);
    }
  }
  for (const SceneTexture& t : scene.textures) {
    const size_t k = chainOf.at({t.image, t.srgb});
    const TextureImage& im = scene.images[t.image];
    store.textures.push_back(
        {offsets[k], im.width, im.height, PackSampler(t) | uint32_t(built[k].size()) << shader::kTextureLevelShift});
  }
  return store;
}

}  // namespace vkpt::internal
