# cmake -DSOURCE_DIR=<checkout> -DWORK=<scratch dir> -P tests/backend_contract_test.cmake
#
# shaders/shared/backend_contract.h lists what a backend defines before it includes
# shaders/shared/. Checks, for each backend the contract names, that its files define
# every name the contract requires of that backend and no VKPT_ macro the contract lists
# nowhere; that the contract's #error checks cover exactly its required macros; and, on a
# copy of those files, that a planted omission or extra name is caught (or the check
# would guard nothing).
cmake_minimum_required(VERSION 3.25)

set(contract_file "shaders/shared/backend_contract.h")
set(cpp_estimator shaders/shared/cpp_prelude.h host/render/scene_access.h host/cpu/cpu_trace.h
    host/cpu/light_importances_sse2.h)
set(glsl_estimator shaders/shared/glsl_prelude.h shaders/scene_constants.glsl shaders/scene_fetch.glsl
    shaders/traverse.glsl)
set(cpp_denoiser shaders/shared/cpp_prelude.h host/render/denoise.cpp)
set(glsl_denoiser shaders/shared/glsl_prelude.h shaders/denoise.comp)
# Other files that define contract names for the shared headers (a kernel's own
# settings, the CPU's second instantiation): checked for unlisted names only.
set(other_definers shaders/pathtrace.comp shaders/aov.comp shaders/trace.comp host/cpu/simple_path.cpp)

# check_tree(<tree> <out_errors>): the errors of the tree's backends against its contract.
function(check_tree tree out_errors)
  set(errors "")
  file(STRINGS "${tree}/${contract_file}" table REGEX "^//   \\[[a-z]+\\] ")
  foreach(kind IN ITEMS language scene function capability denoise internal test)
    set(${kind} "")
  endforeach()
  set(listed "")
  foreach(line IN LISTS table)
    if(NOT line MATCHES "^//   \\[([a-z]+)\\] ([A-Za-z_][A-Za-z0-9_]*)")
      continue()
    endif()
    set(kind "${CMAKE_MATCH_1}")
    set(name "${CMAKE_MATCH_2}")
    if(NOT kind MATCHES "^(language|scene|function|capability|denoise|internal|test)$")
      string(APPEND errors "${contract_file}: unknown kind [${kind}]\n")
      continue()
    endif()
    list(APPEND ${kind} "${name}")
    list(APPEND listed "${name}")
  endforeach()
  if(NOT language OR NOT scene OR NOT function)
    string(APPEND errors "${contract_file}: no table of names found\n")
  endif()

  # The #error checks: exactly the macros every estimator backend must define.
  file(READ "${tree}/${contract_file}" text)
  string(REGEX MATCHALL "#ifndef (VKPT_[A-Z0-9_]+)\n#error" checks "${text}")
  set(checked "")
  foreach(c IN LISTS checks)
    string(REGEX REPLACE "#ifndef (VKPT_[A-Z0-9_]+)\n#error" "\\1" name "${c}")
    list(APPEND checked "${name}")
  endforeach()
  set(required_macros ${language} ${scene})
  list(SORT checked)
  list(SORT required_macros)
  if(NOT checked STREQUAL required_macros)
    string(APPEND errors "${contract_file}: the #error checks (${checked}) are not the language and scene "
                         "names of the table (${required_macros})\n")
  endif()

  foreach(backend IN ITEMS cpp_estimator glsl_estimator cpp_denoiser glsl_denoiser other_definers)
    set(defined "")
    set(functions "")
    foreach(file IN LISTS ${backend})
      file(READ "${tree}/${file}" body)
      string(REGEX MATCHALL "#[ \t]*define[ \t]+VKPT_[A-Z0-9_]+" defines "${body}")
      foreach(d IN LISTS defines)
        string(REGEX REPLACE "#[ \t]*define[ \t]+" "" name "${d}")
        if(NOT name MATCHES "_(H|GLSL)$")  # include guards
          list(APPEND defined "${name}")
        endif()
      endforeach()
      foreach(f IN LISTS function)
        if(body MATCHES "(HitRecord|bool)[ \t]+${f}[ \t]*\\(")
          list(APPEND functions "${f}")
        endif()
      endforeach()
    endforeach()
    list(REMOVE_DUPLICATES defined)
    foreach(name IN LISTS defined)
      if(NOT name IN_LIST listed)
        string(APPEND errors "${backend}: defines ${name}, which ${contract_file} lists nowhere\n")
      endif()
    endforeach()
    if(backend MATCHES "estimator")
      set(required ${language} ${scene})
      set(required_functions ${function})
    elseif(backend MATCHES "denoiser")
      set(required ${language} ${denoise})
      set(required_functions "")
    else()
      set(required "")
      set(required_functions "")
    endif()
    foreach(name IN LISTS required)
      if(NOT name IN_LIST defined)
        string(APPEND errors "${backend}: omits ${name}, which ${contract_file} requires\n")
      endif()
    endforeach()
    foreach(f IN LISTS required_functions)
      if(NOT f IN_LIST functions)
        string(APPEND errors "${backend}: defines no function ${f}, which ${contract_file} requires\n")
      endif()
    endforeach()
  endforeach()
  set(${out_errors} "${errors}" PARENT_SCOPE)
endfunction()

check_tree("${SOURCE_DIR}" errors)
if(errors)
  message(FATAL_ERROR "The backends break their contract:\n${errors}")
endif()
message(STATUS "both estimator and both denoiser backends define what ${contract_file} lists")

# Teeth: on a copy of the files, each planted fault must be caught with its message.
set(tree "${WORK}/tree")
file(REMOVE_RECURSE "${WORK}")
foreach(file IN LISTS contract_file cpp_estimator glsl_estimator cpp_denoiser glsl_denoiser other_definers)
  get_filename_component(dir "${tree}/${file}" DIRECTORY)
  file(COPY "${SOURCE_DIR}/${file}" DESTINATION "${dir}")
endforeach()

# expect_caught(<file> <regex> <replacement> <text the errors must contain>)
function(expect_caught file regex replacement expected)
  set(path "${tree}/${file}")
  file(READ "${path}" original)
  string(REGEX REPLACE "${regex}" "${replacement}" planted "${original}")
  if(planted STREQUAL original)
    message(FATAL_ERROR "${file}: `${regex}` matched nothing; the planted fault is no fault")
  endif()
  file(WRITE "${path}" "${planted}")
  check_tree("${tree}" errors)
  file(WRITE "${path}" "${original}")
  string(FIND "${errors}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${file} with `${regex}` -> `${replacement}`: expected \"${expected}\", got:\n${errors}")
  endif()
  message(STATUS "caught: ${expected}")
endfunction()

# A backend that omits a required name, in either language.
expect_caught(host/render/scene_access.h "#define VKPT_ENV_CDF[^\n]*\n" ""
  "cpp_estimator: omits VKPT_ENV_CDF")
expect_caught(shaders/shared/glsl_prelude.h "#define VKPT_PRECISE[^\n]*\n" ""
  "glsl_estimator: omits VKPT_PRECISE")
expect_caught(shaders/denoise.comp "#define VKPT_DENOISE_GUIDE[^\n]*\n" ""
  "glsl_denoiser: omits VKPT_DENOISE_GUIDE")
expect_caught(host/cpu/cpu_trace.h "bool TraceOccluded" "bool TraceBlocked"
  "cpp_estimator: defines no function TraceOccluded")
# One that defines a name listed nowhere.
expect_caught(shaders/scene_constants.glsl "#define VKPT_SCENE_ARG\n" "#define VKPT_SCENE_ARG\n#define VKPT_SCENE_EXTRA 1\n"
  "glsl_estimator: defines VKPT_SCENE_EXTRA, which")
expect_caught(host/render/scene_access.h "#define VKPT_ALPHA" "#define VKPT_ALPHA_TESTED 1\n#define VKPT_ALPHA"
  "cpp_estimator: defines VKPT_ALPHA_TESTED, which")
expect_caught(shaders/trace.comp "#define VKPT_TWO_TRIANGLE_BUFFERS" "#define VKPT_ONE_TRIANGLE_BUFFER"
  "other_definers: defines VKPT_ONE_TRIANGLE_BUFFER, which")
# A contract whose #error checks and table disagree.
expect_caught(${contract_file} "#ifndef VKPT_ENV_TEXEL\n#error[^\n]*\n#endif\n" ""
  "the #error checks")
