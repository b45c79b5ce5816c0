// Sanitizer builds compile this file instead of path_variant.cpp's 14 builds
// (tests/CMakeLists.txt): every test that renders a variant skips there
// (VKPT_REQUIRE_PATH_VARIANTS), so a call reaching one of these is a test's mistake.
#include <cstdio>
#include <cstdlib>

#include "path_variants.h"

namespace vkpt::internal::test {

#define VKPT_PATH_VARIANT_STUB(name)                                                                              \
  RenderResult name(const RenderScene&, const shader::FrameParams&) {                                             \
    std::fprintf(stderr, "%s: not built in sanitizer builds; the test must VKPT_REQUIRE_PATH_VARIANTS\n", #name); \
    std::abort();                                                                                                 \
  }
#include "path_variant_stubs.inc"  // one VKPT_PATH_VARIANT_STUB(name) per variant, written by CMake

}  // namespace vkpt::internal::test
