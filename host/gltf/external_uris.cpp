#include "gltf/external_uris.h"

#include <set>

namespace vkpt::internal {
namespace {

using nlohmann::json;

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 0;  // as tinygltf: a bad digit counts as 0
}

const json* Member(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// A texture's image: `source`, or an extension's (KHR_texture_basisu, EXT_texture_webp …).
void AddTextureSources(const json& texture, std::set<long long>& used) {
  if (const json* s = Member(texture, "source"); s && s->is_number_integer()) used.insert(s->get<long long>());
  if (const json* ext = Member(texture, "extensions"); ext && ext->is_object())
    for (const auto& [name, value] : ext->items())
      if (const json* s = Member(value, "source"); s && s->is_number_integer()) used.insert(s->get<long long>());
}

}  // namespace

bool IsEmbeddedDataUri(const std::string& uri) {
  static const char* const kPrefixes[] = {"data:application/octet-stream;base64,",
                                          "data:application/gltf-buffer;base64,",
                                          "data:image/jpeg;base64,",
                                          "data:image/png;base64,",
                                          "data:image/bmp;base64,",
                                          "data:image/gif;base64,",
                                          "data:text/plain;base64,"};
  for (const char* prefix : kPrefixes)
    if (uri.starts_with(prefix)) return true;
  return false;
}

std::string DecodeUri(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size()) {
      out += char(HexDigit(uri[i + 1]) << 4 | HexDigit(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

std::vector<ExternalUri> ListExternalUris(const json& doc) {
  std::vector<ExternalUri> uris;
  auto add = [&](const json* array, const char* name, auto&& fill) {
    if (!array || !array->is_array()) return;
    for (size_t i = 0; i < array->size(); ++i) {
      const json* uri = Member((*array)[i], "uri");
      if (!uri || !uri->is_string() || IsEmbeddedDataUri(uri->get_ref<const std::string&>())) continue;
      ExternalUri u;
      u.owner = std::string(name) + "[" + std::to_string(i) + "]";
      u.written = uri->get<std::string>();
      u.decoded = DecodeUri(u.written);
      fill(u, (*array)[i], i);
      uris.push_back(std::move(u));
    }
  };
  add(Member(doc, "buffers"), "buffers", [](ExternalUri& u, const json& buffer, size_t) {
    if (const json* n = Member(buffer, "byteLength"); n && n->is_number_unsigned()) u.byteLength = n->get<uint64_t>();
  });
  std::set<long long> usedImages;
  if (const json* textures = Member(doc, "textures"); textures && textures->is_array())
    for (const json& t : *textures) AddTextureSources(t, usedImages);
  add(Member(doc, "images"), "images",
      [&](ExternalUri& u, const json&, size_t i) { u.used = usedImages.count((long long)i) > 0; });
  return uris;
}

}  // namespace vkpt::internal
