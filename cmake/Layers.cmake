# The architecture, enforced: one library per layer, and a build step that fails on an
# #include between layers that CMakeLists.txt does not declare.
#
# Every layer sits under one include root (host/, shaders/), so the compiler alone cannot
# stop host/scene/ from including "vk/context.h": a target that links any layer sees every
# header under that root. vkpt_layer() therefore records which layers each one may use,
# and vkpt_check_layers() adds a build step (cmake/CheckLayers.cmake) that reads every
# #include in every layer's files and fails the build on one that is not declared. The
# declarations are the allowlist: what a layer USES is both what it links and what its
# files may include, and nothing else.

set_property(GLOBAL PROPERTY VKPT_LAYERS "")

# vkpt_layer(<name> [USES <layer>...] [OWNS <header>...] [SOURCES <file>...])
#
# Declares the layer <name>: its files live in <current source dir>/<name>/ and are
# included as "<name>/file.h", from the current source dir as include root. Creates the
# library vkpt_<name> from SOURCES (an INTERFACE library without them).
#   USES  the layers whose headers its files may include (linked PUBLIC). Each must be
#         declared before, so the layers form a DAG in declaration order: no cycles.
#   OWNS  third-party headers only this layer may include: a file ("tiny_gltf.h") or a
#         folder ending in "/" ("vulkan/"). This keeps, say, glTF out of the renderers
#         even though /usr/include is visible to everyone.
function(vkpt_layer name)
  cmake_parse_arguments(PARSE_ARGV 1 L "" "" "USES;OWNS;SOURCES")
  if(L_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "vkpt_layer(${name}): unexpected arguments ${L_UNPARSED_ARGUMENTS}")
  endif()
  get_property(layers GLOBAL PROPERTY VKPT_LAYERS)
  if(name IN_LIST layers)
    message(FATAL_ERROR "vkpt_layer(${name}): declared twice")
  endif()
  set(deps "")
  foreach(dep IN LISTS L_USES)
    if(NOT dep IN_LIST layers)
      message(FATAL_ERROR "vkpt_layer(${name}): uses \"${dep}\", which is not a layer declared before it "
                          "(layers are declared in dependency order, so they cannot form a cycle)")
    endif()
    list(APPEND deps vkpt_${dep})
  endforeach()

  set(dir "${CMAKE_CURRENT_SOURCE_DIR}/${name}")
  if(NOT IS_DIRECTORY "${dir}")
    message(FATAL_ERROR "vkpt_layer(${name}): no folder ${dir}")
  endif()
  # A file compiles into the layer of its folder: util/x.cpp listed under scene would build
  # and link, yet sit in the wrong layer (a merge can do that silently).
  foreach(source IN LISTS L_SOURCES)
    cmake_path(ABSOLUTE_PATH source NORMALIZE OUTPUT_VARIABLE path)
    cmake_path(IS_PREFIX dir "${path}" NORMALIZE inside)
    if(NOT inside)
      message(FATAL_ERROR "vkpt_layer(${name}): ${source} is not in ${name}/; list it under the layer of its folder")
    endif()
  endforeach()
  if(L_SOURCES)
    add_library(vkpt_${name} STATIC ${L_SOURCES})
    target_include_directories(vkpt_${name} PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}")
    target_link_libraries(vkpt_${name} PUBLIC ${deps})
  else()
    add_library(vkpt_${name} INTERFACE)
    target_include_directories(vkpt_${name} INTERFACE "${CMAKE_CURRENT_SOURCE_DIR}")
    target_link_libraries(vkpt_${name} INTERFACE ${deps})
  endif()

  # What the include check needs, relative to the source tree (the check's own test runs
  # it on a copy of the tree).
  file(RELATIVE_PATH rel "${PROJECT_SOURCE_DIR}" "${dir}")
  set_property(GLOBAL APPEND PROPERTY VKPT_LAYERS ${name})
  set_property(GLOBAL PROPERTY VKPT_LAYER_${name}_DIR "${rel}")
  set_property(GLOBAL PROPERTY VKPT_LAYER_${name}_USES "${L_USES}")
  set_property(GLOBAL PROPERTY VKPT_LAYER_${name}_OWNS "${L_OWNS}")
endfunction()

# vkpt_check_layers(): call once, after every layer is declared. Writes the manifest the
# check reads and adds the build step every layer's library waits for, so a forbidden
# include fails `cmake --build` before anything compiles. The step reruns only when a
# layer's file (or a declaration) changes.
function(vkpt_check_layers)
  get_property(layers GLOBAL PROPERTY VKPT_LAYERS)
  set(manifest "${CMAKE_BINARY_DIR}/layers/manifest.cmake")
  set(text "# Written by vkpt_check_layers() (cmake/Layers.cmake); read by cmake/CheckLayers.cmake.\n")
  string(APPEND text "set(VKPT_LAYERS \"${layers}\")\n")
  set(files "")
  foreach(layer IN LISTS layers)
    foreach(key DIR USES OWNS)
      get_property(value GLOBAL PROPERTY VKPT_LAYER_${layer}_${key})
      string(APPEND text "set(VKPT_LAYER_${layer}_${key} \"${value}\")\n")
    endforeach()
    get_property(dir GLOBAL PROPERTY VKPT_LAYER_${layer}_DIR)
    # CONFIGURE_DEPENDS: a new file in a layer reruns the glob, so it is checked too.
    set(globs "")
    foreach(ext IN ITEMS h hpp cpp cc inl glsl)  # the same list as in CheckLayers.cmake
      list(APPEND globs "${PROJECT_SOURCE_DIR}/${dir}/*.${ext}")
    endforeach()
    file(GLOB_RECURSE layer_files CONFIGURE_DEPENDS ${globs})
    list(APPEND files ${layer_files})
  endforeach()
  file(CONFIGURE OUTPUT "${manifest}" CONTENT "${text}")

  set(stamp "${CMAKE_BINARY_DIR}/layers/checked.stamp")
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND "${CMAKE_COMMAND}" "-DMANIFEST=${manifest}" "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}" "-DSTAMP=${stamp}"
            -P "${PROJECT_SOURCE_DIR}/cmake/CheckLayers.cmake"
    DEPENDS "${manifest}" "${PROJECT_SOURCE_DIR}/cmake/CheckLayers.cmake" ${files}
    COMMENT "Checking #includes against the allowed layer edges"
    VERBATIM)
  add_custom_target(vkpt_layer_check ALL DEPENDS "${stamp}")
  foreach(layer IN LISTS layers)
    add_dependencies(vkpt_${layer} vkpt_layer_check)
  endforeach()
endfunction()
