// Small glTF files for loader tests, written by the test itself: a builder for the JSON
// (one binary buffer, embedded as a base64 data: URI or left for a GLB BIN chunk), a
// temporary file to hold it, and checks of what loading it gives.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gltf/gltf_loader.h"
#include "scene/scene.h"
#include "test_util.h"

namespace vkpt::internal::test {

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;

std::string Num(double v);  // every digit a double needs ("%.17g")

template <class T>
std::string Bytes(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

std::string Join(const std::vector<std::string>& items);  // comma-separated
std::string Base64(const std::string& bytes);             // as a data: URI holds them

// Builds a glTF document: one binary buffer (embedded as a base64 data: URI, or left
// without a uri for a GLB BIN chunk) plus JSON objects the test writes as text.
class GltfBuilder {
 public:
  // Appends bytes (4-byte aligned) as a new bufferView; returns its index.
  int View(const std::string& bytes, int byteStride = 0) {
    while (bin_.size() % 4) bin_ += '\0';
    std::string v = "{\"buffer\":0,\"byteOffset\":" + std::to_string(bin_.size()) +
                    ",\"byteLength\":" + std::to_string(bytes.size());
    if (byteStride) v += ",\"byteStride\":" + std::to_string(byteStride);
    views_.push_back(v + "}");
    bin_ += bytes;
    return int(views_.size()) - 1;
  }
  size_t BinSize() const { return bin_.size(); }
  // A bufferView written by the test (`json`, an object); returns its index.
  int RawView(const std::string& json) {
    views_.push_back(json);
    return int(views_.size()) - 1;
  }
  int Accessor(int view, int componentType, size_t count, const std::string& type, const std::string& extra = "") {
    std::string a = "{";
    if (view >= 0) a += "\"bufferView\":" + std::to_string(view) + ",";
    a += "\"componentType\":" + std::to_string(componentType) + ",\"count\":" + std::to_string(count) + ",\"type\":\"" +
         type + "\"" + extra + "}";
    accessors_.push_back(a);
    return int(accessors_.size()) - 1;
  }
  // FLOAT VEC3 positions, with min/max when they are finite.
  int Positions(const std::vector<glm::vec3>& p) {
    std::string extra;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    bool finite = true;
    for (const glm::vec3& v : p) {
      finite &= std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    if (finite && !p.empty())
      extra = ",\"min\":[" + Num(lo.x) + "," + Num(lo.y) + "," + Num(lo.z) + "],\"max\":[" + Num(hi.x) + "," +
              Num(hi.y) + "," + Num(hi.z) + "]";
    return Accessor(View(Bytes(p)), kFloat, p.size(), "VEC3", extra);
  }
  int Indices(const std::vector<uint32_t>& idx, int componentType = kUInt) {
    std::string bytes;
    for (uint32_t i : idx) {
      if (componentType == kUByte) bytes += Bytes(std::vector<uint8_t>{uint8_t(i)});
      else if (componentType == kUShort) bytes += Bytes(std::vector<uint16_t>{uint16_t(i)});
      else bytes += Bytes(std::vector<uint32_t>{i});
    }
    return Accessor(View(bytes), componentType, idx.size(), "SCALAR");
  }
  // A mesh with one primitive; returns the mesh index.
  int Mesh(int positions, int indices = -1, int material = -1, int mode = -1) {
    std::string p = "{\"attributes\":{\"POSITION\":" + std::to_string(positions) + "}";
    if (indices >= 0) p += ",\"indices\":" + std::to_string(indices);
    if (material >= 0) p += ",\"material\":" + std::to_string(material);
    if (mode >= 0) p += ",\"mode\":" + std::to_string(mode);
    meshes.push_back("{\"primitives\":[" + p + "}]}");
    return int(meshes.size()) - 1;
  }
  int Node(const std::string& json) {
    nodes.push_back(json);
    return int(nodes.size()) - 1;
  }

  // The document; with `glb`, the buffer has no uri (it is the GLB BIN chunk).
  std::string Json(bool glb = false) const;
  // A GLB file: header + JSON chunk (space-padded) + BIN chunk (zero-padded).
  std::string Glb() const;
  std::string Padded() const {
    std::string b = bin_;
    while (b.size() % 4) b += '\0';
    return b;
  }

  std::vector<std::string> meshes, nodes, materials, cameras, scenes, textures, images, skins, animations;
  std::vector<std::string> extensionsUsed, extensionsRequired;
  std::string version = "2.0";
  std::optional<int> scene;
  bool defaultScenes = true;              // scenes [{"nodes":[0]}] when none are given
  std::string extraTopLevel;              // raw JSON members, each starting with ','
  std::vector<std::string> extraBuffers;  // raw buffer objects after buffer 0

 private:
  static std::string Quoted(const std::vector<std::string>& v) {
    std::vector<std::string> q;
    for (const std::string& s : v) q.push_back("\"" + s + "\"");
    return Join(q);
  }
  std::string bin_;
  std::vector<std::string> views_, accessors_;
};

// A file in /tmp named after the running test, removed when it goes out of scope.
class TempFile {
 public:
  TempFile(const std::string& contents, const std::string& ext = ".gltf") {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string test = info->name();
    std::replace(test.begin(), test.end(), '/', '-');  // parameterized tests' names: "Name/0"
    path = TempPath("loader-" + test + "-" + std::to_string(counter_++) + ext);
    std::ofstream(path, std::ios::binary) << contents;
  }
  ~TempFile() { std::remove(path.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  std::string path;

 private:
  static inline int counter_ = 0;
};

Scene Load(const GltfBuilder& b, const SceneChoice& choice = {});

// LoadGltf(path) must throw Error whose message starts with the path and contains
// every needle.
::testing::AssertionResult LoadFailsWith(const std::string& path, std::initializer_list<std::string> needles,
                                         const SceneChoice& choice = {});
::testing::AssertionResult FailsWith(const GltfBuilder& b, std::initializer_list<std::string> needles,
                                     const SceneChoice& choice = {});

::testing::AssertionResult Near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f);

// The triangle (0,0,0), (1,0,0), (0,1,0): front face +Z.
extern const std::vector<glm::vec3> kUnitTriangle;

// One triangle mesh (mesh 0) under the nodes the test adds.
GltfBuilder TriangleModel();

// The unit triangle before a white background that animation "slide" moves LINEAR from
// x = 0 at 0 s to x = 1 at 1 s: the file's JSON.
std::string SlidingTriangle();

}  // namespace vkpt::internal::test
