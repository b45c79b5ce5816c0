// MikkTSpace tangents (scene/tangent_space.h): exact frames on flat quads, mirrored uvs
// kept apart, welding, the contract on random and degenerate meshes, and agreement with the
// TANGENT attributes of real files (the external test data, read in place).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gltf/gltf_loader.h"
#include "scene/tangent_space.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

constexpr glm::vec3 kUp(0.0f, 0.0f, 1.0f);

// The unit square in z = 0 facing +z, two triangles, with the given uv per corner
// (corners (0,0), (1,0), (1,1), (0,1)).
struct Mesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> indices;
  std::vector<glm::vec4> Tangents() const { return GenerateTangents(positions, normals, uvs, indices); }
};

Mesh Quad(glm::vec2 (*uv)(glm::vec2)) {
  Mesh m;
  for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
    m.positions.emplace_back(c, 0.0f);
    m.normals.push_back(kUp);
    m.uvs.push_back(uv(c));
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// The contract every output vertex meets: finite, unit, orthogonal to its (non-zero)
// normal, w = ±1.
void ExpectValidFrame(const glm::vec4& t, const glm::vec3& normal, size_t v) {
  ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w)) << "vertex " << v;
  EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f) << "vertex " << v;
  EXPECT_TRUE(t.w == 1.0f || t.w == -1.0f) << "vertex " << v << " w " << t.w;
  const float len = glm::length(normal);
  if (std::isfinite(len) && len > 1e-20f) {
    EXPECT_LT(std::abs(glm::dot(glm::vec3(t), normal / len)), 1e-5f) << "vertex " << v;
  }
}

// glTF's uvs grow down the image: u = x, v = 1 − y shows the texture upright on the quad,
// so the tangent is +x and the bitangent w · cross(n, t) = +y, up the image: w = +1.
TEST(TangentSpace, FlatQuadUprightTexture) {
  const Mesh m = Quad([](glm::vec2 c) { return glm::vec2(c.x, 1.0f - c.y); });
  const std::vector<glm::vec4> t = m.Tangents();
  ASSERT_EQ(t.size(), 4u);
  for (const glm::vec4& tv : t) EXPECT_EQ(tv, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
}

// u → 1 − u mirrors the texture: ∂P/∂u is −x and the uv area changes sign, so w flips,
// and the bitangent −1 · cross(+z, −x) = +y still points up the image.
TEST(TangentSpace, FlatQuadMirroredTexture) {
  const Mesh m = Quad([](glm::vec2 c) { return glm::vec2(1.0f - c.x, 1.0f - c.y); });
  for (const glm::vec4& tv : m.Tangents()) EXPECT_EQ(tv, glm::vec4(-1.0f, 0.0f, 0.0f, -1.0f));
}

// v = y (the image upside down): the tangent stays +x, the bitangent −y, so w = −1.
TEST(TangentSpace, FlatQuadUpsideDownTexture) {
  const Mesh m = Quad([](glm::vec2 c) { return c; });
  for (const glm::vec4& tv : m.Tangents()) EXPECT_EQ(tv, glm::vec4(1.0f, 0.0f, 0.0f, -1.0f));
}

// Two quads mirrored about x = 0 (u = |x|), as a symmetric model's halves are. The seam
// vertices are duplicated with identical position, normal and uv, so welding joins them,
// but the orientation keeps each half's frame: averaging the halves would cancel ∂P/∂u.
Mesh MirroredHalves(bool shareSeam) {
  Mesh m;
  auto add = [&](float x, float y) {
    m.positions.emplace_back(x, y, 0.0f);
    m.normals.push_back(kUp);
    m.uvs.emplace_back(std::abs(x), 1.0f - y);
    return uint32_t(m.positions.size() - 1);
  };
  const uint32_t l0 = add(-1, 0), l1 = add(-1, 1), s0 = add(0, 0), s1 = add(0, 1);
  const uint32_t r0 = shareSeam ? s0 : add(0, 0), r1 = shareSeam ? s1 : add(0, 1);
  const uint32_t e0 = add(1, 0), e1 = add(1, 1);
  m.indices = {l0, s0, s1, l0, s1, l1, r0, e0, e1, r0, e1, r1};
  return m;
}

TEST(TangentSpace, MirroredHalvesKeepTheirOwnFrames) {
  const Mesh m = MirroredHalves(false);
  const std::vector<glm::vec4> t = m.Tangents();
  for (size_t v = 0; v < t.size(); ++v) {
    const bool right = m.positions[v].x > 0.0f || (m.positions[v].x == 0.0f && v >= 4);
    EXPECT_EQ(t[v], right ? glm::vec4(1, 0, 0, 1) : glm::vec4(-1, 0, 0, -1)) << "vertex " << v;
  }
}

// One vertex shared by both halves must take one half's frame whole, not a blend.
TEST(TangentSpace, SharedSeamVertexTakesOneSide) {
  const Mesh m = MirroredHalves(true);
  const std::vector<glm::vec4> t = m.Tangents();
  for (uint32_t v : {2u, 3u}) EXPECT_EQ(t[v], glm::vec4(t[v].w, 0, 0, t[v].w)) << "vertex " << v;
}

// Per corner, as the loader generates them, each half keeps its own frame at the shared
// seam vertices too: the corners of the right half's triangles (x ≥ 0) all get +x.
TEST(TangentSpace, SharedSeamCornersKeepTheirHalfsFrame) {
  const Mesh m = MirroredHalves(true);
  const std::vector<glm::vec4> t = GenerateCornerTangents(m.positions, m.normals, m.uvs, m.indices);
  ASSERT_EQ(t.size(), m.indices.size());
  for (size_t k = 0; k < m.indices.size(); k += 3) {
    bool right = true;
    for (size_t c = 0; c < 3; ++c) right &= m.positions[m.indices[k + c]].x >= 0.0f;
    for (size_t c = 0; c < 3; ++c)
      EXPECT_EQ(t[k + c], right ? glm::vec4(1, 0, 0, 1) : glm::vec4(-1, 0, 0, -1)) << "triangle " << k / 3;
  }
}

// A patch of the unit sphere, u along the longitude, v down the latitude, `rows` × `cols`
// quads, indexed (shared vertices).
Mesh SpherePatch(int rows, int cols) {
  Mesh m;
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j <= cols; ++j) {
      const float u = float(j) / float(cols), v = float(i) / float(rows);
      const float phi = 1.2f * u, theta = 0.4f + 1.8f * v;
      const glm::vec3 p(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      m.positions.push_back(p);
      m.normals.push_back(p);
      m.uvs.emplace_back(u, v);
    }
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const uint32_t a = uint32_t(i * (cols + 1) + j), b = a + 1, c = a + uint32_t(cols) + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  return m;
}

// On a smooth surface the averaged frame follows ∂P/∂u, the longitude direction, and the
// bitangent −∂P/∂v points up the image (towards smaller v, the north pole).
TEST(TangentSpace, SpherePatchFollowsLongitude) {
  const Mesh m = SpherePatch(12, 16);
  const std::vector<glm::vec4> t = m.Tangents();
  for (size_t v = 0; v < t.size(); ++v) {
    const glm::vec3 p = m.positions[v];
    const glm::vec3 east = glm::normalize(glm::vec3(-p.y, p.x, 0.0f));
    EXPECT_GT(glm::dot(glm::vec3(t[v]), east), std::cos(glm::radians(2.0f))) << "vertex " << v;
    EXPECT_EQ(t[v].w, 1.0f) << "vertex " << v;
  }
}

// The same mesh without an index (every corner its own vertex) welds back to the same
// tangents: MikkTSpace averages over identical vertices, however the file shares them.
TEST(TangentSpace, UnindexedMeshWeldsToIndexedResult) {
  const Mesh m = SpherePatch(6, 8);
  Mesh flat;
  for (uint32_t i : m.indices) {
    flat.positions.push_back(m.positions[i]);
    flat.normals.push_back(m.normals[i]);
    flat.uvs.push_back(m.uvs[i]);
    flat.indices.push_back(uint32_t(flat.indices.size()));
  }
  const std::vector<glm::vec4> indexed = m.Tangents(), unindexed = flat.Tangents();
  for (size_t k = 0; k < m.indices.size(); ++k) {
    const glm::vec4 a = indexed[m.indices[k]], b = unindexed[k];
    EXPECT_GT(glm::dot(glm::vec3(a), glm::vec3(b)), 1.0f - 1e-6f) << "corner " << k;
    EXPECT_EQ(a.w, b.w) << "corner " << k;
  }
}

TEST(TangentSpace, RandomMeshesMeetTheContract) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> coord(-1.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    Mesh m;
    const size_t n = 50 + size_t(trial) * 10;
    for (size_t v = 0; v < n; ++v) {
      m.positions.emplace_back(coord(rng), coord(rng), coord(rng));
      // Random unit normals, unrelated to the faces: the output must still be orthogonal.
      m.normals.push_back(glm::normalize(glm::vec3(coord(rng), coord(rng), coord(rng)) + glm::vec3(0, 0, 1e-3f)));
      m.uvs.emplace_back(coord(rng) * 4.0f, coord(rng) * 4.0f);
    }
    std::uniform_int_distribution<uint32_t> index(0, uint32_t(n - 1));
    for (size_t k = 0; k < 3 * n; ++k) m.indices.push_back(index(rng));
    const std::vector<glm::vec4> t = m.Tangents();
    ASSERT_EQ(t.size(), n);
    for (size_t v = 0; v < n; ++v) ExpectValidFrame(t[v], m.normals[v], v);
  }
}

// Zero-area triangles, coincident uvs, zero, tiny, huge and non-finite normals, huge
// coordinates, indices out of range and arrays of different lengths: all finite frames.
TEST(TangentSpace, DegenerateInputGivesFiniteFrames) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  Mesh m;
  m.positions = {{0, 0, 0},     {0, 0, 0},     {1, 0, 0}, {2, 0, 0},      {0, 1, 0},
                 {1e30f, 0, 0}, {0, 1e30f, 0}, {1, 1, 1}, {1e-30f, 0, 0}, {0, 1e-30f, 0}};
  m.normals = {{0, 0, 1},   {0, 0, 0}, {0, 0, 1e-30f}, {0, 0, 1e30f}, {nan, 0, 1},
               {0, 0, inf}, {0, 0, 1}, {0, 0, 1},      {0, 0, 1},     {0, 0, 1}};
  m.uvs = {{0, 0}, {0, 0}, {0, 0}, {1, 0}, {0, 0}, {1, 0}, {0, 1}, {3e38f, -3e38f}, {0, 0}, {1e-30f, 1e-30f}};
  m.indices = {0, 1, 2,       // two corners coincide
               0, 2, 3,       // collinear: zero area
               0, 2, 4,       // coincident uvs
               0, 5, 6,       // huge coordinates
               2, 4, 7,       // huge uvs
               0, 8, 9,       // tiny triangle, tiny uvs
               1, 3, 4,       // zero normal
               0, 4, 99, 7};  // an index out of range, and a trailing partial triangle
  const std::vector<glm::vec4> t = m.Tangents();
  ASSERT_EQ(t.size(), m.positions.size());
  for (size_t v = 0; v < t.size(); ++v) ExpectValidFrame(t[v], m.normals[v], v);
  // Fewer normals and uvs than positions: the extra vertices get a default frame.
  const std::vector<glm::vec4> shorter =
      GenerateTangents(m.positions, std::span(m.normals).first(4), std::span(m.uvs).first(3), m.indices);
  ASSERT_EQ(shorter.size(), m.positions.size());
  for (size_t v = 0; v < shorter.size(); ++v) ExpectValidFrame(shorter[v], glm::vec3(0.0f), v);
  EXPECT_TRUE(GenerateTangents({}, {}, {}, {}).empty());
}

// A vertex no usable triangle defines gets some tangent orthogonal to its normal, w = 1.
TEST(TangentSpace, UndefinedVertexGetsDefaultFrame) {
  Mesh m = Quad([](glm::vec2) { return glm::vec2(0.5f); });  // every uv the same
  m.normals[2] = glm::normalize(glm::vec3(1, 1, 1));
  const std::vector<glm::vec4> t = m.Tangents();
  for (size_t v = 0; v < t.size(); ++v) {
    ExpectValidFrame(t[v], m.normals[v], v);
    EXPECT_EQ(t[v].w, 1.0f);
  }
}

// How generated tangents compare with a file's TANGENT over its triangles' corners.
struct Agreement {
  std::vector<double> degrees;  // angle between generated and supplied xyz, per triangle corner
  size_t signsAgree = 0;
  double Quantile(double q) const {
    std::vector<double> d = degrees;
    std::sort(d.begin(), d.end());
    return d.empty() ? 0.0 : d[std::min(d.size() - 1, size_t(q * double(d.size())))];
  }
  double SignFraction() const { return degrees.empty() ? 0.0 : double(signsAgree) / double(degrees.size()); }
};

// The scene's normal-mapped triangles as loaded (world space, TANGENT as the file has it)
// become a triangle soup, three corners each, which GenerateCornerTangents welds back into
// the file's vertices; generated and supplied tangents are compared corner by corner.
Agreement CompareWithFile(const std::string& path) {
  const Scene scene = LoadGltf(path);
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec4> supplied;
  for (size_t i = 0; i < scene.triangles.size(); ++i) {
    const SceneTriangle& t = scene.triangles[i];
    const MaterialTexture& ref = scene.materials[t.material].texture(TextureSlot::kNormal);
    if (!ref.Present() || scene.normals.empty() || !scene.normals[i].Present()) continue;
    const VertexNormals& n = scene.normals[i];
    positions.insert(positions.end(), {t.v0, t.v1, t.v2});
    normals.insert(normals.end(), {n.n0, n.n1, n.n2});
    const glm::vec2* set = ref.texCoord == 0 ? scene.uvs[i].set0 : scene.uvs[i].set1;
    uvs.insert(uvs.end(), set, set + 3);
    supplied.insert(supplied.end(), scene.tangents[i].t, scene.tangents[i].t + 3);
  }
  std::vector<uint32_t> indices(positions.size());
  for (uint32_t k = 0; k < indices.size(); ++k) indices[k] = k;
  const std::vector<glm::vec4> t = GenerateCornerTangents(positions, normals, uvs, indices);
  Agreement a;
  for (size_t k = 0; k < t.size(); ++k) {
    const glm::vec3 s(supplied[k]);
    if (!(glm::length(s) > 0.0f)) continue;
    const double c = std::clamp(double(glm::dot(glm::vec3(t[k]), glm::normalize(s))), -1.0, 1.0);
    a.degrees.push_back(glm::degrees(std::acos(c)));
    a.signsAgree += (t[k].w > 0.0f) == (supplied[k].w > 0.0f);
  }
  return a;
}

struct SuppliedFile {
  const char* path;   // in the test data (test_util.h)
  double p95Degrees;  // the bound on the 95th percentile of the angle
};

// Files with a normal texture whose TANGENT came from an exporter's MikkTSpace (Blender,
// RapidCompact, Unity). Measured per triangle corner (median / p95 / p99 / max angle,
// signs agreeing):
//   NormalTangentMirrorTest 0.000° / 0.020° / 0.020° / 0.028°, 100 %
//   AlphaBlendModeTest      0.000° / 0.000° / 0.000° / 0.000°, 100 %
//   LightsPunctualLamp      0.000° / 0.020° / 0.020° / 81.4°,  100 % (the file's outliers
//                           are its own: mikktspace.c differs from it there as much)
//   Avocado                 0.242° / 1.595° / 3.506° / 18.1°,  99.85 % (Unity's tangents
//                           differ from mikktspace.c's by as much)
// The bounds leave a margin over these; signs must agree on 99 % of vertices. Not here:
// NormalTangentTest supplies no TANGENT (it tests generated tangents); Cube and
// TwoSidedPlane (VKTS exporter) agree to 0.000° but with every w negated, the raw
// MikkTSpace sign without glTF's v flip; MultiUVTest and VertexColorTest have no normal
// texture, so their tangents are unused and follow no convention.
TEST(TangentSpace, AgreesWithSuppliedTangents) {
  const SuppliedFile files[] = {
      {"gltf-pbr/NormalTangentMirrorTest/glTF-Binary/NormalTangentMirrorTest.glb", 0.5},
      {"gltf-pbr/AlphaBlendModeTest/glTF-Binary/AlphaBlendModeTest.glb", 0.5},
      {"gltf-pbr/LightsPunctualLamp/glTF/LightsPunctualLamp.gltf", 0.5},
      {"gltf-corpus/valid/Avocado/glTF/Avocado.gltf", 3.0},
  };
  VKPT_REQUIRE_SHARED_DATA();
  for (const SuppliedFile& f : files) {
    const std::string path = test::SharedData(f.path);
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing";
    const Agreement a = CompareWithFile(path);
    ASSERT_GT(a.degrees.size(), 0u) << path;
    std::printf("%s: %zu triangle corners, angle median %.3f° p95 %.3f° p99 %.3f° max %.3f°, signs agree %.2f %%\n",
                std::filesystem::path(path).filename().c_str(), a.degrees.size(), a.Quantile(0.5), a.Quantile(0.95),
                a.Quantile(0.99), a.Quantile(1.0), 100.0 * a.SignFraction());
    EXPECT_LT(a.Quantile(0.95), f.p95Degrees) << path;
    EXPECT_GE(a.SignFraction(), 0.99) << path;
  }
}

}  // namespace
}  // namespace vkpt::internal
