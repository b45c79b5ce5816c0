#include "gltf/gltf_texture_images.h"

#include <span>
#include <utility>
#include <vector>

#include "image/texture_decode.h"
#include "util/parallel.h"

namespace vkpt::internal {
namespace {

// Host memory per texel of an image's level 0: the decoder's output and stb's working memory
// (up to three times the output: texture_decode.h), the Scene's copy, and the renderer's store with its mip
// levels (4/3 of level 0) four times over: the chains as built, the store, its staging
// buffer and its device copy.
constexpr uint64_t kBytesPerTexel = 16 + 4 + 4 * 6;

// An image to decode, its header read.
struct Job {
  int image;
  std::string name;  // "images[2] "wood.png" (used by materials[0] … baseColorTexture)"
  TextureImageHeader header;
};

// The encoded bytes of images[i]: its bufferView's, or what tinygltf read for its uri
// (kept by the loader's image callback).
std::span<const unsigned char> EncodedImage(const GltfSource& src, int image) {
  const tinygltf::Image& im = src.m.images[image];
  if (im.bufferView < 0) return im.image;
  const tinygltf::BufferView& bv = src.m.bufferViews[im.bufferView];
  return std::span<const unsigned char>(src.m.buffers[bv.buffer].data).subspan(bv.byteOffset, bv.byteLength);
}

std::string ImageName(const GltfSource& src, int image) {
  std::string name = "images[" + std::to_string(image) + "]";
  const tinygltf::Image& im = src.m.images[image];
  if (!im.name.empty()) return name + " \"" + im.name + "\"";
  if (!im.uri.empty() && !im.uri.starts_with("data:")) return name + " \"" + im.uri + "\"";
  return name;
}

// Reads every image's header and charges the texel and memory budgets for it, failing
// on the first image that passes one, before anything is decoded.
std::vector<Job> ReadHeaders(const GltfSource& src, const std::map<int, std::string>& users, const LoadLimits& limits,
                             MemoryBudget& budget) {
  std::vector<Job> jobs;
  const uint64_t maxTexels = limits.maxTextureTexels ? limits.maxTextureTexels : kDefaultMaxTextureTexels;
  uint64_t texels = 0;
  for (const auto& [image, user] : users) {
    Job job{image, ImageName(src, image) + " (used by " + user + ")", {}};
    try {
      job.header = ReadTextureImageHeader(EncodedImage(src, image), src.m.images[image].mimeType);
    } catch (const Error& e) {
      src.Fail(job.name + " " + e.what());
    }
    const uint64_t n = uint64_t(job.header.width) * job.header.height;
    texels += n;
    if (texels > maxTexels)
      src.Fail(job.name + " brings the scene's texture texels to " + std::to_string(texels) +
               ", more than --max-texels " + std::to_string(maxTexels));
    budget.Charge(n * kBytesPerTexel, job.name + " (" + std::to_string(job.header.width) + " × " +
                                          std::to_string(job.header.height) + " texels)");
    jobs.push_back(std::move(job));
  }
  return jobs;
}

// Decodes jobs[k] into scene.images[k], in parallel; the first failure (in job order)
// is reported once all are done.
void DecodeImages(const GltfSource& src, const std::vector<Job>& jobs, Scene& scene) {
  scene.images.resize(jobs.size());
  std::vector<std::string> errors(jobs.size());
  ParallelFor(jobs.size(), ThreadCount(0), [&](size_t k) {
    try {
      Rgba8Image decoded = DecodeTextureImage(EncodedImage(src, jobs[k].image), jobs[k].header);
      scene.images[k] = {ImageName(src, jobs[k].image), decoded.width, decoded.height, std::move(decoded.texels)};
    } catch (const Error& e) {
      errors[k] = jobs[k].name + " " + e.what();
    }
  });
  for (const std::string& e : errors)
    if (!e.empty()) src.Fail(e);
}

}  // namespace

void LoadTextureImages(const GltfSource& src, const std::map<int, std::string>& users, const LoadLimits& limits,
                       MemoryBudget& budget, Scene& scene) {
  const std::vector<Job> jobs = ReadHeaders(src, users, limits, budget);
  DecodeImages(src, jobs, scene);
  std::map<int, uint32_t> index;  // glTF image → Scene::images
  for (uint32_t k = 0; k < jobs.size(); ++k) index[jobs[k].image] = k;
  for (SceneTexture& t : scene.textures) t.image = index.at(int(t.image));
}

}  // namespace vkpt::internal
