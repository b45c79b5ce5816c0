// The equirectangular environment map: orientation, lookup, importance sampling and its
// density, one source for both renderers.
//
// Orientation (README "Using it"; the convention of the maps in ../shared/gltf-pbr): a
// direction d of the map's own frame (+Y up) is read at u = 0.5 + atan2(d.x, −d.z) / 2π,
// v = acos(d.y) / π, with u = 0 the left edge and v = 0 the top row. The centre column
// thus faces −Z (where a default glTF camera looks), 3/4 of the width +X, the top row +Y:
// Blender's equirectangular world texture turned −90° about its up axis. FrameParams'
// rotation α turns the map about +Y, counter-clockwise seen from above (what the map shows
// at −Z appears at −X for α = 90°), so a world direction is turned by −α before the lookup.
//
// Sampling is pbrt's two-dimensional piecewise-constant distribution (pbrt-v3 §13.6.7,
// pbrt-v4 PiecewiseConstant2D): a row by the marginal CDF, a column by that row's
// conditional CDF, a point uniform in the cell; with dω = 2π² sin θ du dv the solid-angle
// density is pdf_uv / (2π² sin θ). Each side defines scene access before including this:
//   VKPT_SCENE_PARAM, VKPT_SCENE_ARG   as in path.h
//   VKPT_ENV_TEXEL(i)   vec4: RGB radiance of texel i = row · width + column (row 0 on top)
//   VKPT_ENV_CDF(i)     float: the distribution's CDFs, laid out as layout.h describes
#ifndef VKPT_ENVIRONMENT_H
#define VKPT_ENVIRONMENT_H
#include "layout.h"
#include "prelude.h"
#include "sampling.h"

// A shader may define VKPT_ENVIRONMENT_MAP as a specialization constant that is false
// when there is no map: lavapipe runs an if's body even when no lane takes it, so only a
// constant spares every escaped ray the lookup code (two atan2s, four texel fetches).
#ifndef VKPT_ENVIRONMENT_MAP
#define VKPT_ENVIRONMENT_MAP true
#endif

VKPT_BEGIN_NAMESPACE

struct EnvSample {
  vec3 dir;       // unit world direction towards the environment
  float pdf;      // solid-angle density of dir; 0: no sample (no map, or at a pole)
  vec3 radiance;  // EnvRadiance(dir)
};

VKPT_FN vec2 EnvDirectionToUv(FrameParams p, vec3 dir) {
  float c = p.envRotationCos;
  float s = p.envRotationSin;
  vec3 d = vec3(c * dir.x - s * dir.z, dir.y, s * dir.x + c * dir.z);
  // Straight up or down (atan2(0, 0)) any u will do: PortableAtan2 gives 0.
  float phi = PortableAtan2(d.x, -d.z);
  float u = 0.5f + phi * (0.5f * kInvPi);
  return vec2(clamp(u, 0.0f, 1.0f), PortableAcos(clamp(d.y, -1.0f, 1.0f)) * kInvPi);
}

VKPT_FN vec3 EnvUvToDirection(FrameParams p, vec2 uv) {
  float phi = 2.0f * kPi * (uv.x - 0.5f);
  float theta = kPi * uv.y;
  float sinTheta = sin(theta);
  vec3 d = vec3(sinTheta * sin(phi), cos(theta), -sinTheta * cos(phi));
  float c = p.envRotationCos;
  float s = p.envRotationSin;
  return vec3(c * d.x + s * d.z, d.y, c * d.z - s * d.x);
}

// Bilinear between the four texel centres around uv (texel (i, j) is centred at
// ((i + ½)/w, (j + ½)/h)): wraps around in u, clamps to the top and bottom rows in v.
VKPT_FN vec3 EnvBilinear(VKPT_SCENE_PARAM uint w, uint h, vec2 uv) {
  float x = uv.x * float(w) - 0.5f;
  float y = uv.y * float(h) - 0.5f;
  float fx = x - floor(x);
  float fy = y - floor(y);
  int i0 = int(floor(x));  // in [-1, w - 1] for u ∈ [0, 1]
  int j0 = int(floor(y));
  uint c0 = i0 < 0 ? w - 1u : uint(i0);
  uint c1 = c0 + 1u == w ? 0u : c0 + 1u;
  uint r0 = uint(max(j0, 0)) * w;
  uint r1 = min(uint(j0 + 1), h - 1u) * w;
  vec3 top = mix(vec3(VKPT_ENV_TEXEL(r0 + c0)), vec3(VKPT_ENV_TEXEL(r0 + c1)), fx);
  vec3 bottom = mix(vec3(VKPT_ENV_TEXEL(r1 + c0)), vec3(VKPT_ENV_TEXEL(r1 + c1)), fx);
  return mix(top, bottom, fy);
}

// Radiance arriving from direction dir (unit, world space) from outside the scene: the
// map × intensity, or the constant background when there is no map.
VKPT_FN vec3 EnvRadiance(VKPT_SCENE_PARAM FrameParams p, vec3 dir) {
  if (!VKPT_ENVIRONMENT_MAP || p.envWidth == 0u) return p.background;
  return p.envIntensity * EnvBilinear(VKPT_SCENE_ARG p.envWidth, p.envHeight, EnvDirectionToUv(p, dir));
}

// The interval of the CDF at [first, first + count) that holds u ∈ [0, 1) (sampling.h):
// a row of the marginal CDF, or a column of a row's conditional CDF.
VKPT_DEFINE_CDF_SEARCH(EnvFindInterval, VKPT_ENV_CDF)

VKPT_FN float EnvCdfBelow(VKPT_SCENE_PARAM uint first, uint k) { return k > 0u ? VKPT_ENV_CDF(first + k - 1u) : 0.0f; }

// A cell's pmf as a density over the sphere at v: uniform over the cell in (u, v)
// (pdf_uv = pmf · w · h), and dω = 2π² sin θ du dv. 0 at the poles (a set of measure 0).
VKPT_FN float EnvSolidAnglePdf(float cellPmf, uint w, uint h, float v) {
  float sinTheta = sin(kPi * v);
  return sinTheta > 0.0f ? cellPmf * float(w) * float(h) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

// A direction towards the environment with density ∝ its radiance (per cell, see
// host/render/environment_map.cpp for the weights) from a uniform u ∈ [0, 1)².
VKPT_FN EnvSample SampleEnvironment(VKPT_SCENE_PARAM FrameParams p, vec2 u) {
  EnvSample s;
  s.dir = vec3(0.0f, 1.0f, 0.0f);
  s.pdf = 0.0f;
  s.radiance = vec3(0.0f);
  uint w = p.envWidth;
  uint h = p.envHeight;
  if (w == 0u) return s;
  uint marginal = w * h;
  uint row = EnvFindInterval(VKPT_SCENE_ARG marginal, h, u.y);
  float rowLo = EnvCdfBelow(VKPT_SCENE_ARG marginal, row);
  uint col = EnvFindInterval(VKPT_SCENE_ARG row * w, w, u.x);
  float colLo = EnvCdfBelow(VKPT_SCENE_ARG row * w, col);
  // u stretched back to [0, 1) within the chosen intervals (pbrt's continuous sampling):
  // the point is uniform within its cell.
  // The pmfs are the widths a uniform u really lands in (as the light table's).
  float rowPmf = VKPT_ENV_CDF(marginal + row) - rowLo;
  float colPmf = VKPT_ENV_CDF(row * w + col) - colLo;
  float du = min((u.x - colLo) / colPmf, kOneMinusEpsilon);
  float dv = min((u.y - rowLo) / rowPmf, kOneMinusEpsilon);
  vec2 uv = vec2((float(col) + du) / float(w), (float(row) + dv) / float(h));
  s.dir = EnvUvToDirection(p, uv);
  s.pdf = EnvSolidAnglePdf(rowPmf * colPmf, w, h, uv.y);
  s.radiance = EnvRadiance(VKPT_SCENE_ARG p, s.dir);
  return s;
}

// The solid-angle density with which SampleEnvironment picks dir (0 without a map).
VKPT_FN float EnvironmentPdf(VKPT_SCENE_PARAM FrameParams p, vec3 dir) {
  uint w = p.envWidth;
  uint h = p.envHeight;
  if (w == 0u) return 0.0f;
  vec2 uv = EnvDirectionToUv(p, dir);
  uint col = min(uint(uv.x * float(w)), w - 1u);
  uint row = min(uint(uv.y * float(h)), h - 1u);
  uint marginal = w * h;
  float rowPmf = VKPT_ENV_CDF(marginal + row) - EnvCdfBelow(VKPT_SCENE_ARG marginal, row);
  float colPmf = VKPT_ENV_CDF(row * w + col) - EnvCdfBelow(VKPT_SCENE_ARG row * w, col);
  return EnvSolidAnglePdf(rowPmf * colPmf, w, h, uv.y);
}

VKPT_END_NAMESPACE

#endif
