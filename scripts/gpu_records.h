// The description in shaders/shared/gpu_records.def as values: what gen_gpu_records.cpp
// reads (gpu_records_parse.cpp) and writes out (gpu_records_emit.cpp).
#pragma once

#include <string>
#include <vector>

namespace vkpt::records {

// A field of a record, with its std430 place: byte offset, so texel offset / 16 and
// lane (offset % 16) / 4.
struct Field {
  std::string type;  // uint, float, vec2, vec3 or uvec4
  std::string name;
  std::string comment;  // after "//", or empty
  bool fetch = false;   // @fetch: a Fetch<Short><Name>(i) of its own
  unsigned offset = 0;
};

// A line of a record's body: a field, or a comment line between fields.
struct Item {
  bool isField = true;
  Field field;
  std::string comment;  // a whole-line comment (isField false)
};

struct Record {
  std::string name, shortName;   // the struct; kTexelsPer<shortName>, Fetch<shortName>
  std::vector<std::string> doc;  // the struct's comment lines
  std::vector<Item> items;
  std::vector<std::string> texelCondition;  // per texel: empty, or when it is read
  std::string sampler;                      // empty: not read from texels
  std::string high, flag, splitVar;         // split: the second buffer, when it is used, where it starts
  std::string base;                         // a texel offset added to every index
  unsigned size = 0;                        // bytes, std430 (equal to C++'s, or refused)
  unsigned Texels() const { return size / 16; }
};

struct Slot {
  std::string name;  // baseColor: kSlotBaseColor, TextureSlot::kBaseColor
  bool srgb = false;
  std::string path;  // glTF path in a material: pbrMetallicRoughness.baseColorTexture, KHR_…
  std::string comment;
};

struct Description {
  std::vector<Record> records;
  std::vector<Slot> slots;
};

// Reads the description; throws std::runtime_error("<file>:<line>: …") on any error,
// including a field whose std430 offset differs from its C++ one.
Description Parse(const std::string& text, const std::string& file);

// The three generated files' text.
std::string SharedHeader(const Description& d);  // shared/gpu_records.h
std::string FetchGlsl(const Description& d);     // gpu_fetch.glsl
std::string SlotHeader(const Description& d);    // scene/texture_slots.h

std::string Capitalized(const std::string& s);

}  // namespace vkpt::records
