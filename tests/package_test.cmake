# cmake -DCPACK=<cpack> -DCONFIG=<build>/CPackConfig.cmake -DVERSION=<x.y.z> -DWORK=<scratch dir>
#       -P tests/package_test.cmake
#
# The Debian package is built and used as a user would: `cpack -G DEB`, unpacked with
# `dpkg -x` into a scratch root (no root rights, nothing installed on the machine), and
# the unpacked vkpt must run. Fails if the install rules are missing (no programs in the
# package), and if a shared library the programs load comes from a Debian package the
# package's Depends does not list.
cmake_minimum_required(VERSION 3.25)
foreach(var CPACK CONFIG VERSION WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "package_test.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "`${command}` failed (${result}):\n${out}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK}")
run("${CPACK}" -G DEB --config "${CONFIG}" -B "${WORK}/out")
file(GLOB debs "${WORK}/out/*.deb")
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one .deb in ${WORK}/out, found ${count}: ${debs}")
endif()
set(root "${WORK}/root")
run(dpkg -x "${debs}" "${root}")

foreach(program vkpt vkpt-bench)
  if(NOT EXISTS "${root}/usr/bin/${program}")
    message(FATAL_ERROR "the package has no /usr/bin/${program} (are its install() rules missing?)")
  endif()
endforeach()
run("${root}/usr/bin/vkpt" --version)
if(NOT out MATCHES "^vkpt ${VERSION}")
  message(FATAL_ERROR "`vkpt --version` from the package printed \"${out}\", not \"vkpt ${VERSION}\"")
endif()

# Every library the programs link directly (DT_NEEDED) must come from a listed package.
# dpkg -S knows a file by the path its package ships it at, /lib/... or /usr/lib/...
# (merged /usr), so try the path ldd found and its other spelling.
run(dpkg-deb -f "${debs}" Depends)
string(REGEX REPLACE " *\\([^)]*\\)" "" depends "${out}")  # drop version constraints
string(REGEX REPLACE "[ \n]" "" depends "${depends}")
string(REPLACE "," ";" depends "${depends}")
set(missing "")
foreach(program vkpt vkpt-bench)
  run(readelf -d "${root}/usr/bin/${program}")
  string(REGEX MATCHALL "\\(NEEDED\\)[^[]*\\[[^]]+\\]" needed "${out}")
  run(ldd "${root}/usr/bin/${program}")
  set(ldd "${out}")
  string(REPLACE "\n" ";" ldd_lines "${ldd}")
  foreach(entry IN LISTS needed)
    string(REGEX REPLACE ".*\\[(.+)\\]" "\\1" lib "${entry}")
    set(path "")
    foreach(line IN LISTS ldd_lines)  # "\tlibfoo.so.1 => /lib/x86_64-linux-gnu/libfoo.so.1 (0x...)"
      if(line MATCHES "^[ \t]*([^ ]+) => ([^ ]+)" AND CMAKE_MATCH_1 STREQUAL lib)
        set(path "${CMAKE_MATCH_2}")
      elseif(line MATCHES "^[ \t]*(/[^ ]+) \\(")  # the dynamic loader: "\t/lib64/ld-linux-x86-64.so.2 (0x...)"
        get_filename_component(name "${CMAKE_MATCH_1}" NAME)
        if(name STREQUAL lib)
          set(path "${CMAKE_MATCH_1}")
        endif()
      endif()
    endforeach()
    if(NOT path)
      message(FATAL_ERROR "${program}: ldd does not resolve ${lib}:\n${ldd}")
    endif()
    string(REGEX REPLACE "^/usr/" "/" other "${path}")
    if(other STREQUAL path)
      set(other "/usr${path}")
    endif()
    set(package "")
    foreach(candidate "${path}" "${other}")
      execute_process(COMMAND dpkg -S "${candidate}" RESULT_VARIABLE result OUTPUT_VARIABLE found ERROR_QUIET)
      if(result EQUAL 0)
        string(REGEX REPLACE "[:,].*" "" package "${found}")  # "libc6:amd64: /lib/..."
        break()
      endif()
    endforeach()
    if(NOT package)
      message(FATAL_ERROR "${program}: no Debian package owns ${path} (${lib})")
    endif()
    if(NOT package IN_LIST depends)
      list(APPEND missing "${package} (${program} loads ${lib})")
    endif()
  endforeach()
endforeach()
if(missing)
  list(REMOVE_DUPLICATES missing)
  string(REPLACE ";" ", " missing "${missing}")
  message(FATAL_ERROR "the package's Depends (${depends}) lacks ${missing}: append it to "
                      "VKPT_PACKAGE_DEPENDS beside the link line (see cmake/Package.cmake)")
endif()
string(REPLACE ";" ", " depends "${depends}")
message(STATUS "${debs}: vkpt ${VERSION} runs from the unpacked package; Depends: ${depends}")
