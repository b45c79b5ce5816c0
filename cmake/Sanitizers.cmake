# VKPT_SANITIZE: a comma-separated -fsanitize= list (e.g. "address,undefined") applied
# to the compile and link of every target in the tree: vkpt, vkpt-bench, vkpt_tests
# (whose own harness code tests/CMakeLists.txt compiles uninstrumented).
# Any finding ends the process (-fno-sanitize-recover=all), so a test that triggers one
# fails. Run the tests with the options in .ci/run (docs/testing.md, "Sanitizers and fuzzing"):
# they name the leak suppressions for the Vulkan driver and validation layer
# (tests/sanitizers/lsan.supp).
#
# The build type "Sanitize" (-O1 -g1) is the default of sanitizer and fuzz builds (see
# CMakeLists.txt): with ASan+UBSan it compiles in half the time of -O2 -g, and its stack
# traces still have file:line.
set(VKPT_SANITIZE "" CACHE STRING
  "Sanitizers for every target, a -fsanitize= list such as address,undefined (empty: none)")
set(CMAKE_CXX_FLAGS_SANITIZE "-O1 -g1" CACHE STRING "C++ flags of the Sanitize build type")

if(VKPT_SANITIZE)
  if(NOT VKPT_SANITIZE MATCHES "^[a-z-]+(,[a-z-]+)*$")
    message(FATAL_ERROR "VKPT_SANITIZE=\"${VKPT_SANITIZE}\": expected a comma-separated list such as address,undefined")
  endif()
  set(VKPT_SANITIZE_FLAGS
    "-fsanitize=${VKPT_SANITIZE}" -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_compile_options(${VKPT_SANITIZE_FLAGS})
  add_link_options(${VKPT_SANITIZE_FLAGS})
  message(STATUS "vkpt: sanitizers ${VKPT_SANITIZE} on every target")
endif()

# vkpt_sanitize_executables(<target>...): with AddressSanitizer, whose leak check runs at
# exit, links tests/sanitizers/keep_libraries_loaded.cpp into each executable: the Vulkan
# driver and layer stay loaded, so their leaks are named by library (see the file).
function(vkpt_sanitize_executables)
  if(VKPT_SANITIZE MATCHES "(^|,)address(,|$)")
    foreach(target IN LISTS ARGN)
      target_sources(${target} PRIVATE "${PROJECT_SOURCE_DIR}/tests/sanitizers/keep_libraries_loaded.cpp")
    endforeach()
  endif()
endfunction()
