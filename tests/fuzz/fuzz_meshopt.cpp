// libFuzzer target for the EXT_meshopt_compression decoder (gltf/meshopt_decode.h), in
// memory: fuzz_bodies.h's RunMeshopt says how the input is
// laid out. A Error is the expected outcome of a refusal; anything else is a
// finding (fuzz_target.h).
#include <cstdint>
#include <new>
#include <string_view>

#include "fuzz_bodies.h"
#include "fuzz_target.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::internal::fuzz::ExpectOnly<vkpt::internal::Error>("fuzz_meshopt", "vkpt::internal::Error", [&] {
    // std::bad_alloc is a clean refusal too: the loader turns it into a Error
    // (GltfAsset). Under ASan an allocation past -malloc_limit_mb is reported before it
    // could throw, so this does not hide a runaway allocation.
    try {
      vkpt::internal::fuzz::RunMeshopt({reinterpret_cast<const char*>(data), size});
    } catch (const std::bad_alloc&) {}
  });
  return 0;
}
