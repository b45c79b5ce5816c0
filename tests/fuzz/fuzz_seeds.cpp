// Writes small generated seed files for the image and mesh decoder fuzz targets into
// OUTDIR/env, OUTDIR/pfm, OUTDIR/texture, OUTDIR/draco and OUTDIR/meshopt (run.sh calls
// it; the real files of the test data are read in place besides). EXR and PFM seeds come
// from vkpt's own writers (image/image_encode.h), so they are what vkpt writes; HDR, PNG
// and JPEG seeds from stb_image_write, in each pixel layout the decoders distinguish;
// WebP ones from libwebp; Draco and meshopt ones from those libraries' encoders, each
// behind the header its target parses (RunDraco, RunMeshopt in fuzz_bodies.h).
//   usage: fuzz_seeds OUTDIR
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>
#include <webp/encode.h>
#include <glm/glm.hpp>

#include "image/image.h"
#include "image/image_encode.h"

namespace {

std::string out;

void Write(const std::string& name, const std::vector<uint8_t>& bytes) {
  const std::string path = out + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fclose(f) != 0) {
    std::fprintf(stderr, "fuzz_seeds: cannot write %s\n", path.c_str());
    std::exit(1);
  }
}

void Append(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<uint8_t>*>(context);
  bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}

vkpt::internal::Image Gradient(uint32_t w, uint32_t h) {
  vkpt::internal::Image img{w, h};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) img.At(x, y) = glm::vec3(0.1f * x, 0.25f * y, std::exp2(float(x) - 3.0f));
  return img;
}

void Fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_seeds: %s\n", what.c_str());
  std::exit(1);
}

// An n × n grid of vertices on a bumpy surface, as indexed triangles.
struct Grid {
  std::vector<glm::vec3> positions, normals;
  std::vector<unsigned> indices;
};

Grid MakeGrid(int n) {
  Grid g;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float dzdx = 0.5f * std::cos(0.5f * x) * std::cos(0.5f * y);
      const float dzdy = -0.5f * std::sin(0.5f * x) * std::sin(0.5f * y);
      g.positions.emplace_back(x, y, std::sin(0.5f * x) * std::cos(0.5f * y));
      g.normals.push_back(glm::normalize(glm::vec3(-dzdx, -dzdy, 1.0f)));
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const unsigned v = unsigned(y * n + x);
      for (unsigned i : {v, v + 1, v + n + 1, v, v + n + 1, v + n}) g.indices.push_back(i);
    }
  return g;
}

// The grid as a Draco mesh of positions and normals (points shared between faces).
std::unique_ptr<draco::Mesh> DracoGrid(const Grid& g) {
  draco::TriangleSoupMeshBuilder b;
  b.Start(int(g.indices.size() / 3));
  const int pos = b.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int nor = b.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  for (size_t f = 0; f < g.indices.size() / 3; ++f) {
    const unsigned* c = &g.indices[3 * f];
    b.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &g.positions[c[0]], &g.positions[c[1]], &g.positions[c[2]]);
    b.SetAttributeValuesForFace(nor, draco::FaceIndex(f), &g.normals[c[0]], &g.normals[c[1]], &g.normals[c[2]]);
  }
  return b.Finalize();
}

// A unit cube with a normal and an RGBA8 colour per side: 24 points, seams between sides.
std::unique_ptr<draco::Mesh> DracoCube() {
  draco::TriangleSoupMeshBuilder b;
  b.Start(12);
  const int pos = b.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int nor = b.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int col = b.AddAttribute(draco::GeometryAttribute::COLOR, 4, draco::DT_UINT8, true);
  for (int side = 0; side < 6; ++side) {
    const int axis = side / 2;
    const float s = side % 2 ? 1.0f : -1.0f;
    glm::vec3 n(0.0f), u(0.0f), v(0.0f);
    n[axis] = s;
    u[(axis + 1) % 3] = 1.0f;
    v[(axis + 2) % 3] = s;
    const glm::vec3 corners[4] = {n - u - v, n + u - v, n + u + v, n - u + v};
    const uint8_t rgba[4] = {uint8_t(40 * side), uint8_t(255 - 40 * side), 128, 255};
    for (int t = 0; t < 2; ++t) {
      const draco::FaceIndex f(2 * side + t);
      b.SetAttributeValuesForFace(pos, f, &corners[0], &corners[1 + t], &corners[2 + t]);
      b.SetAttributeValuesForFace(nor, f, &n, &n, &n);
      b.SetAttributeValuesForFace(col, f, rgba, rgba, rgba);
    }
  }
  return b.Finalize();
}

// The fuzz_draco seed of `mesh` as `encoder` encodes it. The header (RunDraco, fuzz_bodies.h) is
// filled in from what libdraco decodes the bitstream to, attributes in their order, so
// the seed decodes whatever the encoder made of the points.
void WriteDraco(const std::string& name, const draco::Mesh& mesh, draco::Encoder& encoder) {
  draco::EncoderBuffer encoded;
  if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok()) Fail("draco cannot encode " + name);
  draco::DecoderBuffer in;
  in.Init(encoded.data(), encoded.size());
  auto decoded = draco::Decoder().DecodeMeshFromBuffer(&in);
  if (!decoded.ok()) Fail("draco cannot decode " + name + ": " + decoded.status().error_msg_string());
  const draco::Mesh& m = *decoded.value();
  if (m.num_attributes() > 4 || m.num_points() > 0xffff || m.num_faces() * 3 > 0xffff)
    Fail(name + " is too large for fuzz_draco's header");
  std::vector<uint8_t> bytes(13, 0);
  bytes[0] = uint8_t(m.num_attributes());
  for (int i = 0; i < m.num_attributes(); ++i) {
    const draco::PointAttribute& a = *m.attribute(i);
    // The index into fuzz_draco's kComponentTypes {5120, 5121, 5122, 5123, 5125, 5126}.
    const int type = a.data_type() == draco::DT_UINT8 ? 1 : a.data_type() == draco::DT_FLOAT32 ? 5 : -1;
    if (type < 0 || a.unique_id() > 0xff) Fail(name + ": attribute " + std::to_string(i) + " has no fuzz_draco layout");
    bytes[1 + 2 * i] = uint8_t(a.unique_id());
    bytes[2 + 2 * i] = uint8_t((a.num_components() - 1) | type << 2);
  }
  const uint32_t points = m.num_points(), indices = m.num_faces() * 3;
  bytes[9] = uint8_t(points), bytes[10] = uint8_t(points >> 8);
  bytes[11] = uint8_t(indices), bytes[12] = uint8_t(indices >> 8);
  bytes.insert(bytes.end(), encoded.data(), encoded.data() + encoded.size());
  Write("draco/" + name, bytes);
}

// Indices into fuzz_meshopt's kModes and kFilters.
enum MeshoptMode : uint8_t { kAttributes, kTriangles, kIndices };
enum MeshoptFilter : uint8_t { kNone, kOctahedral, kQuaternion, kExponential };

// The fuzz_meshopt seed: its header (RunMeshopt, fuzz_bodies.h), then the encoded stream.
void WriteMeshopt(const std::string& name, MeshoptMode mode, MeshoptFilter filter, size_t stride, size_t count,
                  const std::vector<unsigned char>& encoded) {
  if (encoded.empty() || stride >= 512 || count >= 4096) Fail(name + " does not fit fuzz_meshopt's header");
  std::vector<uint8_t> bytes = {
      mode, filter, uint8_t(stride), uint8_t(stride >> 8), uint8_t(count), uint8_t(count >> 8)};
  bytes.insert(bytes.end(), encoded.begin(), encoded.end());
  Write("meshopt/" + name, bytes);
}

// meshopt_encodeVertexBuffer of `count` elements of `stride` bytes.
std::vector<unsigned char> EncodeVertices(const void* elements, size_t count, size_t stride) {
  std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
  out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), elements, count, stride));
  return out;
}

// Each mode and filter of EXT_meshopt_compression on a 20 × 20 grid (400 vertices: two
// of the vertex codec's blocks of 256), with each byteStride its filter allows.
void WriteMeshoptSeeds() {
  const Grid g = MakeGrid(20);
  const size_t n = g.positions.size();
  WriteMeshopt("attributes.bin", kAttributes, kNone, 12, n, EncodeVertices(g.positions.data(), n, 12));

  std::vector<float> normals4, quats, flat;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 nv = g.normals[i];
    normals4.insert(normals4.end(), {nv.x, nv.y, nv.z, 0.0f});
    // The rotation taking +Z to the normal, as a unit quaternion (x, y, z, w).
    const glm::vec3 axis = glm::cross(glm::vec3(0, 0, 1), nv);
    const float w = 1.0f + nv.z, len = std::sqrt(glm::dot(axis, axis) + w * w);
    quats.insert(quats.end(), {axis.x / len, axis.y / len, axis.z / len, w / len});
    flat.insert(flat.end(), {g.positions[i].x, g.positions[i].y, g.positions[i].z});
  }
  for (size_t stride : {4, 8}) {
    std::vector<unsigned char> filtered(n * stride);
    meshopt_encodeFilterOct(filtered.data(), n, stride, stride == 4 ? 8 : 12, normals4.data());
    WriteMeshopt("octahedral-" + std::to_string(stride) + ".bin", kAttributes, kOctahedral, stride, n,
                 EncodeVertices(filtered.data(), n, stride));
  }
  std::vector<unsigned char> filtered(n * 8);
  meshopt_encodeFilterQuat(filtered.data(), n, 8, 12, quats.data());
  WriteMeshopt("quaternion.bin", kAttributes, kQuaternion, 8, n, EncodeVertices(filtered.data(), n, 8));
  filtered.resize(n * 12);
  meshopt_encodeFilterExp(filtered.data(), n, 12, 15, flat.data());
  WriteMeshopt("exponential.bin", kAttributes, kExponential, 12, n, EncodeVertices(filtered.data(), n, 12));

  // Index streams: the same bytes decode to 16- or 32-bit indices.
  const size_t count = g.indices.size();
  std::vector<unsigned char> triangles(meshopt_encodeIndexBufferBound(count, n));
  triangles.resize(meshopt_encodeIndexBuffer(triangles.data(), triangles.size(), g.indices.data(), count));
  std::vector<unsigned char> sequence(meshopt_encodeIndexSequenceBound(count, n));
  sequence.resize(meshopt_encodeIndexSequence(sequence.data(), sequence.size(), g.indices.data(), count));
  for (size_t stride : {2, 4}) {
    WriteMeshopt("triangles-" + std::to_string(stride) + ".bin", kTriangles, kNone, stride, count, triangles);
    WriteMeshopt("indices-" + std::to_string(stride) + ".bin", kIndices, kNone, stride, count, sequence);
  }
}

void WriteDracoSeeds() {
  const std::unique_ptr<draco::Mesh> grid = DracoGrid(MakeGrid(8)), cube = DracoCube();
  if (!grid || !cube) Fail("draco cannot build the seed meshes");
  // Sequential connectivity, attributes lossless then quantized.
  draco::Encoder sequential;
  sequential.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  WriteDraco("grid-sequential.drc", *grid, sequential);
  sequential.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  WriteDraco("grid-sequential-quantized.drc", *grid, sequential);
  // Edgebreaker with quantized positions and normals (octahedral normal prediction);
  // the slowest speed setting takes the valence edgebreaker.
  draco::Encoder edgebreaker;
  edgebreaker.SetEncodingMethod(draco::MESH_EDGEBREAKER_ENCODING);
  edgebreaker.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  edgebreaker.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  WriteDraco("grid-edgebreaker-quantized.drc", *grid, edgebreaker);
  edgebreaker.SetSpeedOptions(0, 0);
  WriteDraco("cube-edgebreaker-valence.drc", *cube, edgebreaker);
}

// Environment maps: EXR as vkpt writes it (RGB; RGB with AOV channels), Radiance HDR
// flat (narrow) and run-length encoded (8 to 32767 wide); PFM as vkpt writes it
// (little-endian) and the same big-endian (positive scale).
void WriteImageSeeds() {
  const vkpt::internal::Image small = Gradient(5, 3), wide = Gradient(16, 2);
  Write("env/rgb.exr", vkpt::internal::EncodeExr(small, "rgb.exr"));
  std::vector<vkpt::internal::ExrChannel> channels = vkpt::internal::RgbChannels(small);
  channels.push_back({"A", std::vector<float>(15, 1.0f)});
  channels.push_back({"depth.Z", std::vector<float>(15, 2.5f)});
  Write("env/aovs.exr", vkpt::internal::EncodeExrChannels(5, 3, channels, "aovs.exr"));
  for (const vkpt::internal::Image* img : {&small, &wide}) {
    std::vector<uint8_t> bytes;
    stbi_write_hdr_to_func(Append, &bytes, int(img->width), int(img->height), 3, &img->pixels[0].x);
    Write(img == &small ? "env/flat.hdr" : "env/rle.hdr", bytes);
  }

  std::vector<uint8_t> le = vkpt::internal::EncodePfm(small);
  Write("pfm/little-endian.pfm", le);
  const std::string header = "PF\n5 3\n1.0\n";
  std::vector<uint8_t> be(header.begin(), header.end());
  for (uint32_t y = small.height; y-- > 0;)
    for (uint32_t x = 0; x < small.width; ++x)
      for (int c = 0; c < 3; ++c) {
        uint32_t u;
        std::memcpy(&u, &small.At(x, y)[c], 4);
        for (int b = 3; b >= 0; --b) be.push_back(uint8_t(u >> (8 * b)));
      }
  Write("pfm/big-endian.pfm", be);
}

// Textures: PNG grey, grey+alpha, RGB, RGBA; JPEG grey and RGB; WebP lossless (RGBA)
// and lossy (RGB), as libwebp encodes them.
void WriteTextureSeeds() {
  std::vector<uint8_t> texels(6 * 5 * 4);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 37);
  for (int comp = 1; comp <= 4; ++comp) {
    std::vector<uint8_t> bytes;
    stbi_write_png_to_func(Append, &bytes, 6, 5, comp, texels.data(), 6 * comp);
    Write("texture/" + std::to_string(comp) + "-channel.png", bytes);
  }
  for (int comp : {1, 3}) {
    std::vector<uint8_t> bytes;
    stbi_write_jpg_to_func(Append, &bytes, 6, 5, comp, texels.data(), 90);
    Write("texture/" + std::to_string(comp) + "-channel.jpg", bytes);
  }
  uint8_t* webp = nullptr;
  size_t size = WebPEncodeLosslessRGBA(texels.data(), 6, 5, 6 * 4, &webp);
  Write("texture/lossless.webp", std::vector<uint8_t>(webp, webp + size));
  WebPFree(webp);
  size = WebPEncodeRGB(texels.data(), 6, 5, 6 * 3, 80.0f, &webp);
  Write("texture/lossy.webp", std::vector<uint8_t>(webp, webp + size));
  WebPFree(webp);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds OUTDIR\n");
    return 2;
  }
  out = argv[1];
  for (const char* dir : {"env", "pfm", "texture", "draco", "meshopt"})
    std::filesystem::create_directories(out + "/" + dir);

  WriteImageSeeds();
  WriteTextureSeeds();
  WriteDracoSeeds();
  WriteMeshoptSeeds();
  return 0;
}
