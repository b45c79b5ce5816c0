// A 64-bit FNV-1a hash (Fowler, Noll, Vo), to tell two inputs apart in reports: fast,
// stable across platforms and runs, and not cryptographic (it names content, it does not
// authenticate it).
#pragma once

#include <cstdint>
#include <span>

namespace vkpt::internal {

class ContentHash {
 public:
  void Add(std::span<const unsigned char> bytes) {
    for (unsigned char b : bytes) value_ = (value_ ^ b) * 0x100000001B3ull;
  }
  uint64_t Value() const { return value_; }

 private:
  uint64_t value_ = 0xCBF29CE484222325ull;
};

}  // namespace vkpt::internal
