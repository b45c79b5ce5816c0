// The kinds of value an option of `vkpt` takes (app/option_table.h): each gives the text
// of the values it accepts, the setter that checks and stores a value in Options, and the
// option's value in the "options" object of --stats. The text and the check come from
// the same range or list, so the docs cannot promise what the parser refuses.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/options.h"
#include "vkpt/settings_schema.h"

namespace vkpt::internal {

// What was given for an option: its name as written and its values (none for a flag).
struct GivenOption {
  const std::string& name;
  const std::vector<std::string>& values;
  const std::string& value() const { return values.at(0); }
};

struct OptionValue {
  std::string accepts;  // "[1, 16384]", "≥ 0", "`auto`, `cpu`"; empty: anything (or a flag)
  std::function<void(Options&, const GivenOption&)> set;  // throws UsageError
  std::function<std::string(const Options&)> json;        // the --stats value; null: none
};

// The range of the library's setting `key` (vkpt/settings_schema.h): the option refuses
// what the library refuses.
Range SettingRange(const std::string& key);
// T is uint32_t, float or double; the error names `opt` and says what was wrong.
template <class T>
T ParseNumber(const std::string& opt, const std::string& text, const Range& r);

// Where an option keeps its value: a member of Options (Own) or of the library's settings
// in Options::api (Api: the part of ApiSettings, then the member).
template <class T>
struct Field {
  std::function<T&(Options&)> at;
  T& operator()(Options& o) const { return at(o); }
  const T& operator()(const Options& o) const { return at(const_cast<Options&>(o)); }
};
template <class T>
Field<T> Own(T Options::*member) {
  return {[member](Options& o) -> T& { return o.*member; }};
}
template <class Part, class T>
Field<T> Api(Part ApiSettings::*part, T Part::*member) {
  return {[part, member](Options& o) -> T& { return o.api.*part.*member; }};
}

// A value as --stats writes it: a number, true/false, a string, null for an absent one.
std::string JsonValue(uint32_t v);
std::string JsonValue(const std::optional<uint32_t>& v);
std::string JsonValue(double v);
std::string JsonValue(const std::optional<double>& v);
std::string JsonValue(float v);
std::string JsonValue(const std::optional<float>& v);
std::string JsonValue(bool v);
std::string JsonValue(const std::string& v);
std::string JsonValue(const std::optional<std::array<float, 3>>& v);

template <class T>
std::function<std::string(const Options&)> JsonOf(Field<T> field) {
  return [field](const Options& o) { return JsonValue(field(o)); };
}

// A number in `range` stored in `field` (plain or optional).
template <class T>
OptionValue Number(Field<T> field, Range range) {
  return {RangeText(range),
          [field, range](Options& o, const GivenOption& g) {
            field(o) = ParseNumber<typename ValueOf<T>::type>(g.name, g.value(), range);
          },
          JsonOf(field)};
}

// The text of one of `names`, listed as the docs show them and the error says them.
std::string ChoicesText(const std::vector<std::string>& names);
[[noreturn]] void ThrowNotAChoice(const GivenOption& g, const std::vector<std::string>& names);

// One of the named values of `field`, its name in the stats.
template <class E>
OptionValue Choice(Field<E> field, std::vector<std::pair<std::string, E>> choices) {
  std::vector<std::string> names;
  for (const auto& [name, value] : choices) names.push_back(name);
  return {ChoicesText(names),
          [field, choices, names](Options& o, const GivenOption& g) {
            for (const auto& [name, value] : choices)
              if (name == g.value()) return void(field(o) = value);
            ThrowNotAChoice(g, names);
          },
          [field, choices](const Options& o) {
            for (const auto& [name, value] : choices)
              if (value == field(o)) return "\"" + name + "\"";
            return std::string("null");
          }};
}

OptionValue Flag(Field<bool> field);  // sets it true; false in the stats when absent
// Any text (`needs` null), or a non-empty one: `needs` completes "--opt needs ..." if empty.
OptionValue Text(Field<std::string> field, const char* needs = nullptr);
OptionValue NoStats(OptionValue v);  // the option leaves no value in the stats

// The values of the options whose values are of their own kind (option_values.cpp).
OptionValue OutValue();
OptionValue SppValue();
OptionValue AdaptiveValue(bool on);
OptionValue CheckpointValue();
OptionValue DiffValue();
OptionValue BackgroundValue();
// X,Y,Z: a point or direction in scene units.
OptionValue PointValue(Field<std::optional<std::array<float, 3>>> field, const std::string& key);
OptionValue AovValue();
OptionValue FramesValue();  // FIRST:LAST[:STEP]
OptionValue MaxMemoryValue();
OptionValue MaxTexelsValue();
OptionValue AllowExternalUrisValue();

}  // namespace vkpt::internal
