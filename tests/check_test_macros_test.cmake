# cmake -DSOURCE_DIR=<checkout> -DWORK=<scratch dir> -P tests/check_test_macros_test.cmake
#
# cmake/CheckTestMacros.cmake keeps test-only macros out of host/ and shaders/ only if it
# really fails on one: on a copy of the two folders, the unchanged copy must pass, and
# each planted macro must fail with a message naming the file and the macro.
cmake_minimum_required(VERSION 3.25)

set(tree "${WORK}/tree")
file(REMOVE_RECURSE "${WORK}")
file(COPY "${SOURCE_DIR}/host" "${SOURCE_DIR}/shaders" DESTINATION "${tree}")

function(run_check out_result out_output)
  execute_process(
    COMMAND "${CMAKE_COMMAND}" "-DSOURCE_DIR=${tree}" -P "${SOURCE_DIR}/cmake/CheckTestMacros.cmake"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  set(${out_result} "${result}" PARENT_SCOPE)
  set(${out_output} "${output}" PARENT_SCOPE)
endfunction()

run_check(result output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the unchanged tree fails the check:\n${output}")
endif()

# expect_failure(<file> <line to append> <text the failure must contain>)
function(expect_failure file line expected)
  set(path "${tree}/${file}")
  file(READ "${path}" original)
  file(APPEND "${path}" "\n${line}\n")
  run_check(result output)
  file(WRITE "${path}" "${original}")
  string(FIND "${output}" "${expected}" at)
  if(result EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "${file} + `${line}`: expected the check to fail with \"${expected}\"; "
                        "exit ${result}, output:\n${output}")
  endif()
  message(STATUS "caught: ${file} + `${line}`")
endfunction()

# The forms the shared estimator carried before its seams, in GLSL and C++ headers alike.
expect_failure(shaders/shared/lights.h "#ifdef VKPT_MUTANT_SPOT_FALLOFF_LINEAR"
  "shaders/shared/lights.h: VKPT_MUTANT_SPOT_FALLOFF_LINEAR")
expect_failure(shaders/shared/path.h "#if defined(VKPT_MIS_LIGHT_ONLY) || defined(X)"
  "shaders/shared/path.h: VKPT_MIS_LIGHT_ONLY")
expect_failure(shaders/trace.comp "#ifdef VKPT_TEST_LOOP_BUDGET" "shaders/trace.comp: VKPT_TEST_LOOP_BUDGET")
expect_failure(shaders/scene_fetch.glsl "  #  ifndef VKPT_TEST_PROBE" "shaders/scene_fetch.glsl: VKPT_TEST_PROBE")
# Host code too, and a mutant's name in a comment (a leftover is a leftover).
expect_failure(host/vk/vk_renderer.cpp "#if VKPT_MUTANT" "host/vk/vk_renderer.cpp: VKPT_MUTANT")
expect_failure(host/cpu/path_tracer.h "// see VKPT_MUTANT_NO_LIGHT_COSINE" "host/cpu/path_tracer.h: VKPT_MUTANT")
# A run-time environment variable is not a macro.
file(APPEND "${tree}/host/app/options.cpp" "\n// getenv(\"VKPT_TEST_SOMETHING\")\n")
run_check(result output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "a VKPT_TEST_ environment variable outside the preprocessor failed the check:\n${output}")
endif()
