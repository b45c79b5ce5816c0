#include "app/option_values.h"

#include <algorithm>
#include <array>
#include <charconv>

#include "app/json_object.h"
#include "image/aov_layer.h"
#include "util/byte_size.h"
#include "util/error.h"
#include "vkpt/setting_choices.h"

namespace vkpt::internal {

Range SettingRange(const std::string& key) { return *SettingOf(key).range; }

template <class T>
T ParseNumber(const std::string& opt, const std::string& text, const Range& r) {
  T v{};
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw UsageError(opt + " expects a number, got \"" + text + "\"");
  const double d = double(v);
  if (!r.Holds(d)) throw UsageError(OutOfRange(opt, r, d, text));
  return v;
}

template uint32_t ParseNumber<uint32_t>(const std::string&, const std::string&, const Range&);
template float ParseNumber<float>(const std::string&, const std::string&, const Range&);
template double ParseNumber<double>(const std::string&, const std::string&, const Range&);

namespace {

std::string Null() { return "null"; }

// The comma-separated parts of `text` ("a,,b": "a", "", "b").
std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

}  // namespace

std::string JsonValue(uint32_t v) { return std::to_string(v); }
std::string JsonValue(const std::optional<uint32_t>& v) { return v ? std::to_string(*v) : Null(); }
std::string JsonValue(double v) { return JsonNumber(v); }
std::string JsonValue(const std::optional<double>& v) { return v ? JsonNumber(*v) : Null(); }
std::string JsonValue(float v) { return JsonNumber(v); }
std::string JsonValue(const std::optional<float>& v) { return v ? JsonNumber(*v) : Null(); }
std::string JsonValue(bool v) { return v ? "true" : "false"; }
std::string JsonValue(const std::string& v) { return JsonString(v); }
std::string JsonValue(const std::optional<std::array<float, 3>>& v) {
  return v ? JsonArray({JsonNumber((*v)[0]), JsonNumber((*v)[1]), JsonNumber((*v)[2])}) : Null();
}

std::string ChoicesText(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "`" : ", `") + name + "`";
  return text;
}

void ThrowNotAChoice(const GivenOption& g, const std::vector<std::string>& names) {
  throw UsageError(g.name + " must be " + OrList(names) + ", got \"" + g.value() + "\"");
}

OptionValue Flag(Field<bool> f) {
  return {"", [f](Options& o, const GivenOption&) { f(o) = true; }, JsonOf(f)};
}

OptionValue Text(Field<std::string> f, const char* needs) {
  return {"",
          [f, needs](Options& o, const GivenOption& g) {
            if (needs && g.value().empty()) throw UsageError(g.name + " needs " + needs);
            f(o) = g.value();
          },
          JsonOf(f)};
}

OptionValue NoStats(OptionValue v) {
  v.json = nullptr;
  return v;
}

OptionValue OutValue() {
  return {"", [](Options& o, const GivenOption& g) { o.out = o.outGiven = g.value(); }, JsonOf(Own(&Options::out))};
}

// --stats shows the bound the render takes, given or derived.
OptionValue SppValue() {
  OptionValue v = Number(Api(&ApiSettings::render, &vkpt::RenderOptions::spp), SettingRange("spp"));
  v.json = [](const Options& o) { return std::to_string(o.Budget().spp); };
  return v;
}

OptionValue AdaptiveValue(bool on) {
  OptionValue v{"", [on](Options& o, const GivenOption&) { o.api.render.adaptive = on; }, nullptr};
  if (on) v.json = [](const Options& o) { return std::string(o.Budget().adaptive ? "true" : "false"); };
  return v;
}

OptionValue CheckpointValue() {
  OptionValue v = Number(Own(&Options::checkpoint), {1e-3, 1e7});
  v.json = [](const Options& o) { return o.checkpoint > 0.0 ? JsonNumber(o.checkpoint) : Null(); };
  return v;
}

OptionValue DiffValue() {
  return {"", [](Options& o, const GivenOption& g) { o.diff = g.values; }, nullptr};
}

OptionValue BackgroundValue() {
  const Range range = SettingRange("background");
  auto set = [range](Options& o, const GivenOption& g) {
    const std::vector<std::string> parts = SplitCommas(g.value());
    if (parts.size() != 1 && parts.size() != 3)
      throw UsageError(g.name + " expects R,G,B or one number, got \"" + g.value() + "\"");
    std::array<float, 3> c{};
    for (size_t k = 0; k < 3; ++k) c[k] = ParseNumber<float>(g.name, parts[parts.size() == 1 ? 0 : k], range);
    o.api.render.background = c;
  };
  return {"each " + RangeText(range), set, JsonOf(Api(&ApiSettings::render, &vkpt::RenderOptions::background))};
}

OptionValue PointValue(Field<std::optional<std::array<float, 3>>> field, const std::string& key) {
  const Range range = SettingRange(key);
  auto set = [field, range](Options& o, const GivenOption& g) {
    const std::vector<std::string> parts = SplitCommas(g.value());
    if (parts.size() != 3) throw UsageError(g.name + " expects X,Y,Z, got \"" + g.value() + "\"");
    std::array<float, 3> p{};
    for (size_t k = 0; k < 3; ++k) p[k] = ParseNumber<float>(g.name, parts[k], range);
    field(o) = p;
  };
  return {"three numbers, each " + RangeText(range), set, JsonOf(field)};
}

OptionValue AovValue() {
  std::vector<std::string> names;
  for (int k = 0; k < kAovCount; ++k) names.push_back(AovName(Aov(k)));
  names.push_back("all");
  auto set = [](Options& o, const GivenOption& g) {
    try {
      o.api.render.aovs.clear();
      for (Aov aov : AovsFromNames(SplitCommas(g.value()))) o.api.render.aovs.emplace_back(AovName(aov));
    } catch (const Error& e) {
      throw UsageError(g.name + ": " + e.what());
    }
  };
  auto json = [](const Options& o) {
    std::vector<std::string> aovs;
    for (const std::string& aov : o.api.render.aovs) aovs.push_back(JsonString(aov));
    return JsonArray(aovs);
  };
  return {ChoicesText(names) + ", comma-separated", set, json};
}

OptionValue MaxMemoryValue() {
  auto set = [](Options& o, const GivenOption& g) {
    std::optional<uint64_t> bytes = ParseByteSize(g.value());
    if (!bytes || *bytes < (uint64_t(1) << 20))
      throw UsageError(g.name + " expects a size of at least 1M (bytes, or with K, M, G or T), got \"" + g.value() +
                       "\"");
    o.api.scene.maxMemory = *bytes;
  };
  return {"≥ 1M", set, [](const Options& o) { return std::to_string(o.api.scene.maxMemory); }};
}

OptionValue MaxTexelsValue() {
  const Range range = SettingRange("max_texels");
  auto set = [range](Options& o, const GivenOption& g) {
    std::optional<uint64_t> texels = ParseByteSize(g.value());
    if (!texels) throw UsageError(g.name + " expects a count (a number, or with K, M or G), got \"" + g.value() + "\"");
    if (!range.Holds(double(*texels))) throw UsageError(OutOfRange(g.name, range, double(*texels), g.value()));
    o.api.scene.maxTexels = *texels;
  };
  return {RangeText(range) + " (0: 256M)", set, [](const Options& o) { return std::to_string(o.api.scene.maxTexels); }};
}

OptionValue AllowExternalUrisValue() {
  return {"", [](Options& o, const GivenOption&) { o.api.scene.allowExternalUris = true; },
          [](const Options& o) { return std::string(o.api.scene.allowExternalUris ? "true" : "false"); }};
}

OptionValue FramesValue() {
  const Range numbers{0, 999999}, steps{1, 999999};
  auto set = [numbers, steps](Options& o, const GivenOption& g) {
    std::vector<std::string> parts;
    for (size_t start = 0;;) {
      const size_t colon = g.value().find(':', start);
      parts.push_back(g.value().substr(start, colon == std::string::npos ? std::string::npos : colon - start));
      if (colon == std::string::npos) break;
      start = colon + 1;
    }
    if (parts.size() != 2 && parts.size() != 3)
      throw UsageError(g.name + " expects FIRST:LAST[:STEP], got \"" + g.value() + "\"");
    FrameRange f;
    f.first = ParseNumber<uint32_t>(g.name, parts[0], numbers);
    f.last = ParseNumber<uint32_t>(g.name, parts[1], numbers);
    if (parts.size() == 3) f.step = ParseNumber<uint32_t>(g.name, parts[2], steps);
    if (f.last < f.first)
      throw UsageError(g.name + ": the last frame, " + parts[1] + ", comes before the first, " + parts[0]);
    o.frames = f;
  };
  auto json = [](const Options& o) {
    if (!o.frames) return std::string("null");
    // Appended piece by piece: GCC 12 warns falsely on "[" + std::string (bug 105651).
    std::string list = "[";
    list += std::to_string(o.frames->first) + ", ";
    list += std::to_string(o.frames->last) + ", ";
    list += std::to_string(o.frames->step) + "]";
    return list;
  };
  return {"FIRST ≤ LAST in " + RangeText(numbers) + ", STEP ≥ 1", set, json};
}

}  // namespace vkpt::internal
