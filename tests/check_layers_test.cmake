# cmake -DMANIFEST=<build>/layers/manifest.cmake -DSOURCE_DIR=<checkout> -DWORK=<scratch dir>
#       -P tests/check_layers_test.cmake
#
# The layer check (cmake/CheckLayers.cmake) guards the architecture only if it really
# fails on a forbidden include; a check that silently passes everything would look just
# like a clean tree. So: on a copy of the layers' folders, the unchanged copy must pass,
# and each planted violation must fail with a message naming the file and the rule.
cmake_minimum_required(VERSION 3.25)
include("${MANIFEST}")

set(tree "${WORK}/tree")
file(REMOVE_RECURSE "${WORK}")
foreach(layer IN LISTS VKPT_LAYERS)
  get_filename_component(parent "${tree}/${VKPT_LAYER_${layer}_DIR}" DIRECTORY)
  file(COPY "${SOURCE_DIR}/${VKPT_LAYER_${layer}_DIR}" DESTINATION "${parent}")
endforeach()

function(run_check out_result out_output)
  execute_process(
    COMMAND "${CMAKE_COMMAND}" "-DMANIFEST=${MANIFEST}" "-DSOURCE_DIR=${tree}"
            -P "${SOURCE_DIR}/cmake/CheckLayers.cmake"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  set(${out_result} "${result}" PARENT_SCOPE)
  set(${out_output} "${output}" PARENT_SCOPE)
endfunction()

run_check(result output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the unchanged tree fails the layer check:\n${output}")
endif()

# expect_failure(<file> <line to append> <text the failure must contain>)
function(expect_failure file line expected)
  set(path "${tree}/${file}")
  set(existed FALSE)
  if(EXISTS "${path}")
    set(existed TRUE)
    file(READ "${path}" original)
  endif()
  file(APPEND "${path}" "\n${line}\n")
  run_check(result output)
  if(existed)
    file(WRITE "${path}" "${original}")
  else()
    file(REMOVE "${path}")
    get_filename_component(dir "${path}" DIRECTORY)
    file(GLOB left "${dir}/*")
    if(NOT left)
      file(REMOVE_RECURSE "${dir}")  # the (empty) folder made for the case
    endif()
  endif()
  string(FIND "${output}" "${expected}" at)
  if(result EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "${file} + `${line}`: expected the layer check to fail with \"${expected}\"; "
                        "exit ${result}, output:\n${output}")
  endif()
  message(STATUS "caught: ${file} + `${line}`")
endfunction()

# scene is below the renderers: it must not see Vulkan's layer, in either include form.
expect_failure(host/scene/scene.h [[#include "vk/context.h"]]
  [[host/scene/scene.h: #include "vk/context.h": layer scene may not include layer vk]])
expect_failure(host/scene/camera.cpp [[#include <vk/vk_renderer.h>]]
  "layer scene may not include layer vk")
# Not only Vulkan: a lower layer including a higher one.
expect_failure(host/util/bounds.h [[#include "bvh/bvh.h"]] "layer util may not include layer bvh")
expect_failure(shaders/shared/layout.h [[#include "util/bounds.h"]] "layer shared may not include layer util")
# vk knows no glTF: neither the gltf layer nor tinygltf itself; the scene model knows no
# glTF either.
expect_failure(host/vk/buffer.cpp [[#include "gltf/gltf_loader.h"]] "layer vk may not include layer gltf")
expect_failure(host/vk/buffer.cpp [[#include <tiny_gltf.h>]] "tiny_gltf.h is for layer gltf only")
expect_failure(host/scene/camera.cpp [[#include "gltf/gltf_source.h"]] "layer scene may not include layer gltf")
expect_failure(host/scene/camera.cpp [[#include <tiny_gltf.h>]] "tiny_gltf.h is for layer gltf only")
# The session knows no device: the engine chooses the backend (engine/render_backend.h),
# the session renders a frame from whichever it is given.
expect_failure(host/session/budget.cpp [[#include "vk/context.h"]] "layer session may not include layer vk")
expect_failure(host/session/budget.cpp [[#include "cpu/path_tracer.h"]] "layer session may not include layer cpu")
expect_failure(host/cpu/traversal.cpp [[#include <vulkan/vulkan_core.h>]] "vulkan/ is for layer vk only")
# No way around it by a relative path, or a new folder under an include root.
expect_failure(host/cpu/traversal.cpp [[#include "../vk/context.h"]] "no \"..\" in includes")
expect_failure(host/extra/x.h [[#pragma once]] "host/extra/: a folder under an include root that is no layer")
