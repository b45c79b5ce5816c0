# find_package(vkpt): the imported target vkpt::vkpt, libvkpt.so with <vkpt/vkpt.h>
# (docs/api.md). Installed by `cmake --install` and the Debian package.
include("${CMAKE_CURRENT_LIST_DIR}/vkptTargets.cmake")
