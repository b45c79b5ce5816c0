// Compressed geometry: KHR_draco_mesh_compression (gltf/gltf_draco.h) and
// EXT_meshopt_compression with its filters (gltf/gltf_meshopt.h). The same bumpy grid is
// written plain, Draco-encoded (sequential and lossless; edgebreaker and quantized) and
// meshopt-encoded (every mode and filter) by the libraries' own encoders, and each
// compressed file loads to the plain file's triangles: exactly where the codec is
// lossless, within the quantization step where it is not. A stream cut anywhere, data
// that disagrees with its accessors, and sizes past --max-memory are errors naming the
// primitive or bufferView. Duck (Draco), BoxMeshopt and the quantized AnimatedMorphCube of
// ../shared/gltf-ext load to their plain versions in ../shared/gltf-corpus.
#include <gtest/gtest.h>

#include <draco/compression/encode.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "gltf/draco_decode.h"
#include "gltf/gltf_loader.h"
#include "gltf/meshopt_decode.h"
#include "gltf_builder.h"
#include "png_writer.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

using namespace test;

// A 9 × 9 grid of vertices over [0, 8]², raised by a bump, with its normals and [0, 1]²
// texture coordinates: 128 triangles.
struct Grid {
  std::vector<float> positions, normals, uvs;  // 3, 3, 2 floats a vertex
  std::vector<uint16_t> indices;
  size_t Vertices() const { return positions.size() / 3; }
};

Grid MakeGrid() {
  Grid g;
  for (int y = 0; y <= 8; ++y)
    for (int x = 0; x <= 8; ++x) {
      const float h = 0.3f * std::sin(0.7f * x) * std::cos(0.5f * y);
      const float dx = 0.21f * std::cos(0.7f * x) * std::cos(0.5f * y),
                  dy = -0.15f * std::sin(0.7f * x) * std::sin(0.5f * y);
      const float len = std::sqrt(dx * dx + dy * dy + 1.0f);
      g.positions.insert(g.positions.end(), {float(x), float(y), h});
      g.normals.insert(g.normals.end(), {-dx / len, -dy / len, 1.0f / len});
      g.uvs.insert(g.uvs.end(), {x / 8.0f, y / 8.0f});
    }
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const uint16_t a = uint16_t(y * 9 + x), b = uint16_t(a + 1), c = uint16_t(a + 9), d = uint16_t(a + 10);
      g.indices.insert(g.indices.end(), {a, b, d, a, d, c});
    }
  return g;
}

// A textured material, so that the loader keeps texture coordinates.
void AddTexturedMaterial(GltfBuilder& b) {
  const std::vector<uint8_t> rgba(4 * 4 * 4, 200);
  const std::vector<uint8_t> png = MakePng(4, 4, 8, 6, rgba);
  b.images.push_back("{\"bufferView\":" + std::to_string(b.View(Bytes(png))) + ",\"mimeType\":\"image/png\"}");
  b.textures.push_back("{\"source\":0}");
  b.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})");
}

std::string Primitive(int pos, int nrm, int uv, int indices, const std::string& extensions = "") {
  return "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
         ",\"NORMAL\":" + std::to_string(nrm) + ",\"TEXCOORD_0\":" + std::to_string(uv) +
         "},\"indices\":" + std::to_string(indices) + ",\"material\":0" + extensions + "}]}";
}

GltfBuilder PlainGrid(const Grid& g) {
  GltfBuilder b;
  AddTexturedMaterial(b);
  const size_t n = g.Vertices();
  const int pos = b.Accessor(b.View(Bytes(g.positions)), kFloat, n, "VEC3", ",\"min\":[0,0,-1],\"max\":[8,8,1]");
  const int nrm = b.Accessor(b.View(Bytes(g.normals)), kFloat, n, "VEC3");
  const int uv = b.Accessor(b.View(Bytes(g.uvs)), kFloat, n, "VEC2");
  const int idx = b.Accessor(b.View(Bytes(g.indices)), kUShort, g.indices.size(), "SCALAR");
  b.meshes.push_back(Primitive(pos, nrm, uv, idx));
  b.Node("{\"mesh\":0}");
  return b;
}

// Draco's encoder on the grid: `bits` 0 keeps the floats as they are (lossless).
std::string EncodeDraco(const Grid& g, bool edgebreaker, int bits) {
  draco::Mesh mesh;
  const size_t n = g.Vertices();
  mesh.set_num_points(uint32_t(n));
  auto add = [&](draco::GeometryAttribute::Type type, int components, const std::vector<float>& data) {
    draco::GeometryAttribute ga;
    ga.Init(type, nullptr, int8_t(components), draco::DT_FLOAT32, false, int64_t(sizeof(float) * components), 0);
    const int id = mesh.AddAttribute(ga, true, uint32_t(n));
    for (size_t i = 0; i < n; ++i)
      mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), &data[i * components]);
  };
  add(draco::GeometryAttribute::POSITION, 3, g.positions);  // unique id 0
  add(draco::GeometryAttribute::NORMAL, 3, g.normals);      // 1
  add(draco::GeometryAttribute::TEX_COORD, 2, g.uvs);       // 2
  for (size_t f = 0; f < g.indices.size(); f += 3)
    mesh.AddFace(
        {draco::PointIndex(g.indices[f]), draco::PointIndex(g.indices[f + 1]), draco::PointIndex(g.indices[f + 2])});
  draco::Encoder encoder;
  encoder.SetEncodingMethod(edgebreaker ? draco::MESH_EDGEBREAKER_ENCODING : draco::MESH_SEQUENTIAL_ENCODING);
  if (bits) {
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  }
  draco::EncoderBuffer out;
  const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &out);
  EXPECT_TRUE(status.ok()) << status.error_msg_string();
  return std::string(out.data(), out.size());
}

// The grid as a Draco primitive: accessors without bufferViews, the bitstream in one.
// `extraPoint` makes the POSITION accessor claim a point the data does not have.
GltfBuilder DracoGrid(const Grid& g, const std::string& bitstream, size_t positionCount = 0, size_t indexCount = 0) {
  GltfBuilder b;
  AddTexturedMaterial(b);
  const size_t n = g.Vertices();
  const int pos =
      b.Accessor(-1, kFloat, positionCount ? positionCount : n, "VEC3", ",\"min\":[0,0,-1],\"max\":[8,8,1]");
  const int nrm = b.Accessor(-1, kFloat, n, "VEC3");
  const int uv = b.Accessor(-1, kFloat, n, "VEC2");
  const int idx = b.Accessor(-1, kUShort, indexCount ? indexCount : g.indices.size(), "SCALAR");
  const int view = b.View(bitstream);
  b.meshes.push_back(
      Primitive(pos, nrm, uv, idx,
                ",\"extensions\":{\"KHR_draco_mesh_compression\":{\"bufferView\":" + std::to_string(view) +
                    ",\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2}}}"));
  b.Node("{\"mesh\":0}");
  b.extensionsUsed = b.extensionsRequired = {"KHR_draco_mesh_compression"};
  return b;
}

// Worst differences between two loads of the same mesh, triangles matched whatever
// their order and the rotation of their vertices; +inf when one has no match.
struct MeshDifference {
  float position = 0, normal = 0, uv = 0;
};

MeshDifference Compare(const Scene& want, const Scene& got, float tolerance) {
  MeshDifference d;
  if (want.triangles.size() != got.triangles.size()) return {INFINITY, INFINITY, INFINITY};
  auto vertex = [](const SceneTriangle& t, int k) { return k == 0 ? t.v0 : k == 1 ? t.v1 : t.v2; };
  auto normal = [](const VertexNormals& n, int k) { return k == 0 ? n.n0 : k == 1 ? n.n1 : n.n2; };
  for (size_t i = 0; i < want.triangles.size(); ++i) {
    float best = INFINITY;
    size_t match = 0;
    int rotation = 0;
    for (size_t j = 0; j < got.triangles.size() && best > tolerance; ++j)
      for (int r = 0; r < 3; ++r) {
        float worst = 0;
        for (int k = 0; k < 3; ++k) {
          const glm::vec3 e = glm::abs(vertex(want.triangles[i], k) - vertex(got.triangles[j], (k + r) % 3));
          worst = std::max({worst, e.x, e.y, e.z});
        }
        if (worst < best) best = worst, match = j, rotation = r;
      }
    d.position = std::max(d.position, best);
    for (int k = 0; k < 3; ++k) {
      const int kg = (k + rotation) % 3;
      if (!want.normals.empty() && !got.normals.empty())
        d.normal = std::max(d.normal, glm::length(normal(want.normals[i], k) - normal(got.normals[match], kg)));
      if (!want.uvs.empty() && !got.uvs.empty())
        d.uv = std::max(d.uv, glm::length(want.uvs[i].set0[k] - got.uvs[match].set0[kg]));
    }
  }
  return d;
}

TEST(Draco, SequentialLosslessEqualsThePlainMesh) {
  const Grid g = MakeGrid();
  const Scene plain = Load(PlainGrid(g));
  const Scene draco = Load(DracoGrid(g, EncodeDraco(g, false, 0)));
  ASSERT_EQ(draco.triangles.size(), 128u);
  const MeshDifference d = Compare(plain, draco, 0.0f);
  EXPECT_EQ(d.position, 0.0f);
  EXPECT_EQ(d.normal, 0.0f);
  EXPECT_EQ(d.uv, 0.0f);
  EXPECT_TRUE(draco.ignoredFeatures.empty()) << draco.ignoredFeatures.front();
}

// 14-bit positions over the grid's 8 units: a step of 4.9e-4; 10-bit normals, 12-bit UVs.
TEST(Draco, EdgebreakerQuantizedIsWithinTheQuantizationStep) {
  const Grid g = MakeGrid();
  const Scene plain = Load(PlainGrid(g));
  const std::string bits = EncodeDraco(g, true, 14);
  const Scene draco = Load(DracoGrid(g, bits));
  const MeshDifference d = Compare(plain, draco, 2.5e-4f);
  std::printf("Draco edgebreaker, %zu bytes for %zu triangles: worst position %.3g, normal %.3g, uv %.3g\n",
              bits.size(), draco.triangles.size(), d.position, d.normal, d.uv);
  EXPECT_LE(d.position, 8.0f / 16383 / 2 * 1.01f);
  EXPECT_LE(d.normal, 0.01f);
  EXPECT_LE(d.uv, 1.0f / 4095 / 2 * 1.5f);
  // A mutant: the same data read as if lossless would be off by more than the step allows.
  EXPECT_GT(Compare(plain, draco, 0.0f).position, 0.0f);
}

TEST(Draco, MalformedOrDisagreeingDataIsNamed) {
  const Grid g = MakeGrid();
  const std::string bits = EncodeDraco(g, true, 14);
  EXPECT_TRUE(FailsWith(DracoGrid(g, std::string(64, 'x')),
                        {"meshes[0].primitives[0]: KHR_draco_mesh_compression: the data (64 bytes) is not Draco"}));
  EXPECT_TRUE(FailsWith(DracoGrid(g, bits, 82),
                        {"meshes[0].primitives[0]: KHR_draco_mesh_compression: the data holds 81 points, but the "
                         "POSITION accessor has 82"}));
  EXPECT_TRUE(
      FailsWith(DracoGrid(g, bits, 0, 387), {"the data declares 128 triangles, but the indices accessor has 387"}));
  GltfBuilder b = DracoGrid(g, bits);
  b.meshes[0].replace(b.meshes[0].rfind("\"NORMAL\":1"), 10, "\"NORMAL\":7");
  EXPECT_TRUE(FailsWith(b, {"attribute NORMAL: the data has no attribute with id 7"}));
}

// Every cut of a bitstream either fails with Error or, where the cut dropped
// nothing the decoder needs, decodes to what the whole stream does; never a crash.
TEST(Draco, EveryCutFailsCleanly) {
  const Grid g = MakeGrid();
  const std::vector<DracoAccessor> wanted = {{"POSITION", 0, 3, kFloat, g.Vertices()},
                                             {"NORMAL", 1, 3, kFloat, g.Vertices()},
                                             {"TEXCOORD_0", 2, 2, kFloat, g.Vertices()}};
  for (bool edgebreaker : {false, true}) {
    const std::string bits = EncodeDraco(g, edgebreaker, 14);
    const auto* data = reinterpret_cast<const unsigned char*>(bits.data());
    const DracoPrimitive whole = DecodeDraco({data, bits.size()}, wanted, g.indices.size());
    size_t refused = 0;
    for (size_t cut = 0; cut < bits.size(); ++cut) {
      try {
        const DracoPrimitive part = DecodeDraco({data, cut}, wanted, g.indices.size());
        EXPECT_EQ(part.indices, whole.indices) << "cut at " << cut;
        EXPECT_EQ(part.attributes, whole.attributes) << "cut at " << cut;
      } catch (const Error&) {
        ++refused;
      }
    }
    std::printf("Draco %s, %zu bytes: %zu of %zu cuts refused\n", edgebreaker ? "edgebreaker" : "sequential",
                bits.size(), refused, bits.size());
    EXPECT_GE(refused, bits.size() * 9 / 10);
  }
}

TEST(Draco, DecodedSizesCountAgainstTheMemoryBudgetFirst) {
  const Grid g = MakeGrid();
  GltfBuilder b = DracoGrid(g, EncodeDraco(g, true, 14), 1500000000);
  EXPECT_TRUE(FailsWith(b, {"meshes[0].primitives[0] (KHR_draco_mesh_compression, decoded)", "--max-memory"}));
}

// meshoptimizer's encoders on a stream, padded to 4 bytes.
std::string EncodeVertices(const void* data, size_t count, size_t stride) {
  std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
  out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
  return Bytes(out);
}

std::string EncodeIndices(const std::vector<uint16_t>& indices, bool sequence) {
  std::vector<uint32_t> wide(indices.begin(), indices.end());
  std::vector<unsigned char> out(sequence ? meshopt_encodeIndexSequenceBound(wide.size(), 81)
                                          : meshopt_encodeIndexBufferBound(wide.size(), 81));
  out.resize(sequence ? meshopt_encodeIndexSequence(out.data(), out.size(), wide.data(), wide.size())
                      : meshopt_encodeIndexBuffer(out.data(), out.size(), wide.data(), wide.size()));
  return Bytes(out);
}

// A meshopt stream: its encoded bytes and what they decode to.
struct EncodedStream {
  std::string bytes;
  size_t count, stride;
  std::string mode, filter;
};

// The grid's streams: positions lossless (or `cutPositions`); normals as octahedral 8-bit
// snorm (KHR_mesh_quantization); UVs through the exponential filter; indices as
// TRIANGLES or as an INDICES sequence.
std::vector<EncodedStream> GridStreams(const Grid& g, bool sequence, const std::string& cutPositions) {
  const size_t n = g.Vertices();
  std::vector<float> four;
  for (size_t i = 0; i < n; ++i)
    four.insert(four.end(), {g.normals[3 * i], g.normals[3 * i + 1], g.normals[3 * i + 2], 0});
  std::vector<int8_t> oct(n * 4);
  meshopt_encodeFilterOct(oct.data(), n, 4, 8, four.data());
  std::vector<uint32_t> expUv(n * 2);
  meshopt_encodeFilterExp(expUv.data(), n, 8, 15, g.uvs.data());
  return {
      {cutPositions.empty() ? EncodeVertices(g.positions.data(), n, 12) : cutPositions, n, 12, "ATTRIBUTES", "NONE"},
      {EncodeVertices(oct.data(), n, 4), n, 4, "ATTRIBUTES", "OCTAHEDRAL"},
      {EncodeVertices(expUv.data(), n, 8), n, 8, "ATTRIBUTES", "EXPONENTIAL"},
      {EncodeIndices(g.indices, sequence), g.indices.size(), 2, sequence ? "INDICES" : "TRIANGLES", "NONE"}};
}

// The streams into b: buffer 0 holds them one after another, and each compressed view
// names its stream there and its decoded place in the fallback buffer (buffer 1, no uri).
// Returns the views, in the streams' order.
std::vector<int> AddMeshoptViews(GltfBuilder& b, const std::vector<EncodedStream>& streams) {
  std::vector<size_t> offsets;
  std::string encoded;
  for (const EncodedStream& s : streams) {
    offsets.push_back(encoded.size());
    std::string bytes = s.bytes;
    bytes.resize((bytes.size() + 3) / 4 * 4, '\0');
    encoded += bytes;
  }
  const size_t base = (b.BinSize() + 3) / 4 * 4;
  b.View(encoded);
  std::vector<int> views;
  size_t fallback = 0;
  for (size_t i = 0; i < streams.size(); ++i) {
    const EncodedStream& s = streams[i];
    const size_t length = s.count * s.stride;
    std::string v =
        "{\"buffer\":1,\"byteOffset\":" + std::to_string(fallback) + ",\"byteLength\":" + std::to_string(length);
    if (s.mode == "ATTRIBUTES") v += ",\"byteStride\":" + std::to_string(s.stride);
    v += ",\"extensions\":{\"EXT_meshopt_compression\":{\"buffer\":0,\"byteOffset\":" +
         std::to_string(base + offsets[i]) + ",\"byteLength\":" + std::to_string(s.bytes.size()) +
         ",\"byteStride\":" + std::to_string(s.stride) + ",\"count\":" + std::to_string(s.count) + ",\"mode\":\"" +
         s.mode + "\",\"filter\":\"" + s.filter + "\"}}}";
    views.push_back(b.RawView(v));
    fallback += (length + 3) / 4 * 4;
  }
  b.extraBuffers.push_back("{\"byteLength\":" + std::to_string(fallback) +
                           ",\"extensions\":{\"EXT_meshopt_compression\":{\"fallback\":true}}}");
  return views;
}

// The grid with every stream meshopt-compressed (GridStreams).
GltfBuilder MeshoptGrid(const Grid& g, bool sequence, const std::string& cutPositions = "") {
  GltfBuilder b;
  AddTexturedMaterial(b);
  const size_t n = g.Vertices();
  const std::vector<int> views = AddMeshoptViews(b, GridStreams(g, sequence, cutPositions));
  const int pos = b.Accessor(views[0], kFloat, n, "VEC3", ",\"min\":[0,0,-1],\"max\":[8,8,1]");
  const int nrm = b.Accessor(views[1], kByte, n, "VEC3", ",\"normalized\":true");
  const int uv = b.Accessor(views[2], kFloat, n, "VEC2");
  const int idx = b.Accessor(views[3], kUShort, g.indices.size(), "SCALAR");
  b.meshes.push_back(Primitive(pos, nrm, uv, idx));
  b.Node("{\"mesh\":0}");
  b.extensionsUsed = b.extensionsRequired = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  return b;
}

Scene LoadGlb(const GltfBuilder& b) {
  TempFile f(b.Glb(), ".glb");
  return LoadGltf(f.path);
}

// Positions and indices decode losslessly; normals within the 8-bit octahedral step
// (the plain grid's normals go through the same snorm encoding in no other way, so the
// bound is the filter's: 2 / 127 per component); UVs through 15-bit mantissas.
TEST(Meshopt, EveryModeAndFilterLoadsThePlainMesh) {
  const Grid g = MakeGrid();
  const Scene plain = Load(PlainGrid(g));
  for (bool sequence : {false, true})
    for (bool glb : {false, true}) {
      const GltfBuilder b = MeshoptGrid(g, sequence);
      const Scene s = glb ? LoadGlb(b) : Load(b);
      const MeshDifference d = Compare(plain, s, 0.0f);
      std::printf("meshopt (%s, %s): worst position %.3g, normal %.3g, uv %.3g\n", sequence ? "INDICES" : "TRIANGLES",
                  glb ? "GLB" : ".gltf", d.position, d.normal, d.uv);
      EXPECT_EQ(d.position, 0.0f);
      EXPECT_LE(d.normal, 0.02f);
      EXPECT_GT(d.normal, 0.0f);  // the octahedral 8-bit encoding is lossy: the filter ran
      EXPECT_LE(d.uv, 1e-4f);
      EXPECT_TRUE(s.ignoredFeatures.empty()) << s.ignoredFeatures.front();
    }
}

// The QUATERNION filter, which no mesh attribute uses (rotations of animations and
// instances do): 12-bit components, back to the unit quaternions up to sign.
TEST(Meshopt, QuaternionFilterRestoresUnitQuaternions) {
  std::vector<float> q;
  for (int i = 0; i < 50; ++i) {
    glm::vec4 v(std::sin(i * 1.3f), std::cos(i * 0.7f), std::sin(i * 2.1f + 1), std::cos(i * 0.3f + 2));
    v = glm::normalize(v);
    q.insert(q.end(), {v.x, v.y, v.z, v.w});
  }
  std::vector<int16_t> encoded(q.size());
  meshopt_encodeFilterQuat(encoded.data(), 50, 8, 12, q.data());
  const std::string stream = EncodeVertices(encoded.data(), 50, 8);
  std::vector<unsigned char> out(50 * 8);
  DecodeMeshoptStream({reinterpret_cast<const unsigned char*>(stream.data()), stream.size()},
                      {"ATTRIBUTES", "QUATERNION", 50, 8}, out);
  float worst = 0;
  for (int i = 0; i < 50; ++i) {
    int16_t c[4];
    std::memcpy(c, out.data() + 8 * i, 8);
    const glm::vec4 got = glm::vec4(c[0], c[1], c[2], c[3]) / 32767.0f;
    const glm::vec4 want(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
    worst = std::max(worst, std::min(glm::length(got - want), glm::length(got + want)));
  }
  EXPECT_LT(worst, 2e-3f);
}

TEST(Meshopt, MalformedStreamsAreNamed) {
  const Grid g = MakeGrid();
  std::string cut = EncodeVertices(g.positions.data(), g.Vertices(), 12);
  cut.resize(cut.size() / 2);
  EXPECT_TRUE(FailsWith(MeshoptGrid(g, false, cut),
                        {"bufferViews[2]: EXT_meshopt_compression: the ATTRIBUTES data", "is malformed"}));
  // Each problem in the extension's fields, one file each.
  const std::string json = MeshoptGrid(g, false).Json();
  for (const auto& [from, to, needle] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"\"mode\":\"TRIANGLES\"", "\"mode\":\"STRIPS\"",
            "bufferViews[5].extensions.EXT_meshopt_compression: mode \"STRIPS\" is not ATTRIBUTES, TRIANGLES or "
            "INDICES"},
           {"\"byteStride\":4,\"count\":81,\"mode\":\"ATTRIBUTES\",\"filter\":\"OCTAHEDRAL\"",
            "\"byteStride\":12,\"count\":81,\"mode\":\"ATTRIBUTES\",\"filter\":\"OCTAHEDRAL\"",
            "byteStride 12 is not 4 or 8 for the OCTAHEDRAL filter"},
           {"\"count\":384", "\"count\":381", "count × byteStride = 762 bytes, but bufferViews[5].byteLength is 768"},
           {"\"EXT_meshopt_compression\":{\"buffer\":0", "\"EXT_meshopt_compression\":{\"buffer\":1",
            "bufferViews[2].extensions.EXT_meshopt_compression.buffer is buffers[1], the fallback, not the compressed "
            "data"},
           {"\"count\":384", "\"count\":10000000000",
            "bufferViews[5].extensions.EXT_meshopt_compression.count is 10000000000, beyond the 32-bit integers"},
       }) {
    std::string edited = json;
    const size_t at = edited.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    edited.replace(at, from.size(), to);
    TempFile f(edited);
    EXPECT_TRUE(LoadFailsWith(f.path, {needle}));
  }
  // An uncompressed bufferView may not read the fallback buffer, which has no data.
  GltfBuilder plain = MeshoptGrid(g, false);
  plain.RawView("{\"buffer\":1,\"byteLength\":4}");
  plain.images.push_back("{\"bufferView\":6,\"mimeType\":\"image/png\"}");
  EXPECT_TRUE(FailsWith(plain, {"bufferViews[6] reads buffers[1], EXT_meshopt_compression's fallback, which holds "
                                "no data"}));
}

// Every cut of each kind of stream fails with Error; none reads past its end.
TEST(Meshopt, EveryCutFailsCleanly) {
  const Grid g = MakeGrid();
  const std::vector<std::pair<std::string, MeshoptStream>> streams = {
      {EncodeVertices(g.positions.data(), g.Vertices(), 12), {"ATTRIBUTES", "NONE", g.Vertices(), 12}},
      {EncodeIndices(g.indices, false), {"TRIANGLES", "NONE", g.indices.size(), 2}},
      {EncodeIndices(g.indices, true), {"INDICES", "NONE", g.indices.size(), 2}}};
  for (const auto& [bytes, s] : streams) {
    std::vector<unsigned char> cut(bytes.begin(), bytes.end()), out(s.count * s.byteStride);
    size_t refused = 0;
    for (size_t n = 0; n < bytes.size(); ++n) {
      cut.resize(n);
      cut.shrink_to_fit();  // so that AddressSanitizer sees a read past the cut
      try {
        DecodeMeshoptStream(cut, s, out);
      } catch (const Error&) {
        ++refused;
      }
      cut.assign(bytes.begin(), bytes.end());
    }
    EXPECT_EQ(refused, bytes.size()) << s.mode;
  }
}

TEST(Meshopt, DecodedSizesCountAgainstTheMemoryBudgetFirst) {
  const Grid g = MakeGrid();
  std::string json = MeshoptGrid(g, false).Json();
  const std::string from = "\"byteLength\":972,\"byteStride\":12";
  json.replace(json.find(from), from.size(), "\"byteLength\":24000000000,\"byteStride\":12");
  const std::string count = "\"byteStride\":12,\"count\":81";
  json.replace(json.find(count), count.size(), "\"byteStride\":12,\"count\":2000000000");
  TempFile f(json);
  EXPECT_TRUE(LoadFailsWith(f.path, {"bufferViews[2] (EXT_meshopt_compression, decoded)", "--max-memory"}));
}

// The corpus's plain models against their compressed encodings in gltf-ext.
TEST(CompressedMeshes, DuckAndBoxLoadAsTheirPlainVersions) {
  VKPT_REQUIRE_SHARED_DATA();
  const Scene duck = LoadGltf(CorpusPath("valid/Duck/glTF-Binary/Duck.glb"));
  const Scene draco = LoadGltf(SharedData("gltf-ext/Duck/glTF-Draco/Duck.gltf"));
  const glm::vec3 extent = duck.bounds.hi - duck.bounds.lo;
  const float size = std::max({extent.x, extent.y, extent.z});
  const MeshDifference d = Compare(duck, draco, size * 1e-4f);
  std::printf("Duck (Draco): %zu triangles, worst position %.3g of a %.3g-unit model, normal %.3g, uv %.3g\n",
              draco.triangles.size(), d.position, size, d.normal, d.uv);
  EXPECT_EQ(draco.triangles.size(), 4212u);
  EXPECT_LE(d.position, size * 1e-3f);
  EXPECT_LE(d.normal, 0.02f);
  EXPECT_LE(d.uv, 2e-3f);
  EXPECT_TRUE(draco.ignoredFeatures.empty()) << draco.ignoredFeatures.front();

  const Scene box = LoadGltf(CorpusPath("valid/Box/glTF-Binary/Box.glb"));
  const Scene meshopt = LoadGltf(SharedData("gltf-ext/BoxMeshopt/glTF-Binary/BoxMeshopt.glb"));
  const MeshDifference e = Compare(box, meshopt, 1e-4f);
  std::printf("BoxMeshopt: %zu triangles, worst position %.3g, normal %.3g\n", meshopt.triangles.size(), e.position,
              e.normal);
  EXPECT_EQ(meshopt.triangles.size(), 12u);
  EXPECT_LE(e.position, 1e-4f);  // 16-bit positions over a unit box
  EXPECT_LE(e.normal, 1e-6f);    // axis-aligned: exact in 8 bits
  EXPECT_TRUE(meshopt.ignoredFeatures.empty()) << meshopt.ignoredFeatures.front();

  // KHR_mesh_quantization: uint16 positions dequantized by the node, int8 normals, int16
  // and int8 morph deltas, posed by its animation at 1 s against the float original.
  const SceneChoice posed{.animation = "0", .time = 1.0};
  const Scene plainCube = LoadGltf(CorpusPath("valid/AnimatedMorphCube/glTF/AnimatedMorphCube.gltf"), {}, posed);
  const Scene quantized =
      LoadGltf(SharedData("gltf-ext/AnimatedMorphCube/glTF-Quantized/AnimatedMorphCube.gltf"), {}, posed);
  const MeshDifference q = Compare(plainCube, quantized, 1e-3f);
  std::printf("AnimatedMorphCube (quantized, at 1 s): worst position %.3g, normal %.3g\n", q.position, q.normal);
  EXPECT_LE(q.position, 5e-3f);  // 16-bit positions of a 2-unit cube, 8- and 16-bit deltas
  EXPECT_LE(q.normal, 0.02f);    // 8-bit normals
}

}  // namespace
}  // namespace vkpt::internal
