# The GPU records (shaders/shared/gpu_records.def, which says what it declares) become
# C++ and GLSL at build time: vkpt-gen-records writes them under VKPT_GPU_RECORDS_DIR,
# and the target vkpt_gpu_records stands for them. Every target that includes one
# (through the shared or scene layer, the shaders, the fuzz targets) depends on it.
set(VKPT_GPU_RECORDS_DIR "${CMAKE_BINARY_DIR}/generated/records")
set(VKPT_GPU_RECORDS_DEF "${PROJECT_SOURCE_DIR}/shaders/shared/gpu_records.def")
set(VKPT_GPU_RECORDS_FILES "${VKPT_GPU_RECORDS_DIR}/shared/gpu_records.h" "${VKPT_GPU_RECORDS_DIR}/gpu_fetch.glsl"
                           "${VKPT_GPU_RECORDS_DIR}/scene/texture_slots.h")

# The parser and the writers, also linked by the tests (GpuRecords.*).
add_library(vkpt_gpu_records_gen STATIC scripts/gpu_records_parse.cpp scripts/gpu_records_emit.cpp)
target_include_directories(vkpt_gpu_records_gen PUBLIC "${PROJECT_SOURCE_DIR}/scripts")
add_executable(vkpt-gen-records scripts/gen_gpu_records.cpp)
target_link_libraries(vkpt-gen-records PRIVATE vkpt_gpu_records_gen)

add_custom_command(
  OUTPUT ${VKPT_GPU_RECORDS_FILES}
  COMMAND vkpt-gen-records "${VKPT_GPU_RECORDS_DEF}" "${VKPT_GPU_RECORDS_DIR}"
  DEPENDS vkpt-gen-records "${VKPT_GPU_RECORDS_DEF}"
  COMMENT "vkpt-gen-records: GPU records <- shaders/shared/gpu_records.def"
  VERBATIM)
add_custom_target(vkpt_gpu_records DEPENDS ${VKPT_GPU_RECORDS_FILES})
