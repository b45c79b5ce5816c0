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

// Writes every byte to `fd` and syncs it; on failure closes it and throws.
void WriteAndSync(int fd, const std::string& path, std::span<const uint8_t> bytes) {
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
}

// Renames the complete temporary `tmp` (under `guard`) over `path`.
void RenameOver(const std::string& tmp, const std::string& path, TempFileGuard& guard) {
  if (::rename(tmp.c_str(), path.c_str()) != 0) Fail(path, "cannot rename " + tmp + " to it", errno);
  guard.Dismiss();
}

std::string DirectoryOf(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// Linux's O_TMPFILE: the bytes go to a file without a name in path's directory, which
// vanishes with the process if it is killed (SIGKILL runs no handler) while writing; only
// once complete is it given its temporary name (linkat through /proc/self/fd) and renamed
// over path, two system calls apart. False, with nothing written, where the file system
// or the kernel has no O_TMPFILE or /proc is not mounted.
bool WriteUnnamedThenLink(const std::string& path, std::span<const uint8_t> bytes) {
  const int fd = ::open(DirectoryOf(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  WriteAndSync(fd, path, bytes);
  const std::string tmp = TemporaryName(path);
  TempFileGuard guard(tmp);  // before linkat: no moment where the name is unguarded
  char self[48];
  std::snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
  if (::linkat(AT_FDCWD, self, AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
    const int error = errno;
    guard.Dismiss();
    ::close(fd);
    if (error == ENOENT) return false;
    Fail(path, "cannot link " + tmp, error);
  }
  if (::close(fd) != 0) Fail(path, "close failed", errno);
  RenameOver(tmp, path, guard);
  return true;
}

}  // namespace

void WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes) {
  if (WriteUnnamedThenLink(path, bytes)) return;
  const std::string tmp = TemporaryName(path);
  TempFileGuard guard(tmp);  // before open(2): no moment where the file is unguarded
  // 0666 less the umask: the permissions any other newly created file would get.
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    guard.Dismiss();  // not ours to remove (it may be someone else's file)
    Fail(path, "cannot create " + tmp, error);
  }
  WriteAndSync(fd, path, bytes);
  if (::close(fd) != 0) Fail(path, "close failed", errno);
  RenameOver(tmp, path, guard);
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
