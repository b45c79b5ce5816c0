// glTF animations (spec §3.11): each channel's sampler read at one time poses its node —
// translation, rotation, scale or morph weights. --animation picks one, --at the time.
#pragma once

#include <string>
#include <vector>

#include "gltf/gltf_source.h"
#include "gltf/node_pose.h"
#include "scene/load_limits.h"
#include "scene/scene.h"

namespace vkpt::internal {

// The file's animations, with their durations (the last keyframe time of any of their
// samplers), each sampler's input checked.
std::vector<AnimationSummary> ListAnimations(const GltfSource& src);

// The index of `wanted` among `animations`: its name, else a decimal index; −1 for "".
// Throws Error naming the file and listing its animations if there is no such one.
int ResolveAnimation(const GltfSource& src, const std::vector<AnimationSummary>& animations, const std::string& wanted);

// Charges `budget` for the keyframes of animations[animation] decoded, before they are
// read; returns the bytes.
uint64_t ChargeAnimation(const GltfSource& src, int animation, MemoryBudget& budget);

// `poses` with every channel of animations[animation] applied at `time` seconds. Each
// sampler is checked against its channel: interpolation, output type and count, and a
// target node without a matrix (and for weights, with morph targets). Channels without a
// target node are skipped, as the spec says.
void PoseAtTime(const GltfSource& src, int animation, double time, std::vector<NodePose>& poses);

}  // namespace vkpt::internal
