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
std::string AlphaNote(const Material& m) {
  char note[64] = "";
  if (m.alphaMode == AlphaMode::kMask)
    std::snprintf(note, sizeof note, " alpha MASK %.3g (cutoff %.3g)", m.alpha, m.alphaCutoff);
  else if (m.alphaMode == AlphaMode::kBlend) std::snprintf(note, sizeof note, " alpha BLEND %.3g", m.alpha);
  return note;
}

// The layers and lobes a material adds to the metallic-roughness model, as -v lists them.
std::string LayerNote(const Material& m) {
  char note[512] = "";  // room for every layer at once
  int n = 0;
  if (m.clearcoat > 0.0f)
    n +=
        std::snprintf(note + n, sizeof note - n, " clearcoat %.3g (roughness %.3g)", m.clearcoat, m.clearcoatRoughness);
  if (m.sheenColor != glm::vec3(0.0f))
    n += std::snprintf(note + n, sizeof note - n, " sheen (%.3g, %.3g, %.3g) roughness %.3g", m.sheenColor.x,
                       m.sheenColor.y, m.sheenColor.z, m.sheenRoughness);
  if (m.diffuseTransmission > 0.0f)
    n +=
        std::snprintf(note + n, sizeof note - n, " diffuse transmission %.3g (%.3g, %.3g, %.3g)", m.diffuseTransmission,
                      m.diffuseTransmissionColor.x, m.diffuseTransmissionColor.y, m.diffuseTransmissionColor.z);
  if (m.anisotropyStrength > 0.0f)
    n += std::snprintf(note + n, sizeof note - n, " anisotropy %.3g (rotation %.3g rad)", m.anisotropyStrength,
                       m.anisotropyRotation);
  if (m.dispersion > 0.0f)
    n += std::snprintf(note + n, sizeof note - n, " dispersion %.3g (Abbe number %.3g%s)", m.dispersion,
                       20.0f / m.dispersion,
                       m.RefractsAsVolume() ? "" : "; unseen: it needs a transmissive volume of ior > 1");
  if (m.iridescence > 0.0f) {
    // Without a thickness texture the film is as thick as its maximum.
    float thin =
        m.texture(TextureSlot::kIridescenceThickness).Present() ? m.iridescenceThicknessMin : m.iridescenceThicknessMax;
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

void PrintSceneLine(const Scene& scene, const RenderScene& rs) {
  const BvhStats& bvh = rs.bvhStats;
  const char* kind = bvh.spatialSplits ? "spatial" : "object";
  char choice[96] = "";
  if (bvh.rejectedSahCost > 0.0)
    std::snprintf(choice, sizeof choice, " (auto: %s splits' SAH cost was %.3f)",
                  bvh.spatialSplits ? "object" : "spatial", bvh.rejectedSahCost);
  std::printf(
      "  scene: %zu triangles (%u degenerate skipped), %zu emissive; BVH: %s splits%s, %u nodes, %u leaves, "
      "depth %u, %u triangle references, SAH cost %.3f, built in %.2f ms\n",
      scene.triangles.size(), rs.degenerateTriangles, rs.lights.size(), kind, choice, bvh.nodes, bvh.leaves, bvh.depth,
      bvh.references, bvh.sahCost, bvh.buildMs);
  if (!rs.textures.empty())
    std::printf("  textures: %zu, %s with their mip levels\n", rs.textures.size(),
                FormatBytes(rs.texels.size() * sizeof(uint32_t)).c_str());
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

}  // namespace

void PrintLoadReport(const Scene& scene, const RenderScene& rs, const Camera& cam, uint32_t camIndex) {
  std::printf("scene: %s\n", scene.path.c_str());
  std::printf("  triangles: %zu, materials: %zu (incl. default), lights: %zu\n", scene.triangles.size(),
              scene.materials.size(), rs.lights.size());
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    std::printf(
        "  material %zu \"%s\": baseColor (%.4g, %.4g, %.4g) metallic %.3g roughness %.3g specular %.3g ior %.3g "
        "transmission %.3g%s emission (%.6g, %.6g, %.6g)%s%s%s%s\n",
        i, scene.materialNames[i].c_str(), m.baseColor.x, m.baseColor.y, m.baseColor.z, m.metallic, m.roughness,
        m.specular, m.ior, m.transmission, m.volume ? " (volume)" : "", m.emission.x, m.emission.y, m.emission.z,
        LayerNote(m).c_str(), m.doubleSided ? " double-sided" : "", m.unlit ? " unlit" : "", AlphaNote(m).c_str());
  }
  if (!scene.colors.empty()) std::printf("  vertex colours (COLOR_0): multiply the base colour\n");
  if (!scene.textures.empty()) {
    uint64_t texels = 0;
    for (const TextureImage& im : scene.images) texels += uint64_t(im.width) * im.height;
    std::printf("  textures: %zu from %zu images, %llu texels at level 0\n", scene.textures.size(), scene.images.size(),
                (unsigned long long)texels);
  }
  if (scene.generatedTangentPrimitives > 0)
    std::printf("  tangents: generated (MikkTSpace) for %u normal-mapped primitive(s) without TANGENT\n",
                scene.generatedTangentPrimitives);
  std::printf("  bounds: (%.6g, %.6g, %.6g) .. (%.6g, %.6g, %.6g)\n", scene.bounds.lo.x, scene.bounds.lo.y,
              scene.bounds.lo.z, scene.bounds.hi.x, scene.bounds.hi.y, scene.bounds.hi.z);
  char which[16] = "default";
  if (!scene.cameras.empty()) std::snprintf(which, sizeof which, "#%u", camIndex);
  std::printf("  cameras: %zu; using %s \"%s\" at (%.6g, %.6g, %.6g) looking (%.4g, %.4g, %.4g), %s %.4g\n",
              scene.cameras.size(), which, cam.name.c_str(), cam.position.x, cam.position.y, cam.position.z,
              cam.forward.x, cam.forward.y, cam.forward.z,
              cam.orthographic ? "orthographic ymag" : "perspective yfov(deg)",
              cam.orthographic ? cam.ymag : cam.yfov * 180.0 / M_PI);
  std::printf("  memory: %s counted for the scene, of --max-memory %s\n", FormatBytes(scene.memoryCounted).c_str(),
              FormatBytes(scene.memoryLimit).c_str());
  if (!scene.materialVariants.empty()) {
    std::printf("  material variants (--variant NAME|INDEX):");
    for (size_t i = 0; i < scene.materialVariants.size(); ++i)
      std::printf("%s %zu \"%s\"", i ? "," : "", i, scene.materialVariants[i].c_str());
    std::printf("; rendering %s\n", scene.variant < 0 ? "the default materials"
                                                      : ("\"" + scene.materialVariants[scene.variant] + "\"").c_str());
  }
  if (!scene.animations.empty()) {
    std::printf("  animations (--animation NAME|INDEX, --at SECONDS):");
    for (size_t i = 0; i < scene.animations.size(); ++i)
      std::printf("%s %zu \"%s\" %.6g s", i ? "," : "", i, scene.animations[i].name.c_str(),
                  scene.animations[i].duration);
    if (scene.animation < 0) std::printf("; posing none (the nodes' own transforms)\n");
    else std::printf("; posing %zu at %.6g s\n", size_t(scene.animation), scene.animationTime);
  }
  for (const std::string& w : scene.warnings) std::printf("  warning: %s\n", w.c_str());
  for (const std::string& f : scene.ignoredFeatures) std::printf("  ignored: %s\n", f.c_str());
}

std::function<void(double)> ProgressLine() {
  if (!isatty(STDERR_FILENO)) return {};
  return [](double f) { std::fprintf(stderr, "\rrendering: %5.1f%%", 100.0 * f); };
}

void EndProgressLine() {
  if (isatty(STDERR_FILENO)) std::fprintf(stderr, "\r%*s\r", 20, "");
}

void PrintRenderReport(const Scene& scene, const RenderScene& rs, const RenderedFrame& frame, const Options& o,
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
  PrintSceneLine(scene, rs);
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
