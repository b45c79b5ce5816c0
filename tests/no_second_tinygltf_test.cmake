# cmake -DNM=<nm> -DDRACO_ARCHIVE=<libdraco.a> -DBINARIES="<vkpt>;<vkpt_tests>" -P tests/no_second_tinygltf_test.cmake
#
# Debian's libdraco carries a tinygltf of its own; linked in, it would stand beside the
# libtinygltf vkpt reads glTF with (host/CMakeLists.txt says how the link avoids it). No
# vkpt binary may define a tinygltf function. The check has teeth: the same pattern must
# find the functions in libdraco's own member.
cmake_minimum_required(VERSION 3.25)

function(defined_tinygltf file out)
  execute_process(COMMAND "${NM}" -C --defined-only "${file}" OUTPUT_VARIABLE symbols ERROR_QUIET RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nm failed on ${file}")
  endif()
  string(REGEX MATCHALL "[^\n]* T tinygltf::[^\n]*" found "${symbols}")
  list(LENGTH found n)
  set(${out} ${n} PARENT_SCOPE)
endfunction()

defined_tinygltf("${DRACO_ARCHIVE}" in_draco)
if(in_draco EQUAL 0)
  message(FATAL_ERROR "the check finds no tinygltf function in ${DRACO_ARCHIVE}: it has no teeth")
endif()
foreach(binary IN LISTS BINARIES)
  defined_tinygltf("${binary}" n)
  if(NOT n EQUAL 0)
    message(FATAL_ERROR "${binary} defines ${n} tinygltf functions: a second tinygltf (libdraco's) is linked in")
  endif()
endforeach()
message(STATUS "no second tinygltf in ${BINARIES}; ${in_draco} tinygltf functions in libdraco's member")
