#include "render/render_scene.h"

#include "bvh/quantized_layout.h"

#include <cmath>
#include <utility>

#include "render/light_table.h"
#include "render/material_packing.h"
#include "render/octahedral.h"
#include "render/texture_store.h"
#include "shared/bsdf.h"
#include "shared/sampling.h"
#include "util/error.h"
#include "util/parallel.h"

namespace vkpt::internal {

bool IsDegenerate(const SceneTriangle& t) {
  glm::vec3 e1 = t.v1 - t.v0, e2 = t.v2 - t.v0;
  // |e1 × e2| = |e1||e2| sin(angle): degenerate when the angle is below ~1e-6 rad.
  return !(glm::length(glm::cross(e1, e2)) > 1e-6f * glm::length(e1) * glm::length(e2));
}

namespace {

// The BVH builder's input: the boxes of the scene's non-degenerate triangles, their
// indices in the scene, and (for spatial splits) their vertices as the GPU stores them.
struct BuildInput {
  std::vector<Bounds3f> bounds;
  std::vector<glm::vec3> vertices;
  std::vector<uint32_t> kept;
  uint32_t degenerate = 0;
};

BuildInput CollectBuildInput(const Scene& scene, const BvhBuildOptions& options) {
  BuildInput in;
  in.bounds.reserve(scene.triangles.size());
  in.kept.reserve(scene.triangles.size());
  for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
    const SceneTriangle& t = scene.triangles[i];
    if (IsDegenerate(t)) {
      ++in.degenerate;
      continue;
    }
    // The box also holds v0 + e1 and v0 + e2 as stored for the GPU (they can differ
    // from v1, v2 in the last bit), so no rounding puts a triangle outside its leaf.
    Bounds3f b;
    b.Extend(t.v0);
    b.Extend(t.v1);
    b.Extend(t.v2);
    b.Extend(t.v0 + (t.v1 - t.v0));
    b.Extend(t.v0 + (t.v2 - t.v0));
    in.bounds.push_back(b);
    if (options.splits != SplitMode::kObject)
      in.vertices.insert(in.vertices.end(), {t.v0, t.v0 + (t.v1 - t.v0), t.v0 + (t.v2 - t.v0)});
    in.kept.push_back(i);
  }
  return in;
}

// The triangles in BVH leaf order (primOrder indexes `kept`), as v0, e1, e2.
std::vector<shader::Triangle> LeafOrderTriangles(const Scene& scene, const std::vector<uint32_t>& primOrder,
                                                 const std::vector<uint32_t>& kept) {
  std::vector<shader::Triangle> triangles;
  triangles.reserve(primOrder.size());
  for (uint32_t k : primOrder) {
    const uint32_t src = kept[k];
    const SceneTriangle& t = scene.triangles[src];
    shader::Triangle g{};
    g.v0 = t.v0;
    g.e1 = t.v1 - t.v0;
    g.e2 = t.v2 - t.v0;
    g.material = t.material;
    g.sourceIndex = src;
    triangles.push_back(g);
  }
  return triangles;
}

// The scene's vertex normals, octahedrally encoded (shared/shading_normal.h); triangles
// without them stay flat (all zero). So do triangles whose three vertex normals encode
// to the code of their own face normal (flat-shaded boxes such as the Cornell box's):
// interpolating them would give the face normal back up to the encoding's error, at the
// cost of three decodes per hit, and a scene without smooth triangles lets the shader
// drop that code (pathtrace.comp). Encoding tries four candidates per normal, which on
// 10 M triangles is worth the threads.
std::vector<shader::TriangleShading> TriangleShadings(const Scene& scene, unsigned threads) {
  if (!scene.normals.empty() && scene.normals.size() != scene.triangles.size())
    throw Error(scene.path + ": " + std::to_string(scene.normals.size()) + " vertex normal triples for " +
                std::to_string(scene.triangles.size()) + " triangles");
  std::vector<shader::TriangleShading> shading(scene.triangles.size(), shader::TriangleShading{0, 0, 0, 0});
  ParallelFor(
      scene.normals.size(), ThreadCount(threads),
      [&](size_t i) {
        const VertexNormals& n = scene.normals[i];
        if (!n.Present()) return;
        const shader::TriangleShading s{EncodeOctahedral(n.n0), EncodeOctahedral(n.n1), EncodeOctahedral(n.n2),
                                        shader::kShadingHasNormals};
        const SceneTriangle& t = scene.triangles[i];
        // A degenerate triangle has no face normal (and is never hit): it keeps its own.
        if (!IsDegenerate(t)) {
          const uint32_t face = EncodeOctahedral(glm::normalize(glm::cross(t.v1 - t.v0, t.v2 - t.v0)));
          if (s.n0 == face && s.n1 == face && s.n2 == face) return;
        }
        shading[i] = s;
      },
      4096);
  return shading;
}

// The scene's tangents, octahedrally encoded like the normals (TriangleShadings), as
// many and threaded alike.
std::vector<shader::TriangleTangents> PackTangents(const Scene& scene, unsigned threads) {
  std::vector<shader::TriangleTangents> packed(scene.tangents.size(), shader::TriangleTangents{0, 0, 0, 0});
  ParallelFor(
      scene.tangents.size(), ThreadCount(threads),
      [&](size_t i) {
        const VertexTangents& t = scene.tangents[i];
        shader::TriangleTangents& p = packed[i];
        uint32_t* codes[3] = {&p.t0, &p.t1, &p.t2};
        for (int k = 0; k < 3; ++k) {
          const glm::vec3 v(t.t[k]);
          if (glm::dot(v, v) > 0.0f) *codes[k] = EncodeOctahedral(glm::normalize(v));
          else p.signs |= shader::kTangentsMissing;  // the normal map is not applied here
          if (t.t[k].w < 0.0f) p.signs |= 1u << k;
        }
      },
      4096);
  return packed;
}

// The scene's vertex colours as unorm16 pairs (shared/vertex_color.h), or none.
std::vector<shader::TriangleColors> PackVertexColors(const Scene& scene) {
  if (!scene.colors.empty() && scene.colors.size() != scene.triangles.size())
    throw Error(scene.path + ": " + std::to_string(scene.colors.size()) + " vertex colour triples for " +
                std::to_string(scene.triangles.size()) + " triangles");
  std::vector<shader::TriangleColors> packed;
  packed.reserve(scene.colors.size());
  for (const VertexColors& c : scene.colors)
    packed.push_back({glm::packUnorm2x16({c.c0.r, c.c0.g}), glm::packUnorm2x16({c.c0.b, c.c0.a}),
                      glm::packUnorm2x16({c.c1.r, c.c1.g}), glm::packUnorm2x16({c.c1.b, c.c1.a}),
                      glm::packUnorm2x16({c.c2.r, c.c2.g}), glm::packUnorm2x16({c.c2.b, c.c2.a}), 0u, 0u});
  return packed;
}

// The scene's texture coordinates and textures, when some material has one (rs.textureRefs
// is packed).
void AddTextures(const Scene& scene, unsigned threads, RenderScene& rs) {
  if (rs.textureRefs.empty()) return;
  if (scene.uvs.size() != scene.triangles.size())
    throw Error(scene.path + ": " + std::to_string(scene.uvs.size()) + " texture coordinate triples for " +
                std::to_string(scene.triangles.size()) + " triangles");
  rs.uvs.reserve(scene.uvs.size());
  for (const VertexUVs& u : scene.uvs)
    rs.uvs.push_back({u.set0[0], u.set0[1], u.set0[2], u.set1[0], u.set1[1], u.set1[2]});
  if (!scene.tangents.empty() && scene.tangents.size() != scene.triangles.size())
    throw Error(scene.path + ": " + std::to_string(scene.tangents.size()) + " tangent triples for " +
                std::to_string(scene.triangles.size()) + " triangles");
  rs.tangents = PackTangents(scene, threads);
  TextureStore store = BuildTextureStore(scene, threads);
  rs.textures = std::move(store.textures);
  rs.texels = std::move(store.words);
  rs.texelDecode = TexelDecodeTable();
}

}  // namespace

namespace {

// Whether some triangle's material has the property.
bool SomeTriangleUses(const RenderScene& scene, bool (*property)(const shader::Material&)) {
  std::vector<char> used(scene.materials.size(), 0);
  for (const shader::Triangle& t : scene.triangles)
    if (t.material < used.size()) used[t.material] = 1;
  for (size_t i = 0; i < used.size(); ++i)
    if (used[i] && property(scene.materials[i])) return true;
  return false;
}

bool UsesAlphaTest(const RenderScene& scene) {
  return SomeTriangleUses(scene,
                          [](const shader::Material& m) { return (m.flags & shader::kMaterialAlphaTested) != 0u; });
}

}  // namespace

bool UsesGlossyMaterial(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return !shader::IsLambertian(m); });
}

bool UsesVolumeMaterial(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return (m.flags & shader::kMaterialVolume) != 0u; });
}

bool UsesClearcoat(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return m.clearcoat > 0.0f; });
}

bool UsesSheen(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return m.sheenColor != glm::vec3(0.0f); });
}

bool UsesDiffuseTransmission(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return m.diffuseTransmission > 0.0f; });
}

bool UsesIridescence(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return m.iridescence > 0.0f; });
}

bool UsesAnisotropy(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return m.anisotropy > 0.0f; });
}

bool UsesDispersion(const RenderScene& scene) {
  return SomeTriangleUses(scene, [](const shader::Material& m) { return m.dispersion > 0.0f; });
}

bool HasLightSources(const RenderScene& scene) {
  for (const shader::Light& l : scene.lights) {
    if (l.type == shader::kLightEnvironment) continue;
    if (l.type != shader::kLightTriangle && l.type != shader::kLightTwoSidedTriangle) return true;
    const uint32_t m = scene.triangles[l.triangle].material;
    if (scene.textureRefs.empty() ||
        scene.textureRefs[m * shader::kTextureSlots + shader::kSlotEmissive].texture == shader::kInvalidIndex)
      return true;
  }
  return false;
}

RenderScene PrepareRenderScene(const Scene& scene, const BvhBuildOptions& options, bool forCpu, bool forGpu) {
  BuildInput in = CollectBuildInput(scene, options);
  if (in.kept.empty()) throw Error(scene.path + ": every triangle of the scene is degenerate (zero area)");
  Bvh bvh = BuildBvh(in.bounds, options, in.vertices);

  RenderScene rs;
  rs.degenerateTriangles = in.degenerate;
  rs.nodes = std::move(bvh.nodes);
  rs.nodeCopies = bvh.copies;
  rs.bvhStats = bvh.stats;
  PackedMaterials packed = PackMaterials(scene);
  rs.materials = std::move(packed.materials);
  rs.textureRefs = std::move(packed.textureRefs);
  rs.triangles = LeafOrderTriangles(scene, bvh.primOrder, in.kept);
  if (forCpu) rs.wideLayout = BuildWideLayout(rs.nodes, bvh.stats.nodes, rs.triangles);
  if (forGpu) rs.gpuNodes = BuildQuantizedLayout(rs.nodes, bvh.stats.nodes, bvh.copies);
  AddTextures(scene, options.threads, rs);  // before the light table, which reads emissive textures
  BuildLightTable(scene, rs);
  rs.shading = TriangleShadings(scene, options.threads);
  rs.vertexColors = PackVertexColors(scene);
  rs.alphaTested = UsesAlphaTest(rs);
  return rs;
}

void RestyleRenderScene(const Scene& scene, RenderScene& rs) {
  PackedMaterials packed = PackMaterials(scene);
  rs.materials = std::move(packed.materials);
  rs.textureRefs = std::move(packed.textureRefs);
  rs.lights.clear();
  rs.lightTree.clear();
  rs.treeLights = 0;
  rs.lightTreeDepth = 0;
  BuildLightTable(scene, rs);
  rs.alphaTested = UsesAlphaTest(rs);
}

std::vector<uint32_t> TriangleLights(const RenderScene& rs) {
  std::vector<uint32_t> lights(rs.triangles.size());
  for (size_t i = 0; i < rs.triangles.size(); ++i) lights[i] = rs.triangles[i].light;
  return lights;
}

shader::FrameParams MakeFrameParams(const RenderScene& scene, const Camera& camera, uint32_t width, uint32_t height) {
  shader::FrameParams p{};
  p.lightCount = uint32_t(scene.lights.size());
  p.treeLights = scene.treeLights;
  p.treeDepth = scene.lightTreeDepth;
  p.envLight = shader::kInvalidIndex;
  p.textureLod = 1u;
  for (uint32_t i = 0; i < scene.lights.size(); ++i)
    if (scene.lights[i].type == shader::kLightEnvironment) p.envLight = i;
  p.nodeCount = uint32_t(scene.gpuNodes.size() / scene.nodeCopies);
  p.nodeCopies = scene.nodeCopies;
  p.origin = camera.position;
  p.forward = camera.forward;
  p.up = camera.up;
  p.right = camera.right;
  p.width = width;
  p.height = height;
  p.aspect = float(width) / float(height);
  p.orthographic = camera.orthographic ? 1u : 0u;
  p.tanHalfFovY = camera.orthographic ? camera.ymag : std::tan(0.5f * camera.yfov);
  SetEnvironmentParams(p, scene.environment, 0.0f, 1.0f);
  return p;
}

}  // namespace vkpt::internal
