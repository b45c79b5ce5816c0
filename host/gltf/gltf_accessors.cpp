#include "gltf/gltf_accessors.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

namespace vkpt::internal {
namespace {

// Checks that a (bufferView, byteOffset) region holds `count` elements of elemSize
// bytes at stride `stride`.
void CheckRegion(const GltfSource& src, const std::string& name, int bufferView, size_t byteOffset, size_t count,
                 size_t elemSize, size_t stride) {
  src.CheckIndex(bufferView, src.m.bufferViews, name + ".bufferView");
  const tinygltf::BufferView& bv = src.m.bufferViews[bufferView];
  if (count == 0) return;
  // Computed in a wide type: count comes from the file and may be absurd.
  long double end = (long double)byteOffset + (long double)stride * (count - 1) + elemSize;
  if (end > (long double)bv.byteLength)
    src.Fail(name + " needs " + std::to_string((unsigned long long)end) + " bytes of bufferViews[" +
             std::to_string(bufferView) + "], which has " + std::to_string(bv.byteLength));
}

// One integer component; normalized, it maps to [0, 1] (unsigned) or [-1, 1] (signed,
// the most negative value clamped) as the glTF spec defines (§3.11, "Animations").
template <class T>
double ReadInteger(const unsigned char* p, bool normalized) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return normalized ? std::max(double(v) / double(std::numeric_limits<T>::max()), -1.0) : double(v);
}

double ReadComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return ReadInteger<int8_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return ReadInteger<uint8_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return ReadInteger<int16_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return ReadInteger<uint16_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return ReadInteger<uint32_t>(p, normalized);
    default: {
      float v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
  }
}

const unsigned char* RegionBase(const GltfSource& src, int bufferView, size_t byteOffset) {
  const tinygltf::BufferView& bv = src.m.bufferViews[bufferView];
  return src.m.buffers[bv.buffer].data.data() + bv.byteOffset + byteOffset;
}

}  // namespace

int ComponentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int ComponentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

size_t ElementSize(const tinygltf::Accessor& a) {
  return size_t(ComponentSize(a.componentType)) * ComponentCount(a.type);
}

void CheckAccessor(const GltfSource& src, int index) {
  const tinygltf::Accessor& a = src.m.accessors[index];
  std::string name = "accessors[" + std::to_string(index) + "]";
  if (ComponentSize(a.componentType) == 0)
    src.Fail(name + ".componentType " + std::to_string(a.componentType) + " is not valid");
  if (ComponentCount(a.type) == 0) src.Fail(name + ".type is not valid");
  if (a.count == 0) src.Fail(name + ".count is 0");
  // Guards the allocation of an accessor without a bufferView (all zeros, or sparse).
  if (a.count > (size_t(1) << 28)) src.Fail(name + ".count " + std::to_string(a.count) + " is too large (limit 2^28)");
  size_t elem = ElementSize(a);
  if (a.bufferView >= 0) {
    src.CheckIndex(a.bufferView, src.m.bufferViews, name + ".bufferView");
    const tinygltf::BufferView& bv = src.m.bufferViews[a.bufferView];
    size_t stride = bv.byteStride ? bv.byteStride : elem;
    if (stride < elem)
      src.Fail(name + ": bufferViews[" + std::to_string(a.bufferView) + "].byteStride " + std::to_string(stride) +
               " is smaller than the element size " + std::to_string(elem));
    if (a.byteOffset % ComponentSize(a.componentType))
      src.Fail(name + ".byteOffset is not a multiple of its component size");
    CheckRegion(src, name, a.bufferView, a.byteOffset, a.count, elem, stride);
  } else if (a.byteOffset != 0) {
    src.Fail(name + " has a byteOffset but no bufferView");
  }
  if (a.sparse.isSparse) {
    const auto& s = a.sparse;
    if (s.count <= 0 || size_t(s.count) > a.count)
      src.Fail(name + ".sparse.count " + std::to_string(s.count) + " is not in [1, " + std::to_string(a.count) + "]");
    int isz = ComponentSize(s.indices.componentType);
    if (s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      src.Fail(name + ".sparse.indices.componentType is not an unsigned integer type");
    if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) src.Fail(name + ".sparse has a negative byteOffset");
    CheckRegion(src, name + ".sparse.indices", s.indices.bufferView, size_t(s.indices.byteOffset), size_t(s.count),
                size_t(isz), size_t(isz));
    CheckRegion(src, name + ".sparse.values", s.values.bufferView, size_t(s.values.byteOffset), size_t(s.count), elem,
                elem);
  }
}

std::vector<double> ReadAccessor(const GltfSource& src, int index) {
  const tinygltf::Accessor& a = src.m.accessors[index];
  const int n = ComponentCount(a.type);
  const int cs = ComponentSize(a.componentType);
  std::vector<double> out(a.count * n, 0.0);
  if (a.bufferView >= 0) {
    const tinygltf::BufferView& bv = src.m.bufferViews[a.bufferView];
    size_t stride = bv.byteStride ? bv.byteStride : ElementSize(a);
    const unsigned char* base = RegionBase(src, a.bufferView, a.byteOffset);
    for (size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < n; ++c)
        out[i * n + c] = ReadComponent(base + i * stride + c * cs, a.componentType, a.normalized);
  }
  if (a.sparse.isSparse) {
    const auto& s = a.sparse;
    const unsigned char* idx = RegionBase(src, s.indices.bufferView, size_t(s.indices.byteOffset));
    const unsigned char* val = RegionBase(src, s.values.bufferView, size_t(s.values.byteOffset));
    int isz = ComponentSize(s.indices.componentType);
    for (int k = 0; k < s.count; ++k) {
      double target = ReadComponent(idx + k * isz, s.indices.componentType, false);
      if (target >= double(a.count))
        src.Fail("accessors[" + std::to_string(index) + "].sparse index " + std::to_string((unsigned long long)target) +
                 " is out of range (count " + std::to_string(a.count) + ")");
      for (int c = 0; c < n; ++c)
        out[size_t(target) * n + c] = ReadComponent(val + (size_t(k) * n + c) * cs, a.componentType, a.normalized);
    }
  }
  return out;
}

}  // namespace vkpt::internal
