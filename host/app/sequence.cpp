#include "app/sequence.h"

#include <cmath>
#include <cstdio>

#include "util/atomic_write.h"

namespace vkpt::internal {

uint64_t FrameCount(const FrameRange& range) { return (uint64_t(range.last) - range.first) / range.step + 1; }

uint32_t FrameNumber(const FrameRange& range, uint64_t i) { return uint32_t(range.first + i * range.step); }

std::string FramePath(const std::string& out, uint32_t frame) {
  const size_t slash = out.find_last_of('/');
  const size_t name = slash == std::string::npos ? 0 : slash + 1;
  const size_t end = out.find_last_of('#');
  if (end != std::string::npos && end >= name) {
    size_t begin = end;
    while (begin > name && out[begin - 1] == '#') --begin;
    char number[16];
    std::snprintf(number, sizeof number, "%0*u", int(end + 1 - begin), frame);
    return out.substr(0, begin) + number + out.substr(end + 1);
  }
  const size_t dot = out.find_last_of('.');
  const size_t at = dot == std::string::npos || dot < name ? out.size() : dot;
  char number[16];
  std::snprintf(number, sizeof number, ".%04u", frame);
  return out.substr(0, at) + number + out.substr(at);
}

Options FrameOptions(const Options& o, uint32_t frame) {
  Options f = o;
  if (!o.api.scene.animation.empty()) f.api.render.time = frame / o.fps;
  // A whole turn is no turn: the angle stays within --orbit's range however many frames.
  f.api.camera.orbitDegrees = std::fmod(o.api.camera.orbitDegrees * frame, 360.0);
  f.out = FramePath(o.out, frame);
  f.stats.clear();
  return f;
}

void WriteSequenceStats(const std::string& path, const std::vector<std::string>& frames) {
  std::string json = "{\"frames\":[";
  for (size_t i = 0; i < frames.size(); ++i) json += (i ? "," : "") + frames[i];
  json += "]}";
  WriteFileAtomically(path, {reinterpret_cast<const uint8_t*>(json.data()), json.size()});
}

}  // namespace vkpt::internal
