#include "gltf_builder.h"

#include "gltf/gltf_loader.h"
#include "util/error.h"

namespace vkpt::internal::test {
std::string Base64(const std::string& bytes) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  auto byte = [&](size_t k) { return uint32_t(static_cast<unsigned char>(bytes[k])); };
  for (; i + 3 <= bytes.size(); i += 3) {
    uint32_t v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
  }
  size_t rest = bytes.size() - i;
  if (rest == 1) {
    uint32_t v = byte(i) << 16;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += "==";
  } else if (rest == 2) {
    uint32_t v = byte(i) << 16 | byte(i + 1) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string Num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string Join(const std::vector<std::string>& items) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i) s += (i ? "," : "") + items[i];
  return s;
}

std::string GltfBuilder::Json(bool glb) const {
  std::string j = "{\"asset\":{\"version\":\"" + version + "\"}";
  if (!extensionsUsed.empty()) j += ",\"extensionsUsed\":[" + Quoted(extensionsUsed) + "]";
  if (!extensionsRequired.empty()) j += ",\"extensionsRequired\":[" + Quoted(extensionsRequired) + "]";
  if (!bin_.empty()) {
    j += ",\"buffers\":[{\"byteLength\":" + std::to_string(glb ? Padded().size() : bin_.size());
    if (!glb) j += ",\"uri\":\"data:application/octet-stream;base64," + Base64(bin_) + "\"";
    j += "}";
    for (const std::string& b : extraBuffers) j += "," + b;
    j += "]";
  }
  auto array = [&](const char* name, const std::vector<std::string>& items) {
    if (!items.empty()) j += std::string(",\"") + name + "\":[" + Join(items) + "]";
  };
  array("bufferViews", views_);
  array("accessors", accessors_);
  array("materials", materials);
  array("meshes", meshes);
  array("cameras", cameras);
  array("textures", textures);
  array("images", images);
  array("nodes", nodes);
  array("skins", skins);
  array("animations", animations);
  std::vector<std::string> sc = scenes;
  if (sc.empty() && !nodes.empty() && defaultScenes) sc.push_back("{\"nodes\":[0]}");
  array("scenes", sc);
  if (scene) j += ",\"scene\":" + std::to_string(*scene);
  return j + extraTopLevel + "}";
}

std::string GltfBuilder::Glb() const {
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string json = Json(/*glb=*/true);
  while (json.size() % 4) json += ' ';
  const std::string bin = Padded();
  std::string body = u32(uint32_t(json.size())) + "JSON" + json;
  if (!bin.empty()) body += u32(uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
  return "glTF" + u32(2) + u32(uint32_t(12 + body.size())) + body;
}

Scene Load(const GltfBuilder& b, const SceneChoice& choice) {
  TempFile f(b.Json());
  return LoadGltf(f.path, {}, choice);
}

::testing::AssertionResult LoadFailsWith(const std::string& path, std::initializer_list<std::string> needles,
                                         const SceneChoice& choice) {
  std::string what;
  try {
    Scene s = LoadGltf(path, {}, choice);
    return ::testing::AssertionFailure() << path << " loaded (" << s.triangles.size()
                                         << " triangles) but should have failed";
  } catch (const Error& e) {
    what = e.what();
  }
  if (what.rfind(path + ": ", 0) != 0)
    return ::testing::AssertionFailure() << "message does not start with \"" << path << ": \": " << what;
  for (const std::string& n : needles)
    if (what.find(n) == std::string::npos)
      return ::testing::AssertionFailure() << "message lacks \"" << n << "\": " << what;
  ::testing::Test::RecordProperty("message", what);
  return ::testing::AssertionSuccess() << what;
}

::testing::AssertionResult FailsWith(const GltfBuilder& b, std::initializer_list<std::string> needles,
                                     const SceneChoice& choice) {
  TempFile f(b.Json());
  return LoadFailsWith(f.path, needles, choice);
}

::testing::AssertionResult Near(const glm::vec3& a, const glm::vec3& b, float eps) {
  if (glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(eps)))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") != (" << b.x << ", " << b.y
                                       << ", " << b.z << ")";
}

const std::vector<glm::vec3> kUnitTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

GltfBuilder TriangleModel() {
  GltfBuilder b;
  b.Mesh(b.Positions(kUnitTriangle));
  return b;
}

std::string SlidingTriangle() {
  GltfBuilder b = TriangleModel();
  b.materials = {R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.3,0.2,1]}})"};
  b.meshes[0].insert(b.meshes[0].rfind("}]"), R"(,"material":0)");
  b.Node(R"({"mesh":0})");
  const int in = b.Accessor(b.View(Bytes(std::vector<float>{0, 1})), kFloat, 2, "SCALAR", ",\"min\":[0],\"max\":[1]");
  const int out = b.Accessor(b.View(Bytes(std::vector<float>{0, 0, 0, 1, 0, 0})), kFloat, 2, "VEC3");
  b.animations = {R"({"name":"slide","samplers":[{"input":)" + std::to_string(in) + ",\"output\":" +
                  std::to_string(out) + R"(}],"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}]})"};
  return b.Json();
}

}  // namespace vkpt::internal::test
