// The one place where a glTF's `uri`s become file reads: the file-system callbacks
// given to tinygltf. A glTF is untrusted, so by default it may read only regular files
// inside its own folder — no "..", no absolute paths, no URLs, no symbolic link leading
// out, no lookup in the current directory — and every file it names is checked against
// what the glTF declares (a buffer's byteLength) and against the memory budget before a
// byte of it is read. `--allow-external-uris` (LoadLimits) lifts the folder rule only.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gltf/external_uris.h"
#include "scene/load_limits.h"

namespace tinygltf {
class TinyGLTF;
}

namespace vkpt::internal {

class AssetAccess {
 public:
  // `scenePath` is the glTF file; `uris` what ListExternalUris found in it.
  AssetAccess(const std::string& scenePath, std::vector<ExternalUri> uris, const LoadLimits& limits,
              MemoryBudget& budget);

  // The scene's folder, absolute and free of symbolic links: tinygltf's base directory.
  std::string BaseDir() const { return folder_.empty() ? "/" : folder_; }

  // Makes `gltf` open files only through this object. It must outlive the load.
  void Install(tinygltf::TinyGLTF& gltf);

  // After the load: throws Error for the first uri that was refused, naming the
  // uri as written and the rule it broke.
  void ThrowIfRefused() const;

  // Images that no texture uses, and so were not read (for -v).
  const std::vector<std::string>& SkippedImages() const { return skipped_; }

 private:
  struct Granted {
    std::string candidate;  // the path tinygltf asked about
    std::string decoded;    // the uri it came from
    std::string path;       // the file to open
    uint64_t size = 0;
    bool skip = false;  // an unused image: tinygltf gets a placeholder, nothing is read
  };

  bool Exists(const std::string& candidate);
  bool Read(std::vector<unsigned char>* out, std::string* err, const std::string& candidate);
  // Applies the rules to one uri; returns the path to open, or "" after Refuse().
  std::string Resolve(const std::string& decoded, const ExternalUri& uri, bool viaCurrentDirectory);
  void Refuse(const std::string& decoded, const ExternalUri& uri, const std::string& why, bool ruleBroken);
  const ExternalUri& Find(const std::string& decoded) const;

  std::string scenePath_;
  std::string folder_;
  std::vector<ExternalUri> uris_;
  LoadLimits limits_;
  MemoryBudget& budget_;
  std::vector<Granted> granted_;
  std::vector<std::pair<std::string, std::string>> refusals_;  // (decoded uri, message)
  std::vector<std::string> skipped_;
};

}  // namespace vkpt::internal
