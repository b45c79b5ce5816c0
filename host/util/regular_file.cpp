#include "util/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace vkpt::internal {

std::string NonRegularProblem(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

std::optional<RegularFile> RegularFile::Open(const std::string& path, std::string* problem) {
  struct stat before {};
  if (path.find('\0') != std::string::npos) {
    *problem = "contains a NUL byte";
    return std::nullopt;
  }
  if (stat(path.c_str(), &before) != 0) {
    *problem = errno == ENOENT ? "does not exist" : std::string("cannot be read: ") + std::strerror(errno);
    return std::nullopt;
  }
  if (*problem = NonRegularProblem(before.st_mode); !problem->empty()) return std::nullopt;
  // O_NONBLOCK: should a FIFO replace the file after stat(), open() must not wait for a
  // writer; fstat() below then refuses it.
  int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    *problem = std::string("cannot be opened: ") + std::strerror(errno);
    return std::nullopt;
  }
  struct stat after {};
  if (fstat(fd, &after) != 0 || !S_ISREG(after.st_mode) || after.st_ino != before.st_ino ||
      after.st_dev != before.st_dev) {
    close(fd);
    *problem = "changed while it was being opened";
    return std::nullopt;
  }
  return RegularFile(fd, uint64_t(after.st_size));
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) close(fd_);
}

bool RegularFile::ReadAt(uint64_t offset, void* dest, size_t size, std::string* problem) const {
  auto* out = static_cast<char*>(dest);
  while (size > 0) {
    ssize_t got = pread(fd_, out, size, off_t(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      *problem = std::string("read error: ") + std::strerror(errno);
      return false;
    }
    if (got == 0) {
      *problem = "became shorter while it was being read";
      return false;
    }
    out += got;
    offset += uint64_t(got);
    size -= size_t(got);
  }
  return true;
}

}  // namespace vkpt::internal
