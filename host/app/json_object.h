// A JSON object written member by member, in order, for vkpt's machine-readable output
// (--stats). Hand-written because the JSON library is the scene layer's (it parses glTF):
// this only has to emit numbers, strings, arrays and nested objects, and does so exactly.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vkpt::internal {

std::string JsonString(std::string_view s);  // quoted, with every character JSON requires escaped
std::string JsonNumber(double v);            // shortest round-trip form; null if not finite
std::string JsonArray(const std::vector<std::string>& jsonValues);

class JsonObject {
 public:
  JsonObject& Str(std::string_view key, std::string_view value) { return Raw(key, JsonString(value)); }
  JsonObject& Num(std::string_view key, double value) { return Raw(key, JsonNumber(value)); }
  JsonObject& Int(std::string_view key, uint64_t value) { return Raw(key, std::to_string(value)); }
  JsonObject& Bool(std::string_view key, bool value) { return Raw(key, value ? "true" : "false"); }
  JsonObject& Obj(std::string_view key, const JsonObject& value) { return Raw(key, value.Text()); }
  JsonObject& Raw(std::string_view key, const std::string& json);  // `json`: a JSON value's text
  std::string Text() const { return "{" + members_ + "}"; }

 private:
  std::string members_;
};

}  // namespace vkpt::internal
