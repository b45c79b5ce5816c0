#include "bvh/spatial_split.h"

#include <algorithm>
#include <vector>

#include "bvh/clip_triangle.h"

namespace vkpt::internal {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Spatial bin k of one axis spans [Plane(k), Plane(k + 1)).
struct SpatialBins {
  float lo, scale, step;
  uint32_t count;
  SpatialBins(const Bounds3f& box, int axis, uint32_t nb) {
    const float extent = box.hi[axis] - box.lo[axis];
    lo = box.lo[axis], scale = float(nb) / extent, step = extent / float(nb), count = nb;
  }
  uint32_t Of(float x) const { return std::min(count - 1, uint32_t(std::max(0.0f, (x - lo) * scale))); }
  float Plane(uint32_t k) const { return lo + float(k) * step; }
};

void Vertices(std::span<const glm::vec3> vertices, uint32_t prim, Float4 v[3]) {
  for (int k = 0; k < 3; ++k) {
    const glm::vec3& p = vertices[3 * size_t(prim) + k];
    v[k] = Float4{p.x, p.y, p.z, 0.0f};
  }
}

// The spatial bins of one axis: every reference is counted where it enters (its first
// bin) and where it leaves (its last), and the box of its part within each bin it spans
// goes into that bin.
struct AxisBins {
  std::vector<Bin> bins;
  std::vector<uint32_t> entries, exits;

  void Fill(std::span<const BuildPrim> refs, std::span<const glm::vec3> vertices, const SpatialBins& sb, int a) {
    bins.assign(sb.count, Bin{});
    entries.assign(sb.count, 0u);
    exits.assign(sb.count, 0u);
    for (const BuildPrim& p : refs) {
      const uint32_t b0 = sb.Of(p.box.lo[a]), b1 = sb.Of(p.box.hi[a]);
      ++entries[b0];
      ++exits[b1];
      if (b0 == b1) {
        bins[b0].Extend(Load4(&p.box.lo.x), Load4(&p.box.hi.x));
        continue;
      }
      // The part in each bin, cut to the reference's box. These boxes only estimate
      // costs (the split itself clips conservatively), so they are not padded.
      Float4 v[3];
      Vertices(vertices, p.index, v);
      const Float4 refLo = Load4(&p.box.lo.x), refHi = Load4(&p.box.hi.x);
      for (uint32_t b = b0; b <= b1; ++b) {
        Box4 part = ClipTriangle(v, a, b == b0 ? -kInf : sb.Plane(b), b == b1 ? kInf : sb.Plane(b + 1));
        part = {Max4(part.lo, refLo), Min4(part.hi, refHi)};
        if (!part.Empty()) bins[b].Extend(part.lo, part.hi);
      }
    }
  }
};

// Where straddling references go (Stich et al. 2009, §4.3, "reference unsplitting"):
// compare A_L·N_L + A_R·N_R for the split reference with the whole reference added to
// either box and dropped from the other count. Starts from the children as the split
// costed them (every straddler split) and follows each decision.
struct Unsplitting {
  Bounds3f boxL, boxR;
  float nl, nr;
  uint32_t slack;  // free slots left for second halves

  enum Place { kBoth, kLeft, kRight };
  Place Decide(const Bounds3f& ref) {
    Bounds3f wholeL = boxL, wholeR = boxR;
    wholeL.Extend(ref);
    wholeR.Extend(ref);
    const float costSplit = slack > 0 ? boxL.SurfaceArea() * nl + boxR.SurfaceArea() * nr : kInf;
    const float costLeft = wholeL.SurfaceArea() * nl + boxR.SurfaceArea() * (nr - 1.0f);
    const float costRight = boxL.SurfaceArea() * (nl - 1.0f) + wholeR.SurfaceArea() * nr;
    if (costSplit <= costLeft && costSplit <= costRight) {
      --slack;
      return kBoth;
    }
    if (costLeft <= costRight) {
      boxL = wholeL;
      nr -= 1.0f;
      return kLeft;
    }
    boxR = wholeR;
    nl -= 1.0f;
    return kRight;
  }
};

}  // namespace

SpatialSplit FindSpatialSplit(std::span<const BuildPrim> refs, const Bounds3f& box,
                              std::span<const glm::vec3> vertices, const BvhBuildOptions& o) {
  SpatialSplit best;
  const float parentArea = box.SurfaceArea();
  if (!(parentArea > 0.0f)) return best;
  static thread_local AxisBins axis;  // reused: no allocation per node
  for (int a = 0; a < 3; ++a) {
    if (!(box.hi[a] > box.lo[a])) continue;
    axis.Fill(refs, vertices, SpatialBins(box, a, o.bins), a);
    SweepBins(
        axis.bins.data(), o, [&](uint32_t b) { return axis.entries[b]; }, [&](uint32_t b) { return axis.exits[b]; },
        parentArea, [&](uint32_t b, float cost, const Bin& left, const Bin& right) {
          if (cost < best.cost) best = {a, b, cost, left, right};
        });
  }
  return best;
}

std::optional<Sides> SplitSpatially(std::span<BuildPrim> slots, uint32_t count, const Bounds3f& box,
                                    const SpatialSplit& split, std::span<const glm::vec3> vertices,
                                    const BvhBuildOptions& o) {
  const int a = split.axis;
  const SpatialBins sb(box, a, o.bins);
  const float plane = sb.Plane(split.bin);
  Unsplitting place{split.left.Box(), split.right.Box(), float(split.left.count), float(split.right.count),
                    uint32_t(slots.size()) - count};
  std::vector<BuildPrim> left, right;
  for (const BuildPrim& p : slots.first(count)) {
    const uint32_t b0 = sb.Of(p.box.lo[a]), b1 = sb.Of(p.box.hi[a]);
    if (b1 < split.bin || b0 >= split.bin) {
      (b1 < split.bin ? left : right).push_back(p);
      continue;
    }
    Float4 v[3];
    Vertices(vertices, p.index, v);
    const Bounds3f l = Conservative(ClipTriangle(v, a, -kInf, plane), p.box);
    const Bounds3f r = Conservative(ClipTriangle(v, a, plane, kInf), p.box);
    if (l.Empty() || r.Empty()) {  // all on one side after all
      (l.Empty() ? right : left).push_back(p);
      continue;
    }
    switch (place.Decide(p.box)) {
      case Unsplitting::kBoth: left.push_back({l, p.index, 0}), right.push_back({r, p.index, 0}); break;
      case Unsplitting::kLeft: left.push_back(p); break;
      case Unsplitting::kRight: right.push_back(p); break;
    }
  }
  if (left.empty() || right.empty()) return std::nullopt;
  std::copy(left.begin(), left.end(), slots.begin());
  std::copy(right.begin(), right.end(), slots.begin() + left.size());
  return Sides{uint32_t(left.size()), uint32_t(right.size())};
}

}  // namespace vkpt::internal
