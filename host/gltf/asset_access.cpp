#include "gltf/asset_access.h"

#include <tiny_gltf.h>

#include <climits>
#include <cstdlib>
#include <new>

#include "util/byte_size.h"
#include "util/error.h"
#include "util/regular_file.h"

namespace vkpt::internal {
namespace {

const char kFolderRule[] = "; a glTF may only read files inside its own folder (--allow-external-uris lifts this rule)";

std::string Canonical(const std::string& path) {
  char buffer[PATH_MAX];
  return realpath(path.c_str(), buffer) ? std::string(buffer) : std::string();
}

// Everything before ':' when the uri starts with an RFC 3986 scheme ("file", "http").
std::string Scheme(const std::string& uri) {
  size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha((unsigned char)uri[0])) return "";
  for (size_t i = 1; i < colon; ++i)
    if (!std::isalnum((unsigned char)uri[i]) && uri[i] != '+' && uri[i] != '-' && uri[i] != '.') return "";
  return uri.substr(0, colon);
}

// `relative` with "." and ".." resolved lexically; false when ".." climbs above the start.
bool StaysInside(const std::string& relative) {
  int depth = 0;
  size_t start = 0;
  while (start <= relative.size()) {
    size_t end = relative.find('/', start);
    if (end == std::string::npos) end = relative.size();
    std::string_view part(relative.data() + start, end - start);
    if (part == "..") {
      if (--depth < 0) return false;
    } else if (!part.empty() && part != ".") {
      ++depth;
    }
    start = end + 1;
  }
  return true;
}

// A uri in a message: as written, cut short if long.
std::string Quote(const std::string& uri) { return "\"" + (uri.size() > 120 ? uri.substr(0, 100) + "…" : uri) + "\""; }

}  // namespace

AssetAccess::AssetAccess(const std::string& scenePath, std::vector<ExternalUri> uris, const LoadLimits& limits,
                         MemoryBudget& budget)
    : scenePath_(scenePath), uris_(std::move(uris)), limits_(limits), budget_(budget) {
  size_t slash = scenePath.find_last_of('/');
  std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : scenePath.substr(0, slash);
  folder_ = Canonical(dir);
  if (folder_.empty()) throw Error(scenePath + ": cannot resolve the scene's folder");
  if (folder_ == "/") folder_.clear();  // so that folder_ + "/" + name is right at the root
}

void AssetAccess::Install(tinygltf::TinyGLTF& gltf) {
  tinygltf::FsCallbacks fs{};
  fs.FileExists = [](const std::string& path, void* self) { return static_cast<AssetAccess*>(self)->Exists(path); };
  // The identity: tinygltf's default expands "~" and "$VARIABLES" with wordexp().
  fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
  fs.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self) {
    return static_cast<AssetAccess*>(self)->Read(out, err, path);
  };
  fs.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "vkpt writes no glTF files";
    return false;
  };
  fs.user_data = this;
  gltf.SetFsCallbacks(fs);
}

const ExternalUri& AssetAccess::Find(const std::string& decoded) const {
  for (const ExternalUri& u : uris_)
    if (u.decoded == decoded) return u;
  static const ExternalUri kUnlisted{"a uri", "", "", std::nullopt, true};
  return kUnlisted;
}

void AssetAccess::Refuse(const std::string& decoded, const ExternalUri& uri, const std::string& why, bool ruleBroken) {
  for (const auto& r : refusals_)
    if (r.first == decoded) return;  // the first reason stands
  std::string written = uri.written.empty() ? decoded : uri.written;
  refusals_.emplace_back(decoded, uri.owner + ".uri " + Quote(written) + " " + why + (ruleBroken ? kFolderRule : ""));
}

// tinygltf asks for <folder>/<decoded uri>, then ./<decoded uri>; the second is the
// current directory, which only --allow-external-uris lets it search.
bool AssetAccess::Exists(const std::string& candidate) {
  std::string decoded;
  bool viaCurrentDirectory = false;
  if (candidate.starts_with(folder_ + "/")) {
    decoded = candidate.substr(folder_.size() + 1);
  } else if (candidate.starts_with("./") && limits_.allowExternalUris) {
    decoded = candidate.substr(2);
    viaCurrentDirectory = true;
  } else {
    return false;
  }
  const ExternalUri& uri = Find(decoded);
  std::string path = Resolve(decoded, uri, viaCurrentDirectory);
  if (path.empty()) return false;

  Granted g{candidate, decoded, path, 0, !uri.used};
  if (g.skip) {
    skipped_.push_back(uri.owner + " " + Quote(uri.written) + ": used by no texture, not read");
  } else {
    std::string problem;
    std::optional<RegularFile> file = RegularFile::Open(path, &problem);
    if (!file) {
      Refuse(decoded, uri, problem == "does not exist" ? "names no file in the scene's folder" : problem, false);
      return false;
    }
    g.size = file->Size();
    if (uri.owner.starts_with("buffers") && g.size != uri.byteLength) {
      Refuse(decoded, uri,
             "holds " + std::to_string(g.size) + " bytes, but " + uri.owner + ".byteLength says " +
                 (uri.byteLength ? std::to_string(*uri.byteLength) : std::string("nothing")),
             false);
      return false;
    }
    budget_.Charge(g.size, uri.owner + " (file " + Quote(uri.written) + ")");
  }
  std::erase_if(refusals_, [&](const auto& r) { return r.first == decoded; });
  granted_.push_back(std::move(g));
  return true;
}

std::string AssetAccess::Resolve(const std::string& decoded, const ExternalUri& uri, bool viaCurrentDirectory) {
  const bool open = limits_.allowExternalUris;
  if (decoded.empty() || decoded.find('\0') != std::string::npos) {
    Refuse(decoded, uri, "is empty or contains a NUL byte", false);
    return "";
  }
  if (std::string scheme = Scheme(decoded); !scheme.empty()) {
    if (scheme != "file" || !decoded.starts_with("file:///")) {
      Refuse(decoded, uri, "is a URL (scheme \"" + scheme + ":\"); vkpt reads local files only", false);
      return "";
    }
    if (!open) {
      Refuse(decoded, uri, "is a file:// URL", true);
      return "";
    }
    return decoded.substr(7);
  }
  if (decoded[0] == '/') {
    if (!open) Refuse(decoded, uri, "is an absolute path", true);
    return open ? decoded : "";
  }
  if (viaCurrentDirectory) return decoded;
  if (!StaysInside(decoded)) {
    if (!open) Refuse(decoded, uri, "leads out of the scene's folder (\"..\")", true);
    return open ? folder_ + "/" + decoded : "";
  }
  std::string path = folder_ + "/" + decoded;
  if (open) return path;
  // Inside by its name; a symbolic link on the way may still lead out.
  std::string real = Canonical(path);
  if (real.empty()) {
    Refuse(decoded, uri, "names no file in the scene's folder", false);
    return "";
  }
  if (!real.starts_with(folder_ + "/")) {
    Refuse(decoded, uri, "is a symbolic link leading out of the scene's folder", true);
    return "";
  }
  return real;
}

bool AssetAccess::Read(std::vector<unsigned char>* out, std::string* err, const std::string& candidate) {
  for (const Granted& g : granted_) {
    if (g.candidate != candidate) continue;
    if (g.skip) {
      out->assign(1, 0);  // tinygltf refuses empty data; vkpt's image callback ignores it
      return true;
    }
    std::string problem;
    std::optional<RegularFile> file = RegularFile::Open(g.path, &problem);
    if (file && file->Size() != g.size) problem = "changed size while the scene was loading";
    try {
      if (file && problem.empty()) out->resize(size_t(g.size));
    } catch (const std::bad_alloc&) {
      problem = "does not fit in memory (" + FormatBytes(g.size) + ")";
    }
    if (file && problem.empty() && file->ReadAt(0, out->data(), out->size(), &problem)) return true;
    Refuse(g.decoded, Find(g.decoded), problem, false);
    *err = problem;
    return false;
  }
  *err = "was not checked before reading";
  return false;
}

void AssetAccess::ThrowIfRefused() const {
  if (!refusals_.empty()) throw Error(scenePath_ + ": " + refusals_.front().second);
}

}  // namespace vkpt::internal
