// Texture lookups (glTF 2.0 §3.8 textures and samplers), written once for both
// renderers. The CPU and the shader return the same bits for the same lookup: every
// float operation here is a single correctly rounded IEEE operation (no division, no
// transcendental; sRGB bytes become floats through an exactly rounded table, linear ones
// through another on the CPU and by integer arithmetic on the GPU, UnormByte, with the
// same bits: VKPT_TEXEL_UNORM), and the values are VKPT_PRECISE so
// that no compiler fuses a multiply and an add into an FMA (lavapipe's NIR does where it
// may). Whether a texture's RGB is sRGB is the caller's argument: a constant at every
// material slot (kSrgbSlots), so that lavapipe compiles only the decode the slot needs.
//
// Scene access, as in path.h:
//   VKPT_TEXTURE(i)      Texture i
//   VKPT_TEXEL_WORD(i)   the i-th RGBA8 texel of the store as a uint, R in the low byte
//   VKPT_TEXEL_DECODE(i) entry i of the byte → float tables (texture_layout.h)
//
// A lookup is written for two kinds of device. Where a branch skips the work it guards
// (the CPU, a GPU whose lanes agree), nearest filtering reads one texel and a second mip
// level is read only when its weight is not 0. Where every side of a branch runs, masked,
// whichever way the lanes go (VKPT_MASKED_BRANCHES: lavapipe's SIMD lanes), the lookup is
// one straight line instead: the level or two levels chosen by selects, each read as a
// bilinear blend (nearest: all weight on the texel under the point) and always two
// levels (the second with weight 0 where one is meant). Both give the same bits: texel
// values are finite and ≥ 0, so a·1 + b·0 = a exactly.
#ifndef VKPT_TEXTURE_H
#define VKPT_TEXTURE_H
#include "prelude.h"  // first, as in every shared header

#include "layout.h"

#ifndef VKPT_MASKED_BRANCHES
#define VKPT_MASKED_BRANCHES false
#endif
#ifndef VKPT_TEXEL_UNORM
#define VKPT_TEXEL_UNORM(b) UnormByte(b)
#endif

VKPT_BEGIN_NAMESPACE

// A texture coordinate brought into [0, 1] by the wrap mode; the texel index is wrapped
// once more below (WrapTexel), since filtering reaches half a texel past either edge.
// MIRRORED_REPEAT folds the coordinate, after which clamping the index is exact: the
// texel mirrored across an edge is the edge texel itself. Coordinates that are not
// finite, or so large that no fraction is left, read at 0.
VKPT_FN float WrapCoordinate(float u, uint mode) {
  if (!(abs(u) < 1e30f)) u = 0.0f;
  if (mode == kWrapClampToEdge) return clamp(u, 0.0f, 1.0f);
  if (mode == kWrapMirroredRepeat) {
    VKPT_PRECISE float t = u - 2.0f * floor(0.5f * u);  // [0, 2]
    return t > 1.0f ? 2.0f - t : t;
  }
  VKPT_PRECISE float f = u - floor(u);  // [0, 1]: 1 when rounding takes a tiny negative u there
  return f;
}

// A texel index in [−1, n] (see TexelSpan) into [0, n).
VKPT_FN int WrapTexel(int x, int n, uint mode) {
  if (mode != kWrapRepeat) return clamp(x, 0, n - 1);
  return x < 0 ? x + n : (x >= n ? x - n : x);
}

// Byte b as b / 255, correctly rounded, from integer operations alone. 1/255 is
// Σ_{k≥1} 2^−8k, so b / 255 = N · 2^−32 · (1 + 2^−32 + …) with N = b · 0x01010101: the
// float's 24 significant bits are N's from its leading one, rounded by the bit after them;
// the endless tail below that bit is never 0, so there is no tie and rounding adds that
// bit. Equal to float(b / 255.0) for every byte (tests/test_texture_filter.cpp), which
// b · (1/255) is not for 126 of them; no uint → float conversion rounds (Vulkan leaves
// its rounding to the device), as b < 2^24 converts exactly.
VKPT_FN float UnormByte(uint b) {
  uint e = floatBitsToUint(float(b)) >> 23u;  // 127 + ⌊log2 b⌋ for b ≥ 1
  uint m = max(e, 127u) - 127u;               // b = 0 reads 0 below, whatever these give
  uint n = b * 0x01010101u;
  uint bits = ((e - 8u) << 23u) + ((n >> (m + 1u)) & 0x7FFFFFu) + ((n >> m) & 1u);
  return b == 0u ? 0.0f : uintBitsToFloat(bits);
}

// Texel k of a texture's store, as floats: RGB through the sRGB table when the texture
// holds colour, alpha (and everything else) as byte / 255.
VKPT_FN vec4 TexelValue(VKPT_SCENE_PARAM uint k, bool srgb) {
  uint word = VKPT_TEXEL_WORD(k);
  uint r = word & 0xFFu, g = (word >> 8u) & 0xFFu, b = (word >> 16u) & 0xFFu;
  vec3 rgb = srgb ? vec3(VKPT_TEXEL_DECODE(r), VKPT_TEXEL_DECODE(g), VKPT_TEXEL_DECODE(b))
                  : vec3(VKPT_TEXEL_UNORM(r), VKPT_TEXEL_UNORM(g), VKPT_TEXEL_UNORM(b));
  return vec4(rgb, VKPT_TEXEL_UNORM(word >> 24u));
}

// One level of a texture: where it starts in the store and its size.
struct TextureLevel {
  uint offset;
  int width;
  int height;
};

// The store begins each texture with the offsets of its levels (see Texture), so that
// finding one takes a single read and no loop (lavapipe counts every loop pass against
// its budget: traverse.glsl).
VKPT_FN TextureLevel LevelOf(VKPT_SCENE_PARAM Texture t, uint level) {
  TextureLevel l;
  l.offset = VKPT_TEXEL_WORD(t.offset + level);
  l.width = int(max(t.width >> level, 1u));
  l.height = int(max(t.height >> level, 1u));
  return l;
}

// The level's value at (s, t) ∈ [0, 1]² (wrapped already): the nearest texel, or the
// bilinear blend of the four whose centres surround the point.
VKPT_FN vec4 SampleLevel(VKPT_SCENE_PARAM uint mode, TextureLevel l, vec2 st, bool linear, bool srgb) {
  uint wrapS = (mode >> kTextureWrapSShift) & 3u;
  uint wrapT = (mode >> kTextureWrapTShift) & 3u;
  if (!VKPT_MASKED_BRANCHES && !linear) {
    int x = WrapTexel(int(floor(st.x * float(l.width))), l.width, wrapS);
    int y = WrapTexel(int(floor(st.y * float(l.height))), l.height, wrapT);
    return TexelValue(VKPT_SCENE_ARG l.offset + uint(y * l.width + x), srgb);
  }
  // Nearest, on a device of masked branches: the blend below with every weight on the
  // texel under the point (its index is the one above: st·w − 0 = st·w).
  float centre = linear ? 0.5f : 0.0f;
  VKPT_PRECISE float sx = st.x * float(l.width) - centre;
  VKPT_PRECISE float sy = st.y * float(l.height) - centre;
  float x0f = floor(sx), y0f = floor(sy);
  VKPT_PRECISE float fx = linear ? sx - x0f : 0.0f;
  VKPT_PRECISE float fy = linear ? sy - y0f : 0.0f;
  int x0 = WrapTexel(int(x0f), l.width, wrapS), x1 = WrapTexel(int(x0f) + 1, l.width, wrapS);
  uint row0 = l.offset + uint(WrapTexel(int(y0f), l.height, wrapT) * l.width);
  uint row1 = l.offset + uint(WrapTexel(int(y0f) + 1, l.height, wrapT) * l.width);
  vec4 a = TexelValue(VKPT_SCENE_ARG row0 + uint(x0), srgb);
  vec4 b = TexelValue(VKPT_SCENE_ARG row0 + uint(x1), srgb);
  vec4 c = TexelValue(VKPT_SCENE_ARG row1 + uint(x0), srgb);
  vec4 d = TexelValue(VKPT_SCENE_ARG row1 + uint(x1), srgb);
  VKPT_PRECISE vec4 top = a * (1.0f - fx) + b * fx;
  VKPT_PRECISE vec4 bottom = c * (1.0f - fx) + d * fx;
  VKPT_PRECISE vec4 v = top * (1.0f - fy) + bottom * fy;
  return v;
}

// The filtered value of texture t at uv for level of detail `lod` (log2 of the texels
// a footprint spans on level 0): magnification when lod ≤ 0 (or NaN), minification
// otherwise, from level 0, the nearest level or the two around lod by the sampler's
// minFilter (OpenGL 4.6 §8.14). `srgb`: the texture's RGB is colour (the slot's, kSrgbSlots).
VKPT_FN vec4 SampleTexture(VKPT_SCENE_PARAM Texture t, vec2 uv, float lod, bool srgb) {
  vec2 st = vec2(WrapCoordinate(uv.x, (t.mode >> kTextureWrapSShift) & 3u),
                 WrapCoordinate(uv.y, (t.mode >> kTextureWrapTShift) & 3u));
  bool minify = lod > 0.0f;
  bool linear = (t.mode & (minify ? kTextureMinLinear : kTextureMagLinear)) != 0u;
  float last = float((t.mode >> kTextureLevelShift) - 1u);
  float level = minify ? min(lod, last) : 0.0f;
  bool nearestLevel = minify && (t.mode & kTextureMipNearest) != 0u;
  bool twoLevels = minify && !nearestLevel && (t.mode & kTextureMipLinear) != 0u;
  // The level read (0 to magnify or without mipmaps), and the weight of the next one.
  float l0 = nearestLevel ? min(floor(level + 0.5f), last) : (twoLevels ? floor(level) : 0.0f);
  VKPT_PRECISE float f = twoLevels ? level - l0 : 0.0f;
  vec4 a = SampleLevel(VKPT_SCENE_ARG t.mode, LevelOf(VKPT_SCENE_ARG t, uint(l0)), st, linear, srgb);
  if (!VKPT_MASKED_BRANCHES && f == 0.0f) return a;
  vec4 b = SampleLevel(VKPT_SCENE_ARG t.mode, LevelOf(VKPT_SCENE_ARG t, uint(min(l0 + 1.0f, last))), st, linear, srgb);
  VKPT_PRECISE vec4 v = a * (1.0f - f) + b * f;
  return v;
}

// The texture coordinate a TextureRef reads: its TEXCOORD set, through its
// KHR_texture_transform.
VKPT_FN vec2 TransformUV(TextureRef ref, vec2 uv) {
  VKPT_PRECISE float u = ref.m00 * uv.x + ref.m01 * uv.y + ref.m02;
  VKPT_PRECISE float v = ref.m10 * uv.x + ref.m11 * uv.y + ref.m12;
  return vec2(u, v);
}

VKPT_END_NAMESPACE

#endif
