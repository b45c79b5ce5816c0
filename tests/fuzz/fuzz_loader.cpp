// libFuzzer target for the glTF loader: every input is written as scene.glb (when it
// starts with "glTF") or scene.gltf into a private empty directory and loaded with
// LoadGltf. A Scene or a Error is the expected outcome; anything else is a
// finding: a crash, a sanitizer report (built with address,undefined), another
// exception, a timeout or too much memory (libFuzzer's -timeout, -rss_limit_mb,
// -malloc_limit_mb). Build and run: README.md, "Sanitizers and fuzzing".
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "fuzz_input.h"

namespace {

const std::string& Dir() {
  static const std::string dir = [] {
    std::string d = vkpt::internal::fuzz::MakePrivateDir("vkpt-fuzz");
    std::atexit([] { ::rmdir(Dir().c_str()); });
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    vkpt::internal::fuzz::LoadInput(Dir(), {reinterpret_cast<const char*>(data), size});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_loader: LoadGltf threw %s, not vkpt::internal::Error: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz_loader: LoadGltf threw something that is not a std::exception\n");
    std::abort();
  }
  return 0;
}
