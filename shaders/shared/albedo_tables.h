// The numbers of the albedo tables that shared/ggx_albedo.h and shared/sheen.h interpolate
// (they say what the tables hold), for C++: one array, the GGX and rough dielectric
// tables (ggx_albedo_table.inc, written by scripts/make_ggx_albedo_table.cpp) and then
// the sheen table (sheen_albedo_table.inc, by scripts/make_sheen_albedo_table.cpp), and
// the hero wavelength's bins (wavelength_table.inc, by scripts/make_wavelength_table.cpp),
// which are no albedo but share the buffer. It is defined once, in
// host/render/albedo_tables.cpp; a shader reads the same numbers from one texel buffer.
#pragma once

#include "layout.h"

namespace vkpt::shader {

constexpr uint kGgxAlbedoFloats = 2u * kSheenAlbedoOffset;
constexpr uint kSheenAlbedoFloats = 2u * kSheenAlbedoCosines * (kSheenAlbedoRoughnesses - 1u);
constexpr uint kWavelengthFloats = 4u * (kWavelengthBins + 1u);
constexpr uint kAlbedoTableFloats = kGgxAlbedoFloats + kSheenAlbedoFloats + kWavelengthFloats;
static_assert(2u * kWavelengthOffset == kGgxAlbedoFloats + kSheenAlbedoFloats && kWavelengthOffset % 2u == 0u,
              "the wavelength bins follow the sheen table, one texel each");
extern const float kAlbedoTables[kAlbedoTableFloats];

// Pair k of the tables (a shader defines it as a texel fetch: backend_contract.h).
#define VKPT_ALBEDO_PAIR(k) vec2(kAlbedoTables[2u * (k)], kAlbedoTables[2u * (k) + 1u])

}  // namespace vkpt::shader
