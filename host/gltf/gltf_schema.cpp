#include "gltf/gltf_schema.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <set>

#include "util/error.h"

namespace vkpt::internal {
namespace {

using nlohmann::json;

// Properties whose value is an index into a top-level array (glTF 2.0 schema,
// "glTFid"): they must be integers >= 0.
const std::set<std::string> kIdProperties = {
    "bufferView", "buffer",   "index",   "source", "sampler", "mesh",     "camera",
    "skin",       "material", "indices", "scene",  "node",    "skeleton", "inverseBindMatrices",
    "input",      "output"};
// Properties that must be arrays (of objects or of glTFids).
const std::set<std::string> kArrayProperties = {
    "accessors", "animations", "buffers",  "bufferViews", "cameras",  "images",         "materials",
    "meshes",    "nodes",      "samplers", "scenes",      "skins",    "textures",       "primitives",
    "children",  "joints",     "targets",  "channels",    "samplers", "extensionsUsed", "extensionsRequired"};
// Arrays whose elements are glTFids.
const std::set<std::string> kIdArrays = {"nodes", "children", "joints"};

// A JSON value as an error message shows it: scalars as written, containers and long
// strings by their size (a value can be megabytes long).
std::string Describe(const json& v) {
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + " elements";
  if (v.is_object()) return "an object";
  if (v.is_string() && v.get_ref<const std::string&>().size() > 40)
    return "a string of " + std::to_string(v.get_ref<const std::string&>().size()) + " characters";
  return v.dump();
}

// The deepest nesting of objects and arrays in a JSON text, outside strings.
int NestingDepth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      deepest = std::max(deepest, ++depth);
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return deepest;
}

// tinygltf keeps the numbers of extension objects as Values of `int` when they are
// integers: a larger one would wrap, so "count": 10000000000 would read as 1410065408.
void CheckExtensionInteger(const std::string& path, const json& v, const std::string& where) {
  if ((v.is_number_integer() && !v.is_number_unsigned() && v.get<long long>() < INT32_MIN) ||
      (v.is_number_unsigned() && v.get<unsigned long long>() > INT32_MAX))
    throw Error(path + ": " + where + " is " + v.dump() +
                ", beyond the 32-bit integers an extension's values may hold");
}

void Walk(const std::string& path, const json& j, const std::string& where, bool inExtras, bool inExtensions) {
  if (inExtensions && !inExtras) CheckExtensionInteger(path, j, where);
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      std::string at = where.empty() ? key : where + "." + key;
      // extras are free-form application data; attribute maps hold accessor ids.
      bool extras = inExtras || key == "extras";
      if (!extras) {
        if (kIdProperties.count(key) && !(value.is_number_integer() && value.get<long long>() >= 0) &&
            !value.is_object())  // "sampler"/"source" etc. are objects in some extensions
          throw Error(path + ": " + at + " must be a non-negative integer index, got " + Describe(value));
        if (kArrayProperties.count(key) && !value.is_array() && !(key == "samplers" && value.is_object()))
          throw Error(path + ": " + at + " must be an array, got " + Describe(value));
        bool idArray = kIdArrays.count(key) && value.is_array() && !value.empty() && !value[0].is_object();
        if (idArray)
          for (const json& id : value)
            if (!(id.is_number_integer() && id.get<long long>() >= 0))
              throw Error(path + ": " + at + " must hold non-negative integer indices, got " + Describe(id));
        if (key == "attributes" && value.is_object())
          for (const auto& [name, id] : value.items())
            if (!(id.is_number_integer() && id.get<long long>() >= 0))
              throw Error(path + ": " + at + "." + name + " must be a non-negative accessor index");
      }
      Walk(path, value, at, extras, inExtensions || key == "extensions");
    }
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i)
      Walk(path, j[i], where + "[" + std::to_string(i) + "]", inExtras, inExtensions);
  }
}

}  // namespace

json ParseGltfJson(const std::string& path, std::string_view text) {
  // glTF needs a handful of nesting levels (extras may hold more); refusing absurd depth
  // keeps the recursive walk below, and the parse tree's destructor, off the end of the
  // stack. Measured on the text rather than through a parser callback: nlohmann-json's
  // callback parser rescans an array on every object that closes in it, quadratic time
  // (13 s for 150,000 nodes).
  constexpr int kMaxDepth = 256;
  if (NestingDepth(text) > kMaxDepth)
    throw Error(path + ": JSON is nested deeper than " + std::to_string(kMaxDepth) + " levels");
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    std::string what = e.what();
    if (what.size() > 200) what = what.substr(0, 200) + "…";
    throw Error(path + ": invalid JSON: " + what);
  }
}

void CheckGltfSchema(const std::string& path, const json& doc) {
  if (!doc.is_object()) throw Error(path + ": the glTF JSON is not an object");
  Walk(path, doc, "", false, false);
}

}  // namespace vkpt::internal
