#include "util/atomic_write.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "util/error.h"
#include "util/temp_file_guard.h"

namespace vkpt::internal {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& what, int error) {
  throw Error(path + ": " + what + ": " + std::strerror(error));
}

constexpr char kTemporaryMark[] = ".partial-";
constexpr size_t kTemporaryDigits = 16;

// An unpredictable name: with O_EXCL, a file or symlink planted under it by someone else
// makes the write fail instead of being followed or overwritten.
std::string TemporaryName(const std::string& path) {
  std::random_device random;
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, "%s%08x%08x", kTemporaryMark, random(), random());
  return path + suffix;
}

std::string DirectoryOf(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// Whether `name` is one of TemporaryName(base)'s names.
bool IsTemporaryOf(const std::string& name, const std::string& base) {
  const std::string prefix = base + kTemporaryMark;
  if (name.size() != prefix.size() + kTemporaryDigits || name.compare(0, prefix.size(), prefix) != 0) return false;
  return name.find_first_not_of("0123456789abcdef", prefix.size()) == std::string::npos;
}

// A writer holds an exclusive flock(2) on its temporary from before the file has a name
// until after the rename, and the kernel releases it when the writer dies however it
// dies. A temporary whose lock can be taken was abandoned (its writer was killed between
// naming and renaming it): it is removed. Best effort: what cannot be read or locked
// stays. Locks, unlike process ids, mean the same in every PID namespace sharing the folder.
void RemoveAbandonedTemporaries(const std::string& path) {
  const std::string dir = DirectoryOf(path);
  const std::string base = std::filesystem::path(path).filename().string();
  DIR* listing = ::opendir(dir.c_str());
  if (!listing) return;
  while (const dirent* entry = ::readdir(listing)) {
    if (!IsTemporaryOf(entry->d_name, base)) continue;
    const std::string name = dir + "/" + entry->d_name;
    // O_NONBLOCK: a FIFO planted under such a name must not block the open.
    const int fd = ::open(name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat info {};
    if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0) ::unlink(name.c_str());
    ::close(fd);
  }
  ::closedir(listing);
}

// Takes the writer's lock on a file only it has opened, so it cannot fail but for a
// file system without locks, where abandoned temporaries are then never removed.
void LockAsWriter(int fd) { (void)::flock(fd, LOCK_EX | LOCK_NB); }

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
  // some file systems (NFS, quotas) report a full disk only at fsync.
  if (::fsync(fd) != 0) closeAndFail("fsync failed");
}

// Renames the complete temporary `tmp` (under `guard`), open as `fd`, over `path`, then
// closes `fd` and with it the writer's lock. fsync has reported any write error already.
void RenameOver(int fd, const std::string& tmp, const std::string& path, TempFileGuard& guard) {
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::close(fd);
    Fail(path, "cannot rename " + tmp + " to it", error);
  }
  guard.Dismiss();
  ::close(fd);
}

// Linux's O_TMPFILE: the bytes go to a file without a name in path's directory, which
// vanishes with the process if it is killed (SIGKILL runs no handler) while writing; only
// once complete is it given its temporary name (linkat through /proc/self/fd) and renamed
// over path, two system calls apart (a kill between them leaves a temporary that the
// next write of path removes: RemoveAbandonedTemporaries). False, with nothing written, where the file system
// or the kernel has no O_TMPFILE or /proc is not mounted.
bool WriteUnnamedThenLink(const std::string& path, std::span<const uint8_t> bytes) {
  const int fd = ::open(DirectoryOf(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  LockAsWriter(fd);
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
  RenameOver(fd, tmp, path, guard);
  return true;
}

}  // namespace

void WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes) {
  RemoveAbandonedTemporaries(path);
  if (WriteUnnamedThenLink(path, bytes)) return;
  const std::string tmp = TemporaryName(path);
  TempFileGuard guard(tmp);  // before open(2): no moment where the file is unguarded
  // A sweep by another writer between open and LockAsWriter would unlink the file: the
  // rename then fails with a clear error, and `path` keeps its previous contents.
  // 0666 less the umask: the permissions any other newly created file would get.
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    guard.Dismiss();  // not ours to remove (it may be someone else's file)
    Fail(path, "cannot create " + tmp, error);
  }
  LockAsWriter(fd);
  WriteAndSync(fd, path, bytes);
  RenameOver(fd, tmp, path, guard);
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

}  // namespace vkpt::internal
