# `cpack -G DEB` (from the build folder): a Debian package of what `cmake --install`
# installs (vkpt and vkpt-bench in /usr/bin). Its Depends are the Debian packages that
# hold the shared libraries the programs load, plus the Vulkan driver: each target that
# installs appends its own to the global property VKPT_PACKAGE_DEPENDS beside its link
# line (host/CMakeLists.txt, bench/CMakeLists.txt). The test Package.Deb checks the list
# against what the installed programs really load.
# The CMake package of the library (host/CMakeLists.txt installs its targets).
include(CMakePackageConfigHelpers)
write_basic_package_version_file("${CMAKE_BINARY_DIR}/vkptConfigVersion.cmake" COMPATIBILITY SameMajorVersion)
install(FILES cmake/vkptConfig.cmake "${CMAKE_BINARY_DIR}/vkptConfigVersion.cmake"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/vkpt")

get_property(depends GLOBAL PROPERTY VKPT_PACKAGE_DEPENDS)
list(REMOVE_DUPLICATES depends)
list(SORT depends)
list(JOIN depends ", " CPACK_DEBIAN_PACKAGE_DEPENDS)

set(CPACK_PACKAGE_NAME vkpt)
set(CPACK_PACKAGE_VENDOR "vkpt maintainers")
# The Maintainer field; a release build can set its own.
set(VKPT_PACKAGE_MAINTAINER "vkpt maintainers <maintainers@users.noreply.h-seed-46c82e57.example>"
    CACHE STRING "Maintainer of the Debian package")
set(CPACK_PACKAGE_CONTACT "${VKPT_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "portable Vulkan compute path tracer for glTF 2.0 scenes")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
  "vkpt renders glTF 2.0 scenes by Monte Carlo path tracing on any Vulkan compute device "
  "(including Mesa's lavapipe on the CPU), with a multithreaded CPU reference renderer "
  "running the same estimator. vkpt-bench measures BVH build, traversal and path tracing.")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # vkpt_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
include(CPack)
