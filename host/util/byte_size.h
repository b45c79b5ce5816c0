// Byte counts for people: printing them so that two different figures never read the
// same, and parsing sizes such as "512M" or "8G" from the command line.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace vkpt::internal {

// "812 bytes", "128 MiB", "1.50 GiB"; a figure that would print as a whole number of its
// unit without being one adds the exact count ("128.00 MiB (134,218,752 bytes)"), so
// that "needs X, allows at most Y" never prints the same figure twice.
std::string FormatBytes(uint64_t bytes);

// "1048576", "512K", "512M", "8G", "1T" (binary units, optional "iB"/"B" suffix, case
// insensitive); nullopt for anything else or a value that overflows 64 bits.
std::optional<uint64_t> ParseByteSize(const std::string& text);

}  // namespace vkpt::internal
