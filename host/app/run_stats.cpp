#include "app/run_stats.h"

#include <cinttypes>
#include <cstdio>

#include "app/json_object.h"
#include "app/option_table.h"

namespace vkpt::internal {
namespace {

std::string Vec3(double x, double y, double z) { return JsonArray({JsonNumber(x), JsonNumber(y), JsonNumber(z)}); }

std::string Strings(const std::vector<std::string>& v) {
  std::vector<std::string> quoted;
  for (const std::string& s : v) quoted.push_back(JsonString(s));
  return JsonArray(quoted);
}

// Every option as given or defaulted (app/option_table.cpp); absent optional ones are null.
JsonObject OptionsJson(const Options& o) {
  JsonObject j;
  for (const OptionDef& def : OptionTable())
    if (def.how.json) j.Raw(def.StatsKey(), def.how.json(o));
  return j;
}

JsonObject SceneJson(const vkpt::Scene& scene, const vkpt::SceneStats& stats) {
  char hash[32];
  std::snprintf(hash, sizeof hash, "fnv1a64:%016" PRIx64, stats.contentHash);
  JsonObject j;
  j.Str("path", stats.path).Str("content_hash", hash).Int("triangles", stats.triangles);
  j.Int("degenerate_triangles", stats.degenerateTriangles).Int("materials", stats.materials);
  j.Int("lights", stats.lights).Int("cameras", scene.CameraCount());
  j.Int("memory_counted", stats.memoryCounted).Int("memory_limit", stats.memoryLimit);
  j.Raw("material_variant", stats.variant ? JsonString(scene.Variants()[*stats.variant]) : "null");
  j.Raw("animation", stats.animation ? JsonString(scene.Animations()[*stats.animation].name) : "null");
  j.Num("animation_time", stats.animationTime);
  return j;
}

JsonObject BvhJson(const vkpt::BvhInfo& b) {
  JsonObject bvh;
  bvh.Str("splits", b.splits).Int("nodes", b.nodes).Int("leaves", b.leaves);
  bvh.Int("depth", b.depth).Int("references", b.references).Num("sah_cost", b.sahCost).Num("build_ms", b.buildMs);
  return bvh;
}

JsonObject TimesJson(const RunTimes& t) {
  JsonObject times;
  times.Num("load", t.load)
      .Num("environment", t.environment)
      .Num("pose", t.pose)
      .Num("prepare", t.prepare)
      .Num("upload", t.upload);
  times.Num("render", t.render).Num("aov", t.aov).Num("denoise", t.denoise).Num("write", t.write).Num("total", t.total);
  return times;
}

JsonObject MpiJson(const std::vector<RankShare>& shares, uint32_t chunkSpp) {
  std::vector<std::string> ranks;
  for (const RankShare& share : shares) {
    JsonObject rank;
    rank.Str("name", share.name).Int("chunks", share.chunks).Int("bytes_sent", share.bytesSent);
    rank.Num("render_s", share.renderSeconds);
    ranks.push_back(rank.Text());
  }
  JsonObject mpi;
  mpi.Int("ranks", shares.size()).Int("chunk_spp", chunkSpp).Raw("per_rank", JsonArray(ranks));
  return mpi;
}

}  // namespace

std::string OptionsAsJson(const Options& o) { return OptionsJson(o).Text(); }

std::string StatsJson(const Options& o, const RunOutcome& run) {
  const RenderedFrame& p = run.frame;
  const Image& image = p.image;
  const uint64_t samples = p.samples;
  std::vector<std::string> passes;
  for (uint32_t n : p.sppPerPass) passes.push_back(std::to_string(n));
  glm::dvec3 mean(0.0);
  for (const glm::vec3& px : image.pixels) mean += glm::dvec3(px);
  mean /= double(uint64_t(image.width) * image.height);

  const vkpt::SceneStats stats = run.scene.Stats();
  JsonObject j;
  j.Str("vkpt_version", VKPT_VERSION).Obj("scene", SceneJson(run.scene, stats)).Str("device", p.engine);
  j.Obj("options", OptionsJson(o)).Int("seed", o.api.render.seed).Int("width", image.width).Int("height", image.height);
  j.Int("frame_memory_counted", run.frameMemory);
  j.Int("spp", p.spp).Raw("spp_per_pass", JsonArray(passes)).Int("samples", samples);
  j.Str("stopped_by", StopReasonName(p.stoppedBy)).Num("estimated_rel_mse", p.estimatedRelMse);
  j.Int("active_pixels", p.activePixels).Int("checkpoints", p.checkpoints);
  j.Int("checkpoint_failures", p.checkpointFailures);
  const FrameSums& sums = p.sums;
  j.Obj("times_s", TimesJson(run.times)).Int("rays", sums.rays).Num("samples_per_s", double(samples) / p.seconds);
  j.Num("rays_per_s", double(sums.rays) / p.seconds).Raw("mean_radiance", Vec3(mean.x, mean.y, mean.z));
  j.Int("non_finite_samples", sums.nonFinite).Int("cut_short_samples", sums.cutShort);
  j.Obj("bvh", BvhJson(stats.bvh)).Int("aov_samples", p.aovs.samples).Raw("files", Strings(run.files));
  if (!p.ranks.empty()) j.Obj("mpi", MpiJson(p.ranks, o.api.render.chunkSpp));
  if (run.reference) {
    JsonObject ref;
    ref.Str("device", run.reference->engine).Num("render_s", run.reference->seconds);
    j.Obj("compare_reference", ref);
  }
  j.Raw("warnings", Strings(stats.warnings)).Raw("ignored_features", Strings(stats.ignoredFeatures));
  j.Int("validation_messages", run.validationMessages).Int("exit_status", uint64_t(run.exitStatus));
  return j.Text() + "\n";
}

}  // namespace vkpt::internal
