# cmake -DSOURCE_DIR=<tree> -P cmake/CheckTestMacros.cmake
#
# Fails if a product source (host/ or shaders/) names a macro that only tests define:
# VKPT_MUTANT_* (deliberately wrong estimators), VKPT_MIS_* (one MIS strategy alone) or,
# on a preprocessor line, VKPT_TEST_*. Tests reach the estimator through its seams
# (shaders/shared/path.h) and tests/shaders/estimator_overrides.h instead, so product
# code never carries a branch that only a test build takes. (VKPT_TEST_* environment
# variables, read at run time, are not macros and stay allowed outside the preprocessor.)
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED SOURCE_DIR)
  message(FATAL_ERROR "CheckTestMacros.cmake: -DSOURCE_DIR=... is required")
endif()

set(globs "")
foreach(root IN ITEMS host shaders)
  foreach(ext IN ITEMS h hpp cpp cc inl glsl comp)
    list(APPEND globs "${SOURCE_DIR}/${root}/*.${ext}")
  endforeach()
endforeach()
file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE "${SOURCE_DIR}" ${globs})
list(SORT files)

set(errors "")
foreach(file IN LISTS files)
  file(STRINGS "${SOURCE_DIR}/${file}" lines REGEX "VKPT_(MUTANT|MIS_|TEST_)")
  foreach(line IN LISTS lines)
    if(line MATCHES "(VKPT_MUTANT[A-Z0-9_]*|VKPT_MIS_[A-Z0-9_]*)")
      string(APPEND errors "${file}: ${CMAKE_MATCH_1}: a test-only macro in product code\n")
    elseif(line MATCHES "^[ \t]*#.*(VKPT_TEST_[A-Z0-9_]*)")
      string(APPEND errors "${file}: ${CMAKE_MATCH_1}: a test-only macro in product code\n")
    endif()
  endforeach()
endforeach()

if(errors)
  message(FATAL_ERROR "Test-only macros in host/ or shaders/ (tests replace the estimator's seams through "
                      "tests/shaders/estimator_overrides.h instead):\n${errors}")
endif()
list(LENGTH files count)
message(STATUS "CheckTestMacros: ${count} files of host/ and shaders/ name no test-only macro")
