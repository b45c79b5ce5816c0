#include "gltf/scene_file.h"

#include <cstring>
#include <limits>
#include <new>

#include "gltf/glb_header.h"
#include "util/byte_size.h"
#include "util/error.h"
#include "util/regular_file.h"

namespace vkpt::internal {
namespace {

// Peak memory per byte of glTF JSON: the schema check's and tinygltf's parse trees are
// ~22× the text (docs/design-notes.md, "Memory of a glTF load"). Binary data (a GLB's
// BIN chunk) is held twice: the file's bytes and tinygltf's copy of the buffer.
constexpr uint64_t kJsonMemoryFactor = 24;
constexpr uint64_t kBinaryMemoryFactor = 2;

uint32_t LittleEndian32(const unsigned char* p) { return p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24; }

// The first non-blank byte of a JSON text must open the top-level object; a UTF-8 BOM
// is let through here so that the loader can name it.
bool CouldBeJson(const unsigned char* head, size_t n) {
  size_t i = n >= 3 && std::memcmp(head, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
  while (i < n && (head[i] == ' ' || head[i] == '\t' || head[i] == '\n' || head[i] == '\r')) ++i;
  return i == n || head[i] == '{';
}

}  // namespace

SceneFile ReadSceneFile(const std::string& path, MemoryBudget& budget) {
  auto fail = [&](const std::string& what) { return Error(path + ": " + what); };
  std::string problem;
  std::optional<RegularFile> file = RegularFile::Open(path, &problem);
  if (!file) throw fail(problem);
  const uint64_t size = file->Size();
  if (size == 0) throw fail("file is empty");

  unsigned char head[20] = {};
  const size_t headSize = size_t(std::min<uint64_t>(size, sizeof head));
  if (!file->ReadAt(0, head, headSize, &problem)) throw fail(problem);
  SceneFile scene;
  scene.binary = headSize >= 4 && std::memcmp(head, "glTF", 4) == 0;
  uint64_t jsonBytes = size;
  if (scene.binary) {
    // A GLB says how long it is: a file of another length is refused unread.
    if (headSize < 12) throw fail("invalid GLB: file is shorter than the 12-byte header");
    if (uint32_t declared = LittleEndian32(head + 8); declared != size)
      throw fail("invalid GLB: header says " + std::to_string(declared) + " bytes but the file has " +
                 std::to_string(size));
    jsonBytes = headSize >= 20 ? std::min<uint64_t>(LittleEndian32(head + 12), size) : 0;
  } else {
    if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0)
      throw fail("not a binary glTF file (the GLB magic \"glTF\" is missing)");
    if (!CouldBeJson(head, headSize))
      throw fail("not a glTF file: neither JSON (which starts with '{') nor binary glTF (magic \"glTF\")");
    if (size > std::numeric_limits<uint32_t>::max())
      throw fail("is " + FormatBytes(size) + "; glTF files are under 4 GiB");
  }
  budget.Charge(jsonBytes * kJsonMemoryFactor + (size - jsonBytes) * kBinaryMemoryFactor,
                "loading the file (" + FormatBytes(size) + ")");
  try {
    scene.bytes.resize(size_t(size));
  } catch (const std::bad_alloc&) {
    throw fail("not enough memory to read the file (" + FormatBytes(size) + ")");
  }
  if (!file->ReadAt(0, scene.bytes.data(), scene.bytes.size(), &problem)) throw fail(problem);
  scene.json = scene.binary ? CheckGlbHeader(path, scene.bytes) : std::string_view(scene.bytes);
  return scene;
}

void ReplaceJson(SceneFile& file, const std::string& json) {
  if (!file.binary) {
    file.bytes = json;
    file.json = file.bytes;
    return;
  }
  // 12-byte header, then the JSON chunk's 8-byte header and text, then the other chunks.
  const size_t rest = 20 + file.json.size();
  std::string padded = json;
  padded.resize((padded.size() + 3) / 4 * 4, ' ');
  std::string glb = file.bytes.substr(0, 12);
  const auto put32 = [&](size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) glb[at + i] = char(v >> (8 * i));
  };
  glb += std::string(8, '\0');
  put32(12, uint32_t(padded.size()));
  glb.replace(16, 4, file.bytes, 16, 4);  // the chunk type, "JSON"
  glb += padded;
  glb.append(file.bytes, rest);
  put32(8, uint32_t(glb.size()));
  file.bytes = std::move(glb);
  file.json = std::string_view(file.bytes).substr(20, padded.size());
}

}  // namespace vkpt::internal
