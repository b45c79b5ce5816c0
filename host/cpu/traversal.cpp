#include "cpu/traversal.h"

#include "bvh/bvh.h"
#include "shared/intersect.h"

namespace vkpt {
namespace {

// Depth of the explicit stack. The builder bounds nothing about depth, so the stack
// grows on the heap past this (pathological trees only).
constexpr int kInlineStack = 64;

template <bool kAnyHit>
Hit Traverse(const std::vector<shader::BvhNode>& nodes, const std::vector<shader::Triangle>& tris,
             glm::vec3 origin, glm::vec3 dir, float tMax, TraversalCounters* counters) {
  using shader::IntersectBox;
  using shader::IntersectTriangle;
  Hit hit{-1.0f, 0.0f, 0.0f, shader::kInvalidIndex};
  const glm::vec3 inv = shader::SafeInverse(dir);
  // Deferred far children with their entry distances: a popped entry beyond the closest
  // hit found since is dropped without testing its box again.
  struct Entry {
    uint32_t node;
    float tEnter;
  };
  Entry inlineStack[kInlineStack];
  std::vector<Entry> overflow;
  int top = 0;
  auto push = [&](Entry e) {
    if (top < kInlineStack) inlineStack[top++] = e;
    else overflow.push_back(e);
  };
  auto pop = [&](Entry& e) {
    if (!overflow.empty()) { e = overflow.back(); overflow.pop_back(); return true; }
    if (top == 0) return false;
    e = inlineStack[--top];
    return true;
  };

  uint64_t visited = 0, tested = 0;
  uint32_t n = 0;
  if (IntersectBox(nodes[0].lo, nodes[0].hi, origin, inv, tMax) < 0.0f) return hit;
  for (;;) {
    const shader::BvhNode& node = nodes[n];
    ++visited;
    if (IsLeaf(node)) {
      for (uint32_t i = LeafFirst(node), e = i + LeafCount(node); i < e; ++i) {
        ++tested;
        const shader::Triangle& t = tris[i];
        glm::vec3 r = IntersectTriangle(t.v0, t.e1, t.e2, origin, dir, tMax);
        if (r.x >= 0.0f) {
          hit = {r.x, r.y, r.z, i};
          if (kAnyHit) goto done;
          tMax = r.x;
        }
      }
    } else {
      uint32_t a = FirstChild(n), b = SecondChild(nodes, n);
      float ta = IntersectBox(nodes[a].lo, nodes[a].hi, origin, inv, tMax);
      float tb = IntersectBox(nodes[b].lo, nodes[b].hi, origin, inv, tMax);
      if (ta >= 0.0f && tb >= 0.0f) {
        if (tb < ta) {
          std::swap(a, b);
          std::swap(ta, tb);
        }
        push({b, tb});  // farther child: revisited later unless a closer hit culls it
        n = a;
        continue;
      }
      if (ta >= 0.0f) { n = a; continue; }
      if (tb >= 0.0f) { n = b; continue; }
    }
    // Pop until an entry still in front of the closest hit. The box test's exit slack
    // (1 + 2γ₃) is applied to tMax so culling stays as conservative as the test itself.
    Entry e;
    bool found = false;
    while (pop(e)) {
      if (e.tEnter <= tMax * 1.0000004f) { found = true; break; }
    }
    if (!found) break;
    n = e.node;
  }
done:
  if (counters) {
    counters->nodesVisited += visited;
    counters->trianglesTested += tested;
  }
  return hit;
}

}  // namespace

Hit IntersectClosest(const std::vector<shader::BvhNode>& nodes, const std::vector<shader::Triangle>& triangles,
                     glm::vec3 origin, glm::vec3 dir, float tMax, TraversalCounters* counters) {
  return Traverse<false>(nodes, triangles, origin, dir, tMax, counters);
}

bool Occluded(const std::vector<shader::BvhNode>& nodes, const std::vector<shader::Triangle>& triangles,
              glm::vec3 origin, glm::vec3 dir, float tMax) {
  return Traverse<true>(nodes, triangles, origin, dir, tMax, nullptr).t >= 0.0f;
}

}  // namespace vkpt
