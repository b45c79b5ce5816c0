#include "gltf/gltf_variants.h"

#include <cctype>

namespace vkpt::internal {
namespace {

constexpr char kExtension[] = "KHR_materials_variants";

// A non-negative integer member `key` of `v`, checked against `count` entries.
int IndexIn(const GltfSource& src, const tinygltf::Value& v, const std::string& what, size_t count) {
  if (!v.IsInt() || v.GetNumberAsInt() < 0 || size_t(v.GetNumberAsInt()) >= count)
    src.Fail(what + " is not an index below " + std::to_string(count));
  return v.GetNumberAsInt();
}

}  // namespace

std::vector<std::string> ReadVariants(const GltfSource& src) {
  std::vector<std::string> names;
  auto ext = src.m.extensions.find(kExtension);
  if (ext == src.m.extensions.end()) return names;
  const std::string what = std::string("extensions.") + kExtension + ".variants";
  if (!ext->second.IsObject() || !ext->second.Has("variants") || !ext->second.Get("variants").IsArray())
    src.Fail(what + " is missing or not an array");
  const tinygltf::Value& list = ext->second.Get("variants");
  for (size_t i = 0; i < list.ArrayLen(); ++i) {
    const tinygltf::Value& v = list.Get(int(i));
    if (!v.IsObject() || !v.Has("name") || !v.Get("name").IsString())
      src.Fail(what + "[" + std::to_string(i) + "].name is missing or not a string");
    names.push_back(v.Get("name").Get<std::string>());
  }
  return names;
}

int ResolveVariant(const GltfSource& src, const std::vector<std::string>& variants, const std::string& wanted) {
  return src.Choose(variants, wanted, "--variant", "material variant", "no material variants (KHR_materials_variants)");
}

int VariantMaterial(const GltfSource& src, const tinygltf::Primitive& prim, int variant, size_t variantCount,
                    const std::string& what) {
  auto ext = prim.extensions.find(kExtension);
  if (ext == prim.extensions.end()) return -1;
  const std::string name = what + ".extensions." + kExtension + ".mappings";
  if (!ext->second.IsObject() || !ext->second.Has("mappings") || !ext->second.Get("mappings").IsArray())
    src.Fail(name + " is missing or not an array");
  const tinygltf::Value& mappings = ext->second.Get("mappings");
  int chosen = -1;
  for (size_t m = 0; m < mappings.ArrayLen(); ++m) {
    const tinygltf::Value& mapping = mappings.Get(int(m));
    const std::string at = name + "[" + std::to_string(m) + "]";
    if (!mapping.IsObject() || !mapping.Has("material") || !mapping.Has("variants") ||
        !mapping.Get("variants").IsArray())
      src.Fail(at + " needs a material and an array of variants");
    const int material = IndexIn(src, mapping.Get("material"), at + ".material", src.m.materials.size());
    const tinygltf::Value& variants = mapping.Get("variants");
    for (size_t k = 0; k < variants.ArrayLen(); ++k)
      if (IndexIn(src, variants.Get(int(k)), at + ".variants[" + std::to_string(k) + "]", variantCount) == variant &&
          chosen < 0)
        chosen = material;
  }
  return chosen;
}

}  // namespace vkpt::internal
