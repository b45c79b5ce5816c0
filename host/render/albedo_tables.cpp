#include "shared/albedo_tables.h"

namespace vkpt::shader {

const float kAlbedoTables[kAlbedoTableFloats] = {
#include "shared/ggx_albedo_table.inc"
#include "shared/sheen_albedo_table.inc"
#include "shared/wavelength_table.inc"
};

}  // namespace vkpt::shader
