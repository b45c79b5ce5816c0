#include "scene/gltf_schema.h"

#include <nlohmann/json.hpp>

#include <set>

#include "util/error.h"

namespace vkpt {
namespace {

using nlohmann::json;

// Properties whose value is an index into a top-level array (glTF 2.0 schema,
// "glTFid"): they must be integers >= 0.
const std::set<std::string> kIdProperties = {
    "bufferView", "buffer", "index", "source", "sampler", "mesh", "camera", "skin", "material",
    "indices", "scene", "node", "skeleton", "inverseBindMatrices", "input", "output"};
// Properties that must be arrays (of objects or of glTFids).
const std::set<std::string> kArrayProperties = {
    "accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials", "meshes",
    "nodes", "samplers", "scenes", "skins", "textures", "primitives", "children", "joints", "targets",
    "channels", "samplers", "extensionsUsed", "extensionsRequired"};
// Arrays whose elements are glTFids.
const std::set<std::string> kIdArrays = {"nodes", "children", "joints"};

void Walk(const std::string& path, const json& j, const std::string& where, bool inExtras) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      std::string at = where.empty() ? key : where + "." + key;
      // extras are free-form application data; attribute maps hold accessor ids.
      bool extras = inExtras || key == "extras";
      if (!extras) {
        if (kIdProperties.count(key) && !(value.is_number_integer() && value.get<long long>() >= 0) &&
            !value.is_object())  // "sampler"/"source" etc. are objects in some extensions
          throw Error(path + ": " + at + " must be a non-negative integer index, got " + value.dump());
        if (kArrayProperties.count(key) && !value.is_array() && !(key == "samplers" && value.is_object()))
          throw Error(path + ": " + at + " must be an array, got " + value.dump().substr(0, 40));
        bool idArray = kIdArrays.count(key) && value.is_array() && !value.empty() && !value[0].is_object();
        if (idArray)
          for (const json& id : value)
            if (!(id.is_number_integer() && id.get<long long>() >= 0))
              throw Error(path + ": " + at + " must hold non-negative integer indices, got " + id.dump());
        if (key == "attributes" && value.is_object())
          for (const auto& [name, id] : value.items())
            if (!(id.is_number_integer() && id.get<long long>() >= 0))
              throw Error(path + ": " + at + "." + name + " must be a non-negative accessor index");
      }
      Walk(path, value, at, extras);
    }
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) Walk(path, j[i], where + "[" + std::to_string(i) + "]", inExtras);
  }
}

// glTF needs a handful of nesting levels (extras may hold more); refusing absurd depth
// keeps the JSON parsers (tinygltf's recurses) and the walk above from exhausting the
// stack. A SAX pass of its own: json::parse's callback could check the depth as it
// builds, but that parser then rescans the enclosing array or object after every element
// it ends, quadratic time (a 0.9 MB array of {} took 26 s, 50 times that under ASan).
class DepthCheck : public nlohmann::json_sax<json> {
 public:
  static constexpr int kMaxDepth = 256;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool key(string_t&) override { return true; }
  bool start_object(std::size_t) override { return Enter(); }
  bool end_object() override { return Leave(); }
  bool start_array(std::size_t) override { return Enter(); }
  bool end_array() override { return Leave(); }
  bool parse_error(std::size_t, const std::string&, const json::exception& e) override {
    error = std::string("invalid JSON: ") + e.what();
    return false;
  }

  std::string error;  // why the pass stopped

 private:
  bool Enter() {
    if (++depth_ <= kMaxDepth) return true;
    error = "JSON is nested deeper than " + std::to_string(kMaxDepth) + " levels";
    return false;
  }
  bool Leave() {
    --depth_;
    return true;
  }
  int depth_ = 0;
};

}  // namespace

void CheckGltfSchema(const std::string& path, std::string_view text) {
  DepthCheck depth;
  json doc;
  try {
    if (!json::sax_parse(text.begin(), text.end(), &depth)) throw Error(path + ": " + depth.error);
    doc = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    throw Error(path + ": invalid JSON: " + e.what());
  }
  if (!doc.is_object()) throw Error(path + ": the glTF JSON is not an object");
  Walk(path, doc, "", false);
}

}  // namespace vkpt
