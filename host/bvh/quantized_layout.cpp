#include "bvh/quantized_layout.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "bvh/bvh.h"
#include "bvh/collapse.h"
#include "util/bounds.h"
#include "util/error.h"

namespace vkpt::internal {
namespace {

float Cell(uint32_t biasedExponent) { return std::bit_cast<float>(biasedExponent << 23); }

// The smallest power-of-two cell (biased exponent 1–254) whose 255 steps from `lo`
// reach `hi`, computed as the shader computes a plane: lo + cell · q, one rounding of an
// exact product, so that monotonic rounding keeps every plane on the safe side.
uint32_t GridExponent(float lo, float hi) {
  uint32_t e = 1;
  if (hi > lo) {
    int exp2 = 0;
    std::frexp((hi - lo) / 255.0f, &exp2);  // (hi − lo) / 255 < 2^exp2
    e = uint32_t(std::clamp(exp2 - 1 + 127, 1, 254));
  }
  while (e > 1 && lo + Cell(e - 1) * 255.0f >= hi) --e;
  while (e < 254 && lo + Cell(e) * 255.0f < hi) ++e;
  return e;
}

// The largest q with lo + cell·q ≤ x, and the smallest with lo + cell·q ≥ x.
uint32_t QuantizeDown(float lo, float cell, float x) {
  float q = std::clamp(std::floor((x - lo) / cell), 0.0f, 255.0f);
  while (q > 0.0f && lo + cell * q > x) q -= 1.0f;
  return uint32_t(q);
}
uint32_t QuantizeUp(float lo, float cell, float x) {
  float q = std::clamp(std::ceil((x - lo) / cell), 0.0f, 255.0f);
  while (q < 255.0f && lo + cell * q < x) q += 1.0f;
  return uint32_t(q);
}

// The order in which rays whose direction has the signs of octant o (bit 0: x < 0,
// bit 1: y < 0, bit 2: z < 0) should enter the children, near first: by their centres
// projected on that octant's diagonal; unused slots last.
void NearFirst(const Bounds3f* boxes, int count, uint32_t octant, int* slots) {
  const glm::vec3 diagonal((octant & 1u) ? -1.0f : 1.0f, (octant & 2u) ? -1.0f : 1.0f, (octant & 4u) ? -1.0f : 1.0f);
  float key[kGpuBvhWidth];
  for (int k = 0; k < kGpuBvhWidth; ++k) {
    slots[k] = k;
    key[k] = k < count ? glm::dot(boxes[k].lo + boxes[k].hi, diagonal) : INFINITY;
  }
  std::stable_sort(slots, slots + kGpuBvhWidth, [&](int a, int b) { return key[a] < key[b]; });
}

shader::WideBvhNode MakeNode(const Bounds3f* boxes, const uint32_t* codes, int count, uint32_t parent, uint32_t slot) {
  Bounds3f box;
  for (int k = 0; k < count; ++k) box.Extend(boxes[k]);
  shader::WideBvhNode n{};
  n.origin = box.lo;
  n.lo.w = parent;
  n.exponents = slot << 24;
  for (int axis = 0; axis < 3; ++axis) {
    const uint32_t e = GridExponent(box.lo[axis], box.hi[axis]);
    const float cell = Cell(e);
    n.exponents |= e << (8 * axis);
    for (int k = 0; k < count; ++k) {
      n.lo[axis] |= QuantizeDown(box.lo[axis], cell, boxes[k].lo[axis]) << (8 * k);
      n.hi[axis] |= QuantizeUp(box.lo[axis], cell, boxes[k].hi[axis]) << (8 * k);
    }
  }
  for (int k = 0; k < count; ++k) n.child[k] = codes[k];
  return n;
}

// The wide tree's shape: per wide node its children (binary nodes), its parent and its
// slot there, and the wide node of each inner child.
struct Shape {
  CollapsedChildren<kGpuBvhWidth> kids;
  uint32_t parent, slot;
  uint32_t inner[kGpuBvhWidth];
};

// Depth first, a node's first inner child right after it in memory.
std::vector<Shape> WideShape(std::span<const shader::BvhNode> nodes, uint32_t copies) {
  std::vector<Shape> shape;
  if (IsLeaf(nodes[0])) {
    Shape root{};
    root.kids.node[0] = 0;
    root.kids.count = 1;
    root.parent = shader::kInvalidIndex;
    shape.push_back(root);
    return shape;
  }
  // Each entry: a binary inner node, the wide node that points to it and its slot there.
  struct Pending {
    uint32_t binary, parent, slot;
  };
  std::vector<Pending> stack = {{0, shader::kInvalidIndex, 0}};
  while (!stack.empty()) {
    const Pending e = stack.back();
    stack.pop_back();
    const uint32_t index = uint32_t(shape.size());
    if (uint64_t(index) * copies >= (1u << 28))
      throw Error("BuildQuantizedLayout: too many nodes for the 28-bit index");
    if (e.parent != shader::kInvalidIndex) shape[e.parent].inner[e.slot] = index;
    Shape s{};
    s.kids = CollapseChildren<kGpuBvhWidth>(nodes, e.binary);
    s.parent = e.parent;
    s.slot = e.slot;
    shape.push_back(s);
    for (int k = s.kids.count - 1; k >= 0; --k)
      if (!IsLeaf(nodes[s.kids.node[k]])) stack.push_back({s.kids.node[k], index, uint32_t(k)});
  }
  return shape;
}

}  // namespace

QuantizedBox ChildBox(const shader::WideBvhNode& node, int k) {
  QuantizedBox b;
  for (int axis = 0; axis < 3; ++axis) {
    const float cell = Cell((node.exponents >> (8 * axis)) & 0xFFu);
    b.lo[axis] = node.origin[axis] + cell * float((node.lo[axis] >> (8 * k)) & 0xFFu);
    b.hi[axis] = node.origin[axis] + cell * float((node.hi[axis] >> (8 * k)) & 0xFFu);
  }
  return b;
}

std::vector<shader::WideBvhNode> BuildQuantizedLayout(std::span<const shader::BvhNode> nodes, uint32_t nodeCount,
                                                      uint32_t copies) {
  if (nodeCount == 0 || nodes.size() < nodeCount) throw Error("BuildQuantizedLayout: no tree to convert");
  if (copies != 1 && copies != 8) throw Error("BuildQuantizedLayout: 1 or 8 copies");
  const std::vector<Shape> shape = WideShape(nodes, copies);
  // Copy o: every node's children in octant o's order (for one copy, octant 0's).
  const uint32_t count = uint32_t(shape.size());
  std::vector<shader::WideBvhNode> out(size_t(count) * copies);
  // rankOf: each node's canonical slot → its slot in this copy. Parents come before their
  // children, so a child finds its parent's entry set.
  std::vector<uint8_t> rankOf(size_t(count) * kGpuBvhWidth);
  for (uint32_t o = 0; o < copies; ++o) {
    const uint32_t base = o * count;
    for (uint32_t i = 0; i < count; ++i) {
      const Shape& s = shape[i];
      Bounds3f canonical[kGpuBvhWidth];
      for (int k = 0; k < s.kids.count; ++k)
        canonical[k] = Bounds3f{nodes[s.kids.node[k]].lo, nodes[s.kids.node[k]].hi};
      int slots[kGpuBvhWidth];
      NearFirst(canonical, s.kids.count, o, slots);
      Bounds3f boxes[kGpuBvhWidth];
      uint32_t codes[kGpuBvhWidth] = {};
      for (int r = 0; r < kGpuBvhWidth; ++r) {
        const int k = slots[r];
        rankOf[size_t(i) * kGpuBvhWidth + k] = uint8_t(r);
        if (k >= s.kids.count) continue;
        const shader::BvhNode& c = nodes[s.kids.node[k]];
        boxes[r] = canonical[k];
        codes[r] = IsLeaf(c) ? c.leaf : (base + s.inner[k]) << 4;
      }
      const bool root = s.parent == shader::kInvalidIndex;
      out[base + i] = MakeNode(boxes, codes, s.kids.count, root ? shader::kInvalidIndex : base + s.parent,
                               root ? 0u : rankOf[size_t(s.parent) * kGpuBvhWidth + s.slot]);
    }
  }
  return out;
}

}  // namespace vkpt::internal
