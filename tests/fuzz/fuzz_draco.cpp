// libFuzzer target for the KHR_draco_mesh_compression decoder, DecodeDraco
// (gltf/draco_decode.h), in memory: fuzz_bodies.h's RunDraco says how the input is
// laid out. A Error is the expected outcome of a refusal; anything else is a
// finding (fuzz_target.h).
#include <cstdint>
#include <new>
#include <string_view>

#include "fuzz_bodies.h"
#include "fuzz_target.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkpt::internal::fuzz::ExpectOnly<vkpt::internal::Error>("fuzz_draco", "vkpt::internal::Error", [&] {
    // std::bad_alloc is a clean refusal too: the loader turns it into a Error
    // (GltfAsset). Under ASan an allocation past -malloc_limit_mb is reported before it
    // could throw, so this does not hide a runaway allocation.
    try {
      vkpt::internal::fuzz::RunDraco({reinterpret_cast<const char*>(data), size});
    } catch (const std::bad_alloc&) {}
  });
  return 0;
}
