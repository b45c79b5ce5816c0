// A render taken in steps (vkpt::ProgressiveRender): the view begun as Render begins it,
// its samples added through the same passes and chunks, and its result made by the
// session's last steps (the AOV pass, the filter) from the sums so far — so that n
// samples give Render's image at spp n, bit for bit.
#include <algorithm>
#include <chrono>
#include <utility>

#include "session/budget.h"
#include "session/local_passes.h"
#include "vkpt/caller_log.h"
#include "vkpt/client.h"
#include "vkpt/public_result.h"
#include "vkpt/scene_access.h"

namespace vkpt {

struct ProgressiveRender::Impl {
  Impl(Scene& scene, const vkpt::Camera& camera, const RenderOptions& o)
      : loaded(SceneAccess::Engine(scene)),
        options(o),
        log(SceneAccess::Options(scene).log),
        client(internal::LoggedView(log)),
        begun(internal::BeginView(scene, camera, options, client)),
        source(*begun.renderer, options.chunkSpp),
        settings(internal::SessionOf(loaded, begun, options, client)),
        maxSpp(options.spp.value_or(internal::kBudgetMaxSpp)) {}

  internal::LoadedScene& loaded;
  const RenderOptions options;
  const LogCallback log;
  const internal::ClientView client;
  internal::BegunView begun;
  internal::LocalPasses source;  // over begun.renderer
  const internal::SessionSettings settings;
  const uint32_t maxSpp;
  uint32_t done = 0;
  bool cancelled = false;  // the last Advance stopped short
  double seconds = 0.0;
};

namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Held by the call that uses it, should a callback of the call end it meanwhile.
std::shared_ptr<ProgressiveRender::Impl> Live(const std::weak_ptr<ProgressiveRender::Impl>& impl) {
  std::shared_ptr<ProgressiveRender::Impl> live = impl.lock();
  if (!live)
    throw Error("this progressive render has ended: its scene began another, rendered, updated or was destroyed");
  return live;
}

}  // namespace

ProgressiveRender::ProgressiveRender(std::weak_ptr<Impl> impl) : impl_(std::move(impl)) {}
ProgressiveRender::~ProgressiveRender() = default;
ProgressiveRender::ProgressiveRender(ProgressiveRender&&) noexcept = default;
ProgressiveRender& ProgressiveRender::operator=(ProgressiveRender&&) noexcept = default;

ProgressiveRender Scene::Begin(const vkpt::Camera& camera, const RenderOptions& options) {
  return internal::Translated([&] {
    if (options.seconds || options.noiseTarget || options.adaptive.value_or(false))
      throw SettingError(
          "a progressive render takes the samples Advance asks for: seconds, noiseTarget and adaptive are Render's");
    impl_->progressive = std::make_shared<ProgressiveRender::Impl>(*this, camera, options);
    return ProgressiveRender(impl_->progressive);
  });
}

uint32_t ProgressiveRender::Advance(uint32_t spp) {
  return internal::Translated([&] {
    const std::shared_ptr<Impl> held = Live(impl_);
    Impl& r = *held;
    const Clock::time_point t0 = Clock::now();
    const uint32_t limit = r.done + std::min(spp, r.maxSpp - r.done);
    internal::SampleRequest request;
    request.limit = limit;
    request.stop = r.options.cancel;
    if (r.options.progress) request.progress = [&](double at) { r.options.progress(at / r.maxSpp); };
    const uint32_t validationBefore = r.loaded.Device() ? r.loaded.Device()->ValidationMessages() : 0;
    r.cancelled = false;
    while (r.done < limit && !r.cancelled) {
      request.done = r.done;
      const uint32_t n = r.source.Advance(request);
      r.done += n;
      r.cancelled = n == 0;  // before the limit, only a stop takes nothing
    }
    r.seconds += Since(t0);
    const uint32_t validation = r.loaded.Device() ? r.loaded.Device()->ValidationMessages() - validationBefore : 0;
    if (validation && r.log)
      r.log(LogLevel::Warning, std::to_string(validation) + " Vulkan validation message(s) in this render");
    return r.done;
  });
}

uint32_t ProgressiveRender::Spp() const {
  return internal::Translated([&] { return Live(impl_)->done; });
}

uint32_t ProgressiveRender::MaxSpp() const {
  return internal::Translated([&] { return Live(impl_)->maxSpp; });
}

CameraInfo ProgressiveRender::Camera() const {
  return internal::Translated([&] { return internal::CameraOf(Live(impl_)->begun); });
}

RenderResult ProgressiveRender::Result() {
  return internal::Translated([&] {
    const std::shared_ptr<Impl> held = Live(impl_);
    Impl& r = *held;
    internal::RenderedFrame frame;
    frame.sums = r.source.Sums();
    internal::ResolveSums(frame);
    frame.spp = r.done;
    frame.engine = r.source.Engine();
    frame.seconds = r.seconds;
    internal::FinishFrame(r.source, r.settings, frame);  // a whole AOV pass and the filter
    internal::RenderedView rendered = internal::Resolved(r.loaded, r.begun, std::move(frame));
    RenderResult result = internal::PublicResult(r.begun, rendered);
    result.stoppedBy = r.done == r.maxSpp ? "spp" : r.cancelled ? "cancelled" : "";
    r.seconds = result.seconds;
    return result;
  });
}

}  // namespace vkpt
