// Reading a file that a path or a glTF names, and nothing else: only regular files are
// opened (a FIFO would block forever, /dev/zero never ends, a directory is no data), and
// only the bytes asked for are read.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>

namespace vkpt::internal {

class RegularFile {
 public:
  // Checks `path` with stat() before opening it, then opens it without blocking and
  // checks again on the descriptor (the file may have been swapped in between). On
  // failure returns nullopt and sets `problem` to a phrase such as "is a directory, not
  // a file" or "does not exist".
  static std::optional<RegularFile> Open(const std::string& path, std::string* problem);

  RegularFile(RegularFile&& other) noexcept : fd_(other.fd_), size_(other.size_) { other.fd_ = -1; }
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;
  ~RegularFile();

  uint64_t Size() const { return size_; }

  // Reads exactly `size` bytes at `offset`; false with `problem` set on an I/O error or
  // a file that is shorter than it was when opened.
  bool ReadAt(uint64_t offset, void* dest, size_t size, std::string* problem) const;

 private:
  RegularFile(int fd, uint64_t size) : fd_(fd), size_(size) {}
  int fd_;
  uint64_t size_;
};

// "is a directory, not a file", "is a FIFO, not a regular file", …: why a file of this
// mode is refused; empty for a regular file.
std::string NonRegularProblem(mode_t mode);

}  // namespace vkpt::internal
