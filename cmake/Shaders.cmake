# vkpt_compile_shader(<out_var> <source.comp> <symbol> [DEFINES A=1 ...] [INCLUDES <dir> ...])
#
# Compiles a GLSL compute shader to SPIR-V at build time and wraps it in a C header
# `<symbol>.h` holding `const uint32_t <symbol>[]`, so binaries embed it and read
# nothing from disk at run time. glslangValidator's depfile makes edits to included
# headers (shaders/shared/*.h) trigger a rebuild, and spirv-val checks the module:
# any shader error fails the build. The header's path is returned in <out_var>.
# INCLUDES adds folders searched after shaders/ (tests' own headers).
function(vkpt_compile_shader out_var source symbol)
  cmake_parse_arguments(ARG "" "" "DEFINES;INCLUDES" ${ARGN})
  set(out_dir "${CMAKE_BINARY_DIR}/generated/shaders")
  set(header "${out_dir}/${symbol}.h")
  set(spv "${out_dir}/${symbol}.spv")
  set(defines "")
  foreach(d IN LISTS ARG_DEFINES)
    list(APPEND defines "-D${d}")
  endforeach()
  foreach(dir IN LISTS ARG_INCLUDES)
    list(APPEND defines "-I${dir}")
  endforeach()
  get_filename_component(source "${source}" ABSOLUTE)
  add_custom_command(
    OUTPUT "${header}" "${spv}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${out_dir}"
    COMMAND "${GLSLANG_VALIDATOR}" -V --target-env vulkan1.2 "-I${PROJECT_SOURCE_DIR}/shaders" "-I${VKPT_GPU_RECORDS_DIR}" ${defines}
            -o "${spv}" "${source}"
    COMMAND "${SPIRV_VAL}" --target-env vulkan1.2 "${spv}"
    # The depfile must name the first OUTPUT (the header), or make never rebuilds it
    # when an included header changes.
    COMMAND "${GLSLANG_VALIDATOR}" -V --target-env vulkan1.2 "-I${PROJECT_SOURCE_DIR}/shaders" "-I${VKPT_GPU_RECORDS_DIR}" ${defines}
            --depfile "${out_dir}/${symbol}.d" --vn "${symbol}" -o "${header}" "${source}"
    MAIN_DEPENDENCY "${source}"
    DEPENDS ${VKPT_GPU_RECORDS_FILES}
    DEPFILE "${out_dir}/${symbol}.d"
    COMMENT "glslang: ${symbol} <- ${source}"
    VERBATIM)
  set(${out_var} "${header}" PARENT_SCOPE)
endfunction()
