#include "util/atomic_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "util/error.h"
#include "util/temp_file_guard.h"

namespace vkpt {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& what, int error) {
  throw Error(path + ": " + what + ": " + std::strerror(error));
}

// An unpredictable name: with O_EXCL, a file or symlink planted under it by someone else
// makes the write fail instead of being followed or overwritten.
std::string TemporaryName(const std::string& path) {
  std::random_device random;
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, ".partial-%08x%08x", random(), random());
  return path + suffix;
}

}  // namespace

void WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes) {
  const std::string tmp = TemporaryName(path);
  TempFileGuard guard(tmp);  // before open(2): no moment where the file is unguarded
  // 0666 less the umask: the permissions any other newly created file would get.
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    guard.Dismiss();  // not ours to remove (it may be someone else's file)
    Fail(path, "cannot create " + tmp, error);
  }
  auto closeAndFail = [&](const char* what) {
    const int error = errno;
    ::close(fd);
    Fail(path, what, error);
  };
  // write(2) may write less than asked (a file-size limit, a disk filling up: the next
  // call then reports why) or be interrupted by a signal before writing anything.
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) closeAndFail("write failed");
    done += size_t(n);
  }
  // Without fsync a crash after the rename could leave the new name on empty blocks;
  // some file systems (NFS, quotas) report a full disk only at fsync or close.
  if (::fsync(fd) != 0) closeAndFail("fsync failed");
  if (::close(fd) != 0) Fail(path, "close failed", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) Fail(path, "cannot rename " + tmp + " to it", errno);
  guard.Dismiss();
}

void CheckWritablePath(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p(path);
  if (fs::is_directory(p, ec)) throw Error(path + ": is a directory, not " + what + " file name");
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw Error(path + ": directory " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw Error(path + ": cannot write to directory " + dir.string() + ": " + std::strerror(errno));
}

}  // namespace vkpt
