#include "image/aov_layer.h"

#include <algorithm>
#include <array>

#include "util/error.h"

namespace vkpt::internal {
namespace {

constexpr std::array<const char*, kAovCount> kNames = {"albedo", "normal",  "depth",     "position",    "variance",
                                                       "spp",    "heatmap", "object_id", "material_id", "instance_id"};

// "albedo, normal, … heatmap or all".
std::string KnownNames() {
  std::string list;
  for (const char* name : kNames) list += std::string(name) + ", ";
  list.resize(list.size() - 2);
  return list + " or all";
}

}  // namespace

const char* AovName(Aov aov) { return kNames[size_t(aov)]; }

std::optional<Aov> AovFromName(std::string_view name) {
  for (int k = 0; k < kAovCount; ++k)
    if (name == kNames[k]) return Aov(k);
  return std::nullopt;
}

std::vector<Aov> AovsFromNames(const std::vector<std::string>& names) {
  std::vector<Aov> aovs;
  auto add = [&aovs](Aov aov) {
    if (std::find(aovs.begin(), aovs.end(), aov) == aovs.end()) aovs.push_back(aov);
  };
  for (const std::string& name : names) {
    if (name == "all") {
      for (int k = 0; k < kAovCount; ++k) add(Aov(k));
    } else if (const std::optional<Aov> aov = AovFromName(name)) {
      add(*aov);
    } else {
      throw Error("unknown AOV \"" + name + "\" (" + KnownNames() + ")");
    }
  }
  return aovs;
}

bool IsIdAov(Aov aov) { return aov == Aov::kObjectId || aov == Aov::kMaterialId || aov == Aov::kInstanceId; }

bool WantsIds(const std::vector<Aov>& aovs) { return std::any_of(aovs.begin(), aovs.end(), IsIdAov); }

std::vector<std::string> AovSuffixes(Aov aov) {
  switch (aov) {
    case Aov::kAlbedo:
    case Aov::kVariance: return {"R", "G", "B"};
    case Aov::kNormal:
    case Aov::kPosition: return {"X", "Y", "Z"};
    case Aov::kDepth: return {"Z"};
    case Aov::kObjectId:
    case Aov::kMaterialId:
    case Aov::kInstanceId: return {"ID"};
    default: return {"Y"};
  }
}

}  // namespace vkpt::internal
