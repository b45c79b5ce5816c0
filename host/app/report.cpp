#include "app/report.h"

#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "image/image_compare.h"
#include "util/byte_size.h"
#include "util/graceful_stop.h"

namespace vkpt::internal {
namespace {

// " alpha MASK (cutoff c)", " alpha BLEND", or nothing for OPAQUE; with the factor's alpha.
std::string AlphaNote(const vkpt::MaterialInfo& m) {
  char note[64] = "";
  if (m.alphaMode == "MASK") std::snprintf(note, sizeof note, " alpha MASK %.3g (cutoff %.3g)", m.alpha, m.alphaCutoff);
  else if (m.alphaMode == "BLEND") std::snprintf(note, sizeof note, " alpha BLEND %.3g", m.alpha);
  return note;
}

// Whether the material refracts as the boundary of a volume, where alone its dispersion
// is seen (as the tracers' Material::RefractsAsVolume decides).
bool RefractsAsVolume(const vkpt::MaterialInfo& m) {
  return m.volume && m.transmission > 0.0f && m.ior > 1.0f && !m.unlit;
}

// The layers and lobes a material adds to the metallic-roughness model, as -v lists them.
std::string LayerNote(const vkpt::MaterialInfo& m) {
  char note[512] = "";  // room for every layer at once
  int n = 0;
  if (m.clearcoat > 0.0f)
    n +=
        std::snprintf(note + n, sizeof note - n, " clearcoat %.3g (roughness %.3g)", m.clearcoat, m.clearcoatRoughness);
  if (m.sheenColor != vkpt::Rgb{})
    n += std::snprintf(note + n, sizeof note - n, " sheen (%.3g, %.3g, %.3g) roughness %.3g", m.sheenColor[0],
                       m.sheenColor[1], m.sheenColor[2], m.sheenRoughness);
  if (m.diffuseTransmission > 0.0f)
    n +=
        std::snprintf(note + n, sizeof note - n, " diffuse transmission %.3g (%.3g, %.3g, %.3g)", m.diffuseTransmission,
                      m.diffuseTransmissionColor[0], m.diffuseTransmissionColor[1], m.diffuseTransmissionColor[2]);
  if (m.anisotropyStrength > 0.0f)
    n += std::snprintf(note + n, sizeof note - n, " anisotropy %.3g (rotation %.3g rad)", m.anisotropyStrength,
                       m.anisotropyRotation);
  if (m.dispersion > 0.0f)
    n += std::snprintf(note + n, sizeof note - n, " dispersion %.3g (Abbe number %.3g%s)", m.dispersion,
                       20.0f / m.dispersion,
                       RefractsAsVolume(m) ? "" : "; unseen: it needs a transmissive volume of ior > 1");
  if (m.iridescence > 0.0f) {
    // Without a thickness texture the film is as thick as its maximum.
    float thin = m.textures.count("iridescenceThickness") ? m.iridescenceThicknessMin : m.iridescenceThicknessMax;
    std::snprintf(note + n, sizeof note - n, " iridescence %.3g (ior %.3g, %.4g-%.4g nm)", m.iridescence,
                  m.iridescenceIor, thin, m.iridescenceThicknessMax);
  }
  return note;
}

std::string DiffPath(const std::string& out) {
  size_t dot = out.find_last_of('.');
  return out.substr(0, dot) + "-diff.png";
}

// Why the render stopped, as the user asked for it.
std::string StopReasonText(const RenderedFrame& frame, const Options& o) {
  char why[96];
  switch (frame.stoppedBy) {
    case StopReason::kTime: std::snprintf(why, sizeof why, "--time %g s", *o.api.render.seconds); break;
    case StopReason::kNoiseTarget:
      std::snprintf(why, sizeof why, "--noise-target %g", *o.api.render.noiseTarget);
      break;
    case StopReason::kConverged: std::snprintf(why, sizeof why, "every pixel converged (--adaptive)"); break;
    case StopReason::kSignal:
      std::snprintf(why, sizeof why, "%s", GracefulStop::Signal() == SIGTERM ? "SIGTERM" : "SIGINT");
      break;
    default: std::snprintf(why, sizeof why, "--spp %u", o.Budget().spp); break;
  }
  return why;
}

void PrintSceneLine(const vkpt::SceneStats& scene) {
  const vkpt::BvhInfo& bvh = scene.bvh;
  char choice[96] = "";
  if (bvh.rejectedSahCost > 0.0)
    std::snprintf(choice, sizeof choice, " (auto: %s splits' SAH cost was %.3f)",
                  bvh.splits == "spatial" ? "object" : "spatial", bvh.rejectedSahCost);
  std::printf(
      "  scene: %llu triangles (%llu degenerate skipped), %llu emissive; BVH: %s splits%s, %u nodes, %u leaves, "
      "depth %u, %u triangle references, SAH cost %.3f, built in %.2f ms\n",
      (unsigned long long)scene.triangles, (unsigned long long)scene.degenerateTriangles,
      (unsigned long long)scene.lights, bvh.splits.c_str(), choice, bvh.nodes, bvh.leaves, bvh.depth, bvh.references,
      bvh.sahCost, bvh.buildMs);
  if (scene.textures)
    std::printf("  textures: %llu, %s with their mip levels\n", (unsigned long long)scene.textures,
                FormatBytes(scene.textureBytes).c_str());
}

// The ranks of an MPI job, the AOVs and the denoised image.
void PrintOutputs(const RenderedFrame& frame, const Options& o, const std::vector<std::string>& files,
                  const char* denoiser) {
  for (const RankShare& rank : frame.ranks)
    std::printf("  %s: %u chunk(s) in %.3f s, %s sent\n", rank.name.c_str(), rank.chunks, rank.renderSeconds,
                FormatBytes(rank.bytesSent).c_str());
  if (!o.api.render.aovs.empty()) {
    std::string names, written;
    for (const std::string& aov : o.api.render.aovs) names += (names.empty() ? "" : ", ") + aov;
    for (size_t k = 1; k < files.size(); ++k) written += std::string(written.empty() ? "" : ", ") + files[k];
    if (written.empty()) written = o.out;
    std::printf("  AOVs: %s (%u samples per pixel, %.3f s) in %s\n", names.c_str(), frame.aovs.samples,
                frame.aovSeconds, written.c_str());
  }
  if (frame.denoised)
    std::printf("  denoised (à-trous, %s) in %.3f s; the raw image is %s\n", denoiser, frame.denoiseSeconds,
                files.back().c_str());
}

void PrintMaterial(const vkpt::MaterialInfo& m) {
  std::printf(
      "  material %u \"%s\": baseColor (%.4g, %.4g, %.4g) metallic %.3g roughness %.3g specular %.3g ior %.3g "
      "transmission %.3g%s emission (%.6g, %.6g, %.6g)%s%s%s%s\n",
      m.index, m.name.c_str(), m.baseColor[0], m.baseColor[1], m.baseColor[2], m.metallic, m.roughness, m.specular,
      m.ior, m.transmission, m.volume ? " (volume)" : "", m.emission[0], m.emission[1], m.emission[2],
      LayerNote(m).c_str(), m.doubleSided ? " double-sided" : "", m.unlit ? " unlit" : "", AlphaNote(m).c_str());
}

void PrintCamera(const vkpt::CameraInfo& cam, size_t cameras) {
  char which[16] = "default";
  if (cameras) std::snprintf(which, sizeof which, "#%u", cam.index);
  std::printf("  cameras: %zu; using %s \"%s\" at (%.6g, %.6g, %.6g) looking (%.4g, %.4g, %.4g), %s %.4g\n", cameras,
              which, cam.name.c_str(), cam.position[0], cam.position[1], cam.position[2], cam.forward[0],
              cam.forward[1], cam.forward[2], cam.orthographic ? "orthographic ymag" : "perspective yfov(deg)",
              cam.orthographic ? cam.ymag : cam.yfovDegrees);
}

// The file's variants and animations, and which of them the scene is rendered with.
void PrintChoices(const vkpt::Scene& scene, const vkpt::SceneStats& stats) {
  const std::vector<std::string> variants = scene.Variants();
  if (!variants.empty()) {
    std::printf("  material variants (--variant NAME|INDEX):");
    for (size_t i = 0; i < variants.size(); ++i) std::printf("%s %zu \"%s\"", i ? "," : "", i, variants[i].c_str());
    std::printf("; rendering %s\n",
                stats.variant ? ("\"" + variants[*stats.variant] + "\"").c_str() : "the default materials");
  }
  const std::vector<vkpt::AnimationInfo> animations = scene.Animations();
  if (!animations.empty()) {
    std::printf("  animations (--animation NAME|INDEX, --at SECONDS):");
    for (const vkpt::AnimationInfo& a : animations)
      std::printf("%s %u \"%s\" %.6g s", a.index ? "," : "", a.index, a.name.c_str(), a.duration);
    if (!stats.animation) std::printf("; posing none (the nodes' own transforms)\n");
    else std::printf("; posing %u at %.6g s\n", *stats.animation, stats.animationTime);
  }
}

}  // namespace

void PrintLoadReport(const vkpt::Scene& scene, const vkpt::CameraInfo& cam) {
  const vkpt::SceneStats stats = scene.Stats();
  const std::vector<vkpt::MaterialInfo> materials = scene.Materials();
  std::printf("scene: %s\n", stats.path.c_str());
  std::printf("  triangles: %llu, materials: %zu (incl. default), lights: %llu\n", (unsigned long long)stats.triangles,
              materials.size(), (unsigned long long)stats.lights);
  for (const vkpt::MaterialInfo& m : materials) PrintMaterial(m);
  if (stats.vertexColors) std::printf("  vertex colours (COLOR_0): multiply the base colour\n");
  if (stats.textures)
    std::printf("  textures: %llu from %llu images, %llu texels at level 0\n", (unsigned long long)stats.textures,
                (unsigned long long)stats.images, (unsigned long long)stats.texels);
  if (stats.generatedTangentPrimitives > 0)
    std::printf("  tangents: generated (MikkTSpace) for %u normal-mapped primitive(s) without TANGENT\n",
                stats.generatedTangentPrimitives);
  std::printf("  bounds: (%.6g, %.6g, %.6g) .. (%.6g, %.6g, %.6g)\n", stats.boundsMin[0], stats.boundsMin[1],
              stats.boundsMin[2], stats.boundsMax[0], stats.boundsMax[1], stats.boundsMax[2]);
  PrintCamera(cam, scene.CameraCount());
  std::printf("  memory: %s counted for the scene, of --max-memory %s\n", FormatBytes(stats.memoryCounted).c_str(),
              FormatBytes(stats.memoryLimit).c_str());
  PrintChoices(scene, stats);
  for (const std::string& w : stats.warnings) std::printf("  warning: %s\n", w.c_str());
  for (const std::string& f : stats.ignoredFeatures) std::printf("  ignored: %s\n", f.c_str());
}

std::function<void(double)> ProgressLine() {
  if (!isatty(STDERR_FILENO)) return {};
  return [](double f) { std::fprintf(stderr, "\rrendering: %5.1f%%", 100.0 * f); };
}

void EndProgressLine() {
  if (isatty(STDERR_FILENO)) std::fprintf(stderr, "\r%*s\r", 20, "");
}

void PrintRenderReport(const vkpt::SceneStats& scene, const RenderedFrame& frame, const Options& o,
                       const std::vector<std::string>& files, const char* denoiser) {
  const Image& image = frame.image;
  glm::dvec3 mean(0.0);
  for (const glm::vec3& px : image.pixels) mean += glm::dvec3(px);
  mean /= double(image.pixels.size());
  std::printf("vkpt: %s -> %s: %ux%u, %u spp, %s\n", o.scene.c_str(), o.out.c_str(), image.width, image.height,
              frame.spp, frame.engine.c_str());
  std::printf("  stopped by %s after %zu pass(es); estimated relMSE %.4g", StopReasonText(frame, o).c_str(),
              frame.sppPerPass.size(), frame.estimatedRelMse);
  const double samples = double(frame.samples);
  if (o.Budget().adaptive)
    std::printf("; adaptive: %.2f spp per pixel on average, %llu pixels still active", samples / image.pixels.size(),
                (unsigned long long)frame.activePixels);
  std::printf("\n  time %.3f s, %.3f Msamples/s, %.3f Mrays/s, mean radiance (%.6g, %.6g, %.6g)\n", frame.seconds,
              samples / frame.seconds * 1e-6, double(frame.sums.rays) / frame.seconds * 1e-6, mean.x, mean.y, mean.z);
  PrintSceneLine(scene);
  if (frame.sums.nonFinite)
    std::printf("  warning: %llu non-finite samples were discarded\n", (unsigned long long)frame.sums.nonFinite);
  if (frame.sums.cutShort)
    std::fprintf(stderr,
                 "vkpt: warning: %llu samples came near lavapipe's limit of 65535 loop iterations per SIMD group "
                 "and may have been cut short (image biased dark); use --backend cpu or a smaller --max-depth\n",
                 (unsigned long long)frame.sums.cutShort);
  PrintOutputs(frame, o, files, denoiser);
}

int CompareBackends(const RenderedFrame& reference, const RenderedFrame& frame, const Options& o) {
  ImageComparison c = CompareImages(reference.image, frame.image);
  WriteImage(DifferenceHeatmap(reference.image, frame.image), DiffPath(o.out));
  std::printf("vkpt: --compare: A = %s (%.3f s), B = %s (%.3f s), seed %u\n%s\n  heat map: %s\n",
              reference.engine.c_str(), reference.seconds, frame.engine.c_str(), frame.seconds, o.api.render.seed,
              c.Summary().c_str(), DiffPath(o.out).c_str());
  if (c.lockstepAgree && c.statisticallyAgree) return 0;
  std::fprintf(stderr, "vkpt: --compare: the CPU and Vulkan images DISAGREE\n");
  return 4;
}

}  // namespace vkpt::internal
