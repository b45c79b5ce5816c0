# cmake -DMANIFEST=<build>/layers/manifest.cmake -DSOURCE_DIR=<tree> [-DSTAMP=<file>]
#       -P cmake/CheckLayers.cmake
#
# Fails if a layer's file includes what its vkpt_layer() declaration does not allow (see
# cmake/Layers.cmake): a header of a layer it does not USE, a third-party header another
# layer OWNS, or anything by a path with "..". Also fails on a folder under an include
# root (host/, shaders/) that is no layer, as its files would be reachable yet unchecked.
# The build runs this before compiling any layer; touches STAMP when all is well.
cmake_minimum_required(VERSION 3.25)
foreach(var MANIFEST SOURCE_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CheckLayers.cmake: -D${var}=... is required")
  endif()
endforeach()
include("${MANIFEST}")

set(errors "")
set(roots "")
foreach(layer IN LISTS VKPT_LAYERS)
  set(dir "${VKPT_LAYER_${layer}_DIR}")
  get_filename_component(root "${dir}" DIRECTORY)
  list(APPEND roots "${root}")
  set(globs "")
  foreach(ext IN ITEMS h hpp cpp cc inl glsl)  # the same list as in Layers.cmake
    list(APPEND globs "${SOURCE_DIR}/${dir}/*.${ext}")
  endforeach()
  file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE "${SOURCE_DIR}" ${globs})
  list(SORT files)
  if(VKPT_LAYER_${layer}_USES)
    string(REPLACE ";" ", " uses "${VKPT_LAYER_${layer}_USES}")
  else()
    set(uses "no other layer")
  endif()

  foreach(file IN LISTS files)
    file(STRINGS "${SOURCE_DIR}/${file}" lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(NOT line MATCHES "#[ \t]*include[ \t]*([<\"])([^>\"]+)[>\"]")
        continue()
      endif()
      set(inc "${CMAKE_MATCH_2}")
      if(CMAKE_MATCH_1 STREQUAL "<")
        set(where "${file}: #include <${inc}>")
      else()
        set(where "${file}: #include \"${inc}\"")
      endif()

      # "../x.h" reaches past the layer's folder without naming a layer.
      if(inc MATCHES "(^|/)\\.\\.(/|$)")
        list(APPEND errors "${where}: no \"..\" in includes; name the layer (\"layer/file.h\")")
        continue()
      endif()

      # "layer/file.h" (or <layer/file.h>: the include roots are -I paths): a header of
      # another layer, allowed only if this layer USES it.
      if(inc MATCHES "^([^/]+)/" AND CMAKE_MATCH_1 IN_LIST VKPT_LAYERS)
        set(other "${CMAKE_MATCH_1}")
        if(NOT other STREQUAL layer AND NOT other IN_LIST VKPT_LAYER_${layer}_USES)
          list(APPEND errors "${where}: layer ${layer} may not include layer ${other} (${layer} uses ${uses})")
        endif()
      endif()

      # A third-party header another layer owns (say, Vulkan outside vk/).
      foreach(owner IN LISTS VKPT_LAYERS)
        if(owner STREQUAL layer)
          continue()
        endif()
        foreach(owned IN LISTS VKPT_LAYER_${owner}_OWNS)
          string(FIND "${inc}" "${owned}" at)
          if((owned MATCHES "/$" AND at EQUAL 0) OR inc STREQUAL owned)
            list(APPEND errors "${where}: ${owned} is for layer ${owner} only")
          endif()
        endforeach()
      endforeach()
    endforeach()
  endforeach()
endforeach()

# Every folder directly under an include root must be a layer: "foo/x.h" would otherwise
# be includable from anywhere without a check.
list(REMOVE_DUPLICATES roots)
foreach(root IN LISTS roots)
  file(GLOB children LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}/${root}" "${SOURCE_DIR}/${root}/*")
  foreach(child IN LISTS children)
    if(IS_DIRECTORY "${SOURCE_DIR}/${root}/${child}"
       AND NOT (child IN_LIST VKPT_LAYERS AND VKPT_LAYER_${child}_DIR STREQUAL "${root}/${child}"))
      list(APPEND errors "${root}/${child}/: a folder under an include root that is no layer; declare it with vkpt_layer()")
    endif()
  endforeach()
endforeach()

if(errors)
  list(LENGTH errors count)
  string(REPLACE ";" "\n  " errors "${errors}")
  message(FATAL_ERROR "layer check: ${count} include(s) break the architecture:\n  ${errors}\n"
                      "The allowed edges are the USES of each vkpt_layer() in host/CMakeLists.txt and "
                      "shaders/CMakeLists.txt. If a new edge is really meant, declare it there (it changes "
                      "the architecture: say why in the commit).")
endif()
if(DEFINED STAMP)
  file(TOUCH "${STAMP}")
endif()
