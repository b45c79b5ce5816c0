#include "session/aov.h"

#include <algorithm>

namespace vkpt::internal {

bool NeedsAovPass(Aov aov) { return aov != Aov::kVariance && aov != Aov::kSpp; }

bool NeedsAovPass(const std::vector<Aov>& aovs) {
  return std::any_of(aovs.begin(), aovs.end(), [](Aov aov) { return NeedsAovPass(aov); });
}

uint32_t AovChannels(const std::vector<Aov>& aovs) {
  uint32_t n = 0;
  for (Aov aov : aovs) n += uint32_t(AovSuffixes(aov).size());
  return n;
}

std::vector<AovLayer> ResolveAovs(const std::vector<Aov>& wanted, const AovSums& aovSums, const FrameSums& sums,
                                  const Image& image, const TriangleIdsOf& idsOf) {
  const size_t pixels = size_t(image.width) * image.height;
  std::vector<AovLayer> layers;
  for (Aov aov : wanted) {
    AovLayer layer{aov, AovSuffixes(aov), {}};
    layer.values.reserve(pixels * layer.suffixes.size());
    auto put = [&layer](glm::vec3 v) { layer.values.insert(layer.values.end(), {v.x, v.y, v.z}); };
    // Which of the triangle's ids the layer holds, an exact float (scene/scene_ids.h's
    // CheckIdsAreExact is asked before the render).
    const size_t which = aov == Aov::kObjectId ? 0 : aov == Aov::kMaterialId ? 1 : 2;
    auto putId = [&](uint32_t triangle) { layer.values.push_back(float(idsOf(triangle)[which])); };
    for (size_t i = 0; i < pixels; ++i) {
      const AovPixel a = NeedsAovPass(aov) ? ResolveAovPixel(aovSums.pixels.at(i), aovSums.samples) : AovPixel{};
      switch (aov) {
        case Aov::kAlbedo: put(a.albedo); break;
        case Aov::kNormal: put(a.normal); break;
        case Aov::kDepth: layer.values.push_back(a.depth); break;
        case Aov::kPosition: put(a.position); break;
        case Aov::kVariance: put(image.variance.empty() ? glm::vec3(0.0f) : image.variance[i]); break;
        case Aov::kSpp: layer.values.push_back(float(sums.pixels.at(i).samples)); break;
        case Aov::kHeatmap: layer.values.push_back(a.boxTests); break;
        case Aov::kObjectId:
        case Aov::kMaterialId:
        case Aov::kInstanceId: putId(aovSums.pixels.at(i).triangle); break;
      }
    }
    layers.push_back(std::move(layer));
  }
  return layers;
}

}  // namespace vkpt::internal
