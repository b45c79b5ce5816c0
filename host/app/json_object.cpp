#include "app/json_object.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace vkpt::internal {

std::string JsonString(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {  // control characters; bytes >= 0x80 pass through as UTF-8
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", u);
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string JsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : "null";
}

std::string JsonArray(const std::vector<std::string>& jsonValues) {
  std::string out = "[";
  for (size_t i = 0; i < jsonValues.size(); ++i) out += (i ? "," : "") + jsonValues[i];
  return out + "]";
}

JsonObject& JsonObject::Raw(std::string_view key, const std::string& json) {
  if (!members_.empty()) members_ += ',';
  members_ += JsonString(key) + ":" + json;
  return *this;
}

}  // namespace vkpt::internal
