// The one place output files are written: complete or not at all.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace vkpt::internal {

// Writes `bytes` to a new temporary file beside `path` (same directory, so the rename is
// atomic), checks every write, fsyncs, closes and renames it over `path`: any reader, and
// any number of processes writing the same path, see one complete file or the one before.
// On any failure the temporary is removed, `path` is left as it was, and Error
// names `path` and the OS error. SIGINT/SIGTERM meanwhile also remove the temporary
// (TempFileGuard). SIGKILL leaves the previous file or the new one, whole; the temporary
// it may leave (where the file system has O_TMPFILE — ext4, xfs, btrfs, tmpfs — only if
// the kill falls between naming the complete file and renaming it) is removed by the
// next write of `path` from any process, which can tell it was abandoned by its lock.
void WriteFileAtomically(const std::string& path, std::span<const uint8_t> bytes);

// Throws Error unless WriteFileAtomically(path, …) could succeed as far as can be
// told before writing: path is not a directory, its directory exists and is writable.
// `what` names the file's purpose in the message ("an image").
void CheckWritablePath(const std::string& path, const std::string& what);

}  // namespace vkpt::internal
