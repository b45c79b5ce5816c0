// The CPU tracer's walk (cpu/traversal.h), included twice by cpu/traversal.cpp: once as
// written for any CPU (4-wide vectors, SSE or NEON through util/float4.h), once with
// VKPT_WALK_AVX2 under GCC's AVX2 target, which tests a node's eight boxes in one 8-wide
// step. Each inclusion sits in its own namespace of internal linkage, so nothing of one
// can stand in for the other at link time (an inline function compiled for AVX2 must
// never run on a CPU without it). No include guard, for that reason.

struct RaySlabs {
  Float4 origin[3];
  Float4 dir[3];
  Float4 invDir[3];
  // Per axis, where in a BvhWideNode the near and far planes of the boxes lie: the lo row
  // for a positive direction, the hi row for a negative one (the ray meets that plane
  // first), so a slab test needs no min/max of the two planes' distances.
  uint32_t nearRow[3], farRow[3];
#if VKPT_WALK_AVX2
  __m256 origin8[3], invDir8[3];
#endif
};

// The slab test of the kBvhWidth boxes of `n` at once: a hit mask (lane k: bit k), the
// entry distances in tEnter. The exit distance has the 1 + 2γ₃ slack of
// shader::IntersectBox. An unused lane (lo = +∞, hi = −∞) enters at +∞ and leaves at −∞.
// Both forms compute (plane − o)·(1/d) and take maxima and minima alike (maxps/minps,
// the second operand on NaN), so they decide alike.
inline int IntersectNode(const BvhWideNode& n, const RaySlabs& r, float tMax, float tEnter[kBvhWidth]) {
  const float* planes = &n.lo[0][0];
#if VKPT_WALK_AVX2
  __m256 enter = _mm256_setzero_ps(), exit = _mm256_set1_ps(tMax);
  for (int axis = 0; axis < 3; ++axis) {
    const __m256 near = _mm256_load_ps(planes + r.nearRow[axis]);
    const __m256 far = _mm256_load_ps(planes + r.farRow[axis]);
    enter = _mm256_max_ps(enter, _mm256_mul_ps(_mm256_sub_ps(near, r.origin8[axis]), r.invDir8[axis]));
    exit = _mm256_min_ps(exit, _mm256_mul_ps(_mm256_sub_ps(far, r.origin8[axis]), r.invDir8[axis]));
  }
  exit = _mm256_mul_ps(exit, _mm256_set1_ps(1.0000004f));
  _mm256_storeu_ps(tEnter, enter);
  return _mm256_movemask_ps(_mm256_cmp_ps(enter, exit, _CMP_LE_OQ));
#else
  int mask = 0;
  for (int half = 0; half < kBvhWidth / 4; ++half) {
    Float4 enter = Splat4(0.0f), exit = Splat4(tMax);
    for (int axis = 0; axis < 3; ++axis) {
      const float* near = planes + r.nearRow[axis] + 4 * half;
      const float* far = planes + r.farRow[axis] + 4 * half;
      enter = Max4(enter, (Load4(near) - r.origin[axis]) * r.invDir[axis]);
      exit = Min4(exit, (Load4(far) - r.origin[axis]) * r.invDir[axis]);
    }
    exit *= Splat4(1.0000004f);
    std::memcpy(tEnter + 4 * half, &enter, sizeof enter);
    mask |= Mask4(enter <= exit) << (4 * half);
  }
  return mask;
#endif
}

// shader::IntersectTriangle (Möller–Trumbore) on the four triangles of a packet: the same
// operations in the same order (glm's cross and left-to-right dot), so t, b1 and b2 are
// bit-identical to the scalar test's. Returns the 4-bit mask of lanes with a hit in
// (0, tMax). Always inlined: with four walks (closest or any hit, with or without alpha)
// GCC stops inlining it, and the Cornell box's shadow rays cost 4 % more instructions.
[[gnu::always_inline]] inline int IntersectPacket(const TrianglePacket& p, const RaySlabs& r, float tMax, Float4& t,
                                                  Float4& b1, Float4& b2) {
  const Float4* d = r.dir;
  const Float4 px = d[1] * p.e2[2] - p.e2[1] * d[2];
  const Float4 py = d[2] * p.e2[0] - p.e2[2] * d[0];
  const Float4 pz = d[0] * p.e2[1] - p.e2[0] * d[1];
  const Float4 det = (p.e1[0] * px + p.e1[1] * py) + p.e1[2] * pz;
  const Float4 invDet = Splat4(1.0f) / det;
  const Float4 sx = r.origin[0] - p.v0[0], sy = r.origin[1] - p.v0[1], sz = r.origin[2] - p.v0[2];
  b1 = ((sx * px + sy * py) + sz * pz) * invDet;
  const Float4 qx = sy * p.e1[2] - p.e1[1] * sz;
  const Float4 qy = sz * p.e1[0] - p.e1[2] * sx;
  const Float4 qz = sx * p.e1[1] - p.e1[0] * sy;
  b2 = ((d[0] * qx + d[1] * qy) + d[2] * qz) * invDet;
  t = ((p.e2[0] * qx + p.e2[1] * qy) + p.e2[2] * qz) * invDet;
  const Float4 zero = Splat4(0.0f), one = Splat4(1.0f);
  // The scalar test's early outs, as one mask (comparisons with NaN are false there too).
  const Int4 ok =
      (det != zero) & ~(b1 < zero) & ~(b1 > one) & ~(b2 < zero) & ~(b1 + b2 > one) & (t > zero) & (t < Splat4(tMax));
  return (ok[0] & 1) | (ok[1] & 2) | (ok[2] & 4) | (ok[3] & 8);
}

RaySlabs MakeSlabs(glm::vec3 origin, glm::vec3 dir) {
  const glm::vec3 inv = shader::SafeInverse(dir);
  RaySlabs slabs;
  for (int axis = 0; axis < 3; ++axis) {
    slabs.origin[axis] = Splat4(origin[axis]);
    slabs.dir[axis] = Splat4(dir[axis]);
    slabs.invDir[axis] = Splat4(inv[axis]);
    const uint32_t lo = kBvhWidth * axis, hi = kBvhWidth * (3 + axis);  // rows of BvhWideNode's planes
    slabs.nearRow[axis] = inv[axis] < 0.0f ? hi : lo;
    slabs.farRow[axis] = inv[axis] < 0.0f ? lo : hi;
#if VKPT_WALK_AVX2
    slabs.origin8[axis] = _mm256_set1_ps(origin[axis]);
    slabs.invDir8[axis] = _mm256_set1_ps(inv[axis]);
#endif
  }
  return slabs;
}

// The deferred farther children of the walk (node index << 4, or a leaf code) with their
// entry distances, so that one beyond the closest hit found since is dropped without
// another box test. The first kInline entries live on the call stack; the builder bounds
// nothing about depth, so deeper ones (pathological trees only) go to the heap.
class DeferredStack {
 public:
  void Push(uint32_t code, float tEnter) {
    if (top_ < kInline) inline_[top_++] = {code, tEnter};
    else overflow_.push_back({code, tEnter});
  }

  // Pops until an entry still in front of the closest hit (tMax) and sets `code` to it;
  // false once none is left. The box test's exit slack (1 + 2γ₃) is applied to tMax so
  // culling stays as conservative as the test itself.
  bool PopInFront(float tMax, uint32_t& code) {
    Entry e;
    while (Pop(e))
      if (e.tEnter <= tMax * 1.0000004f) {
        code = e.code;
        return true;
      }
    return false;
  }

 private:
  static constexpr int kInline = 64;
  struct Entry {
    uint32_t code;
    float tEnter;
  };

  bool Pop(Entry& e) {
    if (!overflow_.empty()) {
      e = overflow_.back();
      overflow_.pop_back();
      return true;
    }
    if (top_ == 0) return false;
    e = inline_[--top_];
    return true;
  }

  Entry inline_[kInline];
  std::vector<Entry> overflow_;
  int top_ = 0;
};

// The query: closest or any hit, whether alpha is tested (with the ray's key), and
// whether the walk counts its box tests (into *boxTests).
template <bool kAnyHit, bool kAlpha, bool kCount = false>
struct Query {
  const RenderScene& scene;
  uint32_t alphaKey;
  uint32_t* boxTests = nullptr;

  // Whether the ray passes through the hit (b1, b2) of leaf-order triangle i.
  bool Rejects(uint32_t i, float b1, float b2) const {
    if (!kAlpha) return false;
    const shader::Triangle& tri = scene.triangles[i];
    return shader::AlphaRejects(scene, tri.material, tri.sourceIndex, b1, b2, alphaKey);
  }
};

// Tests the triangles of leaf `code`, lanes in order, each against the closest hit so far
// (the scalar loop's result), narrowing tMax. True when an any-hit query has its hit.
template <bool kAnyHit, bool kAlpha, bool kCount>
bool TestLeaf(const Query<kAnyHit, kAlpha, kCount>& q, uint32_t code, const RaySlabs& slabs, float& tMax, Hit& hit) {
  const HugeVector<TrianglePacket>& packets = q.scene.wideLayout.packets;
  for (uint32_t k = code >> 4, e = k + ((code & 15u) + 3) / 4; k < e; ++k) {
    Float4 t, b1, b2;
    const int mask = IntersectPacket(packets[k], slabs, tMax, t, b1, b2);
    for (int lane = 0; lane < 4; ++lane) {
      if (!(mask >> lane & 1) || !(t[lane] < tMax)) continue;
      if (q.Rejects(packets[k].index[lane], b1[lane], b2[lane])) continue;
      hit = {t[lane], b1[lane], b2[lane], packets[k].index[lane]};
      if (kAnyHit) return true;
      tMax = t[lane];
    }
  }
  return false;
}

// Asks for the first four cache lines of child `code` — a whole node, or a leaf's first
// packet — as soon as its box is hit, nearest child included, so that its loads overlap
// the ordering of its siblings and the walk of nearer subtrees (as Embree's BVH8 walk
// does; docs/design-notes.md, "CPU prefetch").
inline void Prefetch(const RenderScene& scene, uint32_t code) {
  const char* p = IsLeafCode(code) ? reinterpret_cast<const char*>(&scene.wideLayout.packets[code >> 4])
                                   : reinterpret_cast<const char*>(&scene.wideLayout.nodes[code >> 4]);
  for (int line = 0; line < 4; ++line) __builtin_prefetch(p + 64 * line);
}

// The ordered walk over the wide nodes: a node's boxes at once, the nearest child
// hit entered next, the others deferred, nearer ones on top.
template <bool kAnyHit, bool kAlpha, bool kCount>
Hit Traverse(const Query<kAnyHit, kAlpha, kCount>& q, glm::vec3 origin, glm::vec3 dir, float tMax) {
  const RenderScene& scene = q.scene;
  Hit hit{-1.0f, 0.0f, 0.0f, shader::kInvalidIndex};
  const HugeVector<BvhWideNode>& nodes = scene.wideLayout.nodes;
  const RaySlabs slabs = MakeSlabs(origin, dir);
  DeferredStack deferred;
  // The root's own box is not tested: its children's boxes cull as well. A single-leaf
  // tree has no nodes; its leaf is the whole walk.
  uint32_t code = scene.wideLayout.rootLeaf;
  for (;;) {
    if (IsLeafCode(code)) {
      if (TestLeaf(q, code, slabs, tMax, hit)) return hit;
    } else {
      const BvhWideNode& n = nodes[code >> 4];
      float tEnter[kBvhWidth];
      int mask = IntersectNode(n, slabs, tMax, tEnter);
      if constexpr (kCount) *q.boxTests += kBvhWidth;
      if (mask != 0) {
        // The children hit, sorted by entry distance (insertion sort of at most kBvhWidth).
        uint32_t kids[kBvhWidth];
        float ts[kBvhWidth];
        int count = 0;
        for (; mask != 0; mask &= mask - 1) {
          const int lane = __builtin_ctz(unsigned(mask));
          int k = count++;
          for (; k > 0 && ts[k - 1] > tEnter[lane]; --k) {
            kids[k] = kids[k - 1];
            ts[k] = ts[k - 1];
          }
          kids[k] = n.child[lane];
          ts[k] = tEnter[lane];
          Prefetch(scene, n.child[lane]);
        }
        for (int k = count - 1; k > 0; --k) deferred.Push(kids[k], ts[k]);  // revisited unless a closer hit culls it
        code = kids[0];
        continue;
      }
    }
    if (!deferred.PopInFront(tMax, code)) break;
  }
  return hit;
}

// The queries of cpu/traversal.h.
struct Walk {
  static Hit IntersectClosest(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
    return Traverse(Query<false, false>{scene, 0u}, origin, dir, tMax);
  }

  static bool Occluded(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax) {
    return Traverse(Query<true, false>{scene, 0u}, origin, dir, tMax).t >= 0.0f;
  }

  static Hit IntersectClosestAlpha(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax,
                                   uint32_t alphaKey) {
    return Traverse(Query<false, true>{scene, alphaKey}, origin, dir, tMax);
  }

  static bool OccludedAlpha(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, float tMax, uint32_t alphaKey) {
    return Traverse(Query<true, true>{scene, alphaKey}, origin, dir, tMax).t >= 0.0f;
  }

  static Hit IntersectClosestCounted(const RenderScene& scene, glm::vec3 origin, glm::vec3 dir, uint32_t alphaKey,
                                     uint32_t& boxTests) {
    const float tMax = shader::kInfinity;
    return scene.alphaTested ? Traverse(Query<false, true, true>{scene, alphaKey, &boxTests}, origin, dir, tMax)
                             : Traverse(Query<false, false, true>{scene, 0u, &boxTests}, origin, dir, tMax);
  }
};
