#include "util/byte_size.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace vkpt::internal {
namespace {

std::string WithThousands(uint64_t v) {
  std::string digits = std::to_string(v), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace

std::string FormatBytes(uint64_t bytes) {
  static const char* const kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  int unit = 0;
  uint64_t scale = 1024;
  while (unit < 5 && bytes / scale >= 1024) {
    scale *= 1024;
    ++unit;
  }
  char text[64];
  if (bytes % scale == 0) {
    std::snprintf(text, sizeof text, "%llu %s", (unsigned long long)(bytes / scale), kUnits[unit]);
    return text;
  }
  int n = std::snprintf(text, sizeof text, "%.2f %s", double(bytes) / double(scale), kUnits[unit]);
  // "128.00 MiB" would read as a whole 128 MiB: say exactly how far from it the figure is.
  bool looksWhole = n > 4 && std::string_view(text, size_t(n)).find(".00 ") != std::string_view::npos;
  return looksWhole ? std::string(text) + " (" + WithThousands(bytes) + " bytes)" : std::string(text);
}

std::optional<uint64_t> ParseByteSize(const std::string& text) {
  uint64_t value = 0;
  const char* end = text.data() + text.size();
  auto [rest, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || rest == text.data()) return std::nullopt;
  std::string suffix;
  for (const char* p = rest; p != end; ++p) suffix += char(std::toupper((unsigned char)*p));
  if (suffix.size() > 1 && (suffix.ends_with("IB") || suffix.ends_with("B")) && suffix != "B")
    suffix.erase(suffix.size() - (suffix.ends_with("IB") ? 2 : 1));
  int shift = 0;
  if (suffix.empty() || suffix == "B") shift = 0;
  else if (suffix == "K") shift = 10;
  else if (suffix == "M") shift = 20;
  else if (suffix == "G") shift = 30;
  else if (suffix == "T") shift = 40;
  else return std::nullopt;
  if (shift && value > (UINT64_MAX >> shift)) return std::nullopt;
  return value << shift;
}

}  // namespace vkpt::internal
