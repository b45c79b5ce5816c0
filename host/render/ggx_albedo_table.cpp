#include "shared/ggx_albedo_table.h"

namespace vkpt::shader {

const float kGgxAlbedo[kGgxAlbedoFloats] = {
#include "shared/ggx_albedo_table.inc"
};

}  // namespace vkpt::shader
