// The numbers of the albedo tables that shared/ggx_albedo.h and shared/sheen.h interpolate
// (they say what the tables hold), for C++: one array, the GGX and rough dielectric
// tables (ggx_albedo_table.inc, written by scripts/make_ggx_albedo_table.cpp) and then
// the sheen table (sheen_albedo_table.inc, by scripts/make_sheen_albedo_table.cpp). It is
// defined once, in host/render/albedo_tables.cpp; a shader reads the same numbers from
// one texel buffer.
#pragma once

#include "layout.h"

namespace vkpt::shader {

constexpr uint kGgxAlbedoFloats = 2u * kSheenAlbedoOffset;
constexpr uint kSheenAlbedoFloats = 2u * kSheenAlbedoCosines * (kSheenAlbedoRoughnesses - 1u);
constexpr uint kAlbedoTableFloats = kGgxAlbedoFloats + kSheenAlbedoFloats;
extern const float kAlbedoTables[kAlbedoTableFloats];

// Pair k of the tables (a shader defines it as a texel fetch: backend_contract.h).
#define VKPT_ALBEDO_PAIR(k) vec2(kAlbedoTables[2u * (k)], kAlbedoTables[2u * (k) + 1u])

}  // namespace vkpt::shader
