#include "gltf/gltf_animation.h"

#include <cmath>

#include "gltf/gltf_accessors.h"
#include "gltf/keyframes.h"

namespace vkpt::internal {
namespace {

// A sampler's keyframe times: a FLOAT SCALAR accessor of finite, strictly increasing,
// non-negative seconds.
std::vector<double> ReadTimes(const GltfSource& src, const tinygltf::AnimationSampler& s, const std::string& name) {
  src.CheckIndex(s.input, src.m.accessors, name + ".input");
  const tinygltf::Accessor& a = src.m.accessors[s.input];
  const std::string what = name + ".input (accessors[" + std::to_string(s.input) + "])";
  if (a.type != TINYGLTF_TYPE_SCALAR || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.count == 0)
    src.Fail(what + " must be a FLOAT SCALAR accessor of at least one time");
  std::vector<double> times = ReadAccessor(src, s.input);
  for (size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || times[k] < 0.0)
      src.Fail(what + " element " + std::to_string(k) + " is not a finite time ≥ 0");
    if (k > 0 && !(times[k] > times[k - 1]))
      src.Fail(what + " element " + std::to_string(k) + " does not follow element " + std::to_string(k - 1) +
               " (times must increase strictly)");
  }
  return times;
}

Interpolation ReadInterpolation(const GltfSource& src, const tinygltf::AnimationSampler& s, const std::string& name) {
  if (s.interpolation == "LINEAR") return Interpolation::kLinear;
  if (s.interpolation == "STEP") return Interpolation::kStep;
  if (s.interpolation == "CUBICSPLINE") return Interpolation::kCubicSpline;
  src.Fail(name + ".interpolation \"" + s.interpolation + "\" is not LINEAR, STEP or CUBICSPLINE");
}

// The curve of a channel's sampler, its output checked for the path it animates:
// translation and scale FLOAT VEC3; rotation VEC4 and weights SCALAR, of FLOAT or
// normalized integers (spec §3.11, "Animations"); finite values.
Keyframes ReadCurve(const GltfSource& src, const tinygltf::AnimationSampler& s, const std::string& name,
                    const std::string& path, size_t targets) {
  Keyframes k;
  k.times = ReadTimes(src, s, name);
  k.mode = ReadInterpolation(src, s, name);
  k.rotation = path == "rotation";
  k.width = path == "weights" ? targets : path == "rotation" ? 4 : 3;
  src.CheckIndex(s.output, src.m.accessors, name + ".output");
  const tinygltf::Accessor& a = src.m.accessors[s.output];
  const std::string what = name + ".output (accessors[" + std::to_string(s.output) + "])";
  const bool normalizedInteger = a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT &&
                                 a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool floats = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const int type = path == "rotation"  ? TINYGLTF_TYPE_VEC4
                   : path == "weights" ? TINYGLTF_TYPE_SCALAR
                                       : TINYGLTF_TYPE_VEC3;
  if (a.type != type || !(floats || (normalizedInteger && (path == "rotation" || path == "weights"))))
    src.Fail(what + " does not suit a " + path + " channel (" +
             (path == "rotation"  ? "FLOAT or normalized integer VEC4"
              : path == "weights" ? "FLOAT or normalized integer SCALAR"
                                  : "FLOAT VEC3") +
             ")");
  const size_t perKey = (k.mode == Interpolation::kCubicSpline ? 3 : 1) * (path == "weights" ? targets : 1);
  if (a.count != k.times.size() * perKey)
    src.Fail(what + " has " + std::to_string(a.count) + " elements; " + std::to_string(k.times.size()) +
             " keyframes of this channel need " + std::to_string(k.times.size() * perKey));
  k.values = ReadAccessor(src, s.output);
  for (size_t i = 0; i < k.values.size(); ++i)
    if (!std::isfinite(k.values[i])) src.Fail(what + " component " + std::to_string(i) + " is not finite");
  return k;
}

// Applies one curve's value to the node it animates.
void Apply(const std::vector<double>& v, const std::string& path, NodePose& pose) {
  if (path == "translation") pose.translation = glm::dvec3(v[0], v[1], v[2]);
  if (path == "scale") pose.scale = glm::dvec3(v[0], v[1], v[2]);
  if (path == "weights") pose.weights = v;
  if (path == "rotation") {
    const glm::dquat q(v[3], v[0], v[1], v[2]);  // (w, x, y, z)
    const double len = glm::length(q);
    // A zero quaternion keeps the rest rotation rather than divide by zero.
    if (len > 1e-12) pose.rotation = q / len;
  }
}

}  // namespace

std::vector<AnimationSummary> ListAnimations(const GltfSource& src) {
  std::vector<AnimationSummary> list;
  for (size_t i = 0; i < src.m.animations.size(); ++i) {
    const tinygltf::Animation& anim = src.m.animations[i];
    AnimationSummary a{anim.name, 0.0};
    for (size_t s = 0; s < anim.samplers.size(); ++s) {
      const std::string name = "animations[" + std::to_string(i) + "].samplers[" + std::to_string(s) + "]";
      a.duration = std::max(a.duration, ReadTimes(src, anim.samplers[s], name).back());
    }
    list.push_back(a);
  }
  return list;
}

int ResolveAnimation(const GltfSource& src, const std::vector<AnimationSummary>& animations,
                     const std::string& wanted) {
  return src.Choose(Names(animations), wanted, "--animation", "animation", "no animations");
}

uint64_t ChargeAnimation(const GltfSource& src, int animation, MemoryBudget& budget) {
  uint64_t bytes = 0;
  for (const tinygltf::AnimationSampler& s : src.m.animations[animation].samplers)
    for (int accessor : {s.input, s.output})
      if (accessor >= 0 && size_t(accessor) < src.m.accessors.size())
        bytes += src.m.accessors[accessor].count * ComponentCount(src.m.accessors[accessor].type) * 2 * sizeof(double);
  budget.Charge(bytes, "animations[" + std::to_string(animation) + "] (decoding its keyframes)");
  return bytes;
}

void PoseAtTime(const GltfSource& src, int animation, double time, std::vector<NodePose>& poses) {
  const tinygltf::Animation& anim = src.m.animations[animation];
  for (size_t c = 0; c < anim.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = anim.channels[c];
    const std::string name = "animations[" + std::to_string(animation) + "].channels[" + std::to_string(c) + "]";
    if (ch.target_node < 0) continue;
    src.CheckIndex(ch.target_node, src.m.nodes, name + ".target.node");
    const std::string& path = ch.target_path;
    if (path != "translation" && path != "rotation" && path != "scale" && path != "weights")
      src.Fail(name + ".target.path \"" + path + "\" is not translation, rotation, scale or weights");
    NodePose& pose = poses[ch.target_node];
    const std::string node = "nodes[" + std::to_string(ch.target_node) + "]";
    if (path != "weights" && pose.matrix)
      src.Fail(name + " animates " + node +
               ", which has a matrix (an animated node must use translation, "
               "rotation and scale)");
    if (path == "weights" && pose.weights.empty())
      src.Fail(name + " animates the morph weights of " + node + ", whose mesh has no morph targets");
    src.CheckIndex(ch.sampler, anim.samplers, name + ".sampler");
    const tinygltf::AnimationSampler& s = anim.samplers[ch.sampler];
    const std::string sname =
        "animations[" + std::to_string(animation) + "].samplers[" + std::to_string(ch.sampler) + "]";
    Apply(ReadCurve(src, s, sname, path, pose.weights.size()).At(time), path, pose);
  }
}

}  // namespace vkpt::internal
