// vkpt-gen-records <gpu_records.def> <out dir>: writes the generated files of the GPU
// records (gpu_records.h says which) under <out dir>, each only when its text changes,
// so that an unchanged description rebuilds nothing. Run by the build.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "gpu_records.h"

namespace fs = std::filesystem;

namespace {

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void WriteIfChanged(const fs::path& path, const std::string& text) {
  if (fs::exists(path) && ReadFile(path) == text) return;
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: vkpt-gen-records <gpu_records.def> <out dir>\n";
    return 2;
  }
  try {
    using namespace vkpt::records;
    const Description d = Parse(ReadFile(argv[1]), argv[1]);
    const fs::path out = argv[2];
    WriteIfChanged(out / "shared/gpu_records.h", SharedHeader(d));
    WriteIfChanged(out / "gpu_fetch.glsl", FetchGlsl(d));
    WriteIfChanged(out / "scene/texture_slots.h", SlotHeader(d));
  } catch (const std::exception& e) {
    std::cerr << "vkpt-gen-records: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
