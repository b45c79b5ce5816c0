// The numbers of the GGX and rough dielectric albedo tables that shared/ggx_albedo.h
// interpolates (it says what they hold), for C++. They are defined once, in
// host/render/ggx_albedo_table.cpp, from ggx_albedo_table.inc, which
// scripts/make_ggx_albedo_table.cpp writes; a shader reads them from a texel buffer.
#pragma once

#include "layout.h"

namespace vkpt::shader {

constexpr uint kGgxAlbedoFloats =
    2u * (kGgxAlbedoSize * (kGgxAlbedoSize + 1u) + kGlassAlbedoIors * kGlassAlbedoCosines * kGlassAlbedoRoughnesses);
extern const float kGgxAlbedo[kGgxAlbedoFloats];

}  // namespace vkpt::shader
