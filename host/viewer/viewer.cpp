#include "viewer/viewer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include "viewer/display_pixels.h"
#include "viewer/view_camera.h"
#include "window/presenter.h"
#include "window/window_input.h"

namespace vkpt::internal {
namespace {

using Clock = std::chrono::steady_clock;

// How long the camera must rest before the render goes back to full size.
constexpr double kRestSeconds = 0.3;
// While moving: this fraction of each side, 1 sample per pixel.
constexpr uint32_t kPreviewDivisor = 4;
// Flying crosses this fraction of the scene's radius a second.
constexpr double kFlySpeed = 0.5;
// Samples per step grow while a step takes less than this, and shrink above twice it.
constexpr double kStepSeconds = 0.05;

double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

SceneBox BoxOf(const vkpt::SceneStats& stats) {
  const vkpt::Vec3 &lo = stats.boundsMin, &hi = stats.boundsMax;
  return {glm::dvec3(lo[0], lo[1], lo[2]), glm::dvec3(hi[0], hi[1], hi[2])};
}

// New pictures and the seconds they took: the render begun (while moving), its samples,
// its image and its showing.
struct FrameCount {
  uint32_t frames = 0;
  double seconds = 0.0;
  void Add(double s) { ++frames, seconds += s; }
  double Rate() const { return seconds > 0.0 ? frames / seconds : 0.0; }
};

class Viewer {
 public:
  explicit Viewer(const ViewerSettings& s)
      : opened_(Clock::now()),
        s_(s),
        scene_(s.scene, s.sceneOptions),
        box_(BoxOf(scene_.Stats())),
        base_(s.camera),
        panel_(StartPanel(scene_, s.render, s.display)) {
    // The first render's size (a missing side from the camera's aspect) is the window's.
    Begin(false, RenderOptionsOf(s.render, panel_));
    const vkpt::RenderResult first = render_->Result();
    size_ = {first.image.width, first.image.height};
    presenter_ = std::make_unique<Presenter>("vkpt: " + std::filesystem::path(s.scene).filename().string(), size_.x,
                                             size_.y, "", s.sceneOptions.validation);
    input_ = std::make_unique<InputRecorder>(presenter_->Window());
    say("vkpt: drag to orbit, right-drag to pan, wheel to dolly, W/A/S/D/Q/E to fly; F frames the scene, C "
        "cycles the file's cameras, R resets, P saves, Escape quits; the settings are in the top-left corner");
  }

  int Run() {
    Clock::time_point last = Clock::now();
    while (true) {
      const double dt = Since(last);  // the last frame's
      last = Clock::now();
      const bool refining = render_->Spp() < render_->MaxSpp() || preview_ || panel_.playing;
      const WindowInput in = input_->Poll(refining ? 0.0 : 0.05);
      if (presenter_->ShouldClose() || (s_.stop && s_.stop()) || !Keys(in.keys)) break;
      Move(in, dt);
      Overlay(dt);
      const Clock::time_point t0 = Clock::now();
      Restart(in.dragging || Since(lastChange_) < kRestSeconds);
      const bool fresh = Refine();
      if (!pixels_.empty()) presenter_->Show(pixels_, shownSize_.x, shownSize_.y);
      if (fresh) (preview_ ? moving_ : resting_).Add(Since(t0));
      if (fresh && firstPicture_ == 0.0) firstPicture_ = Since(opened_);
    }
    Summary();
    return 0;
  }

 private:
  void say(const std::string& line) const {
    if (s_.say) s_.say(line);
  }

  // The view the camera controls start from: moved, or the base camera as rendered.
  ViewCamera Current() const { return moved_ ? *moved_ : FromCamera(render_->Camera(), box_); }

  void Changed(const ViewCamera& view) {
    moved_ = view;
    Moved();
  }
  void Moved() {
    lastChange_ = Clock::now();
    dirty_ = true;
  }

  // F, C, R, P and Escape; false to quit.
  bool Keys(const std::string& keys) {
    for (const char key : keys) {
      if (key == '\x1b') return false;
      if (key == 'F') Changed(FrameAll(Current(), box_, double(size_.x) / std::max(size_.y, 1u)));
      if (key == 'C' || key == 'R') {
        base_ = s_.camera;
        if (key == 'C' && scene_.CameraCount() > 0) {
          camera_ = (camera_ + 1) % scene_.CameraCount();
          base_ = vkpt::Camera{};
          base_.index = camera_;
        }
        moved_.reset();
        dirty_ = true;
      }
      if (key == 'P') Save();
    }
    return true;
  }

  void Move(const WindowInput& in, double dt) {
    const double height = std::max(presenter_->FramebufferSize().y, 1u);
    if (in.orbit != glm::dvec2(0.0)) Changed(Orbit(Current(), in.orbit, height));
    if (in.pan != glm::dvec2(0.0)) Changed(Pan(Current(), in.pan, height));
    if (in.wheel != 0.0) Changed(Dolly(Current(), in.wheel));
    if (in.fly != glm::dvec3(0.0)) Changed(Fly(Current(), in.fly * (kFlySpeed * box_.Radius() * std::min(dt, 0.1))));
  }

  // The overlay's rows drawn, and what the user changed in them applied; a playing
  // animation moves on by `dt`, rendered as a moving camera is.
  void Overlay(double dt) {
    presenter_->BeginOverlay();
    std::vector<PanelRow> rows = PanelRows(panel_, stats_);
    DrawPanel("settings", rows);
    PanelChange change = ApplyPanel(rows, panel_);
    if (panel_.playing) change.scene["time"] = panel_.time = AdvanceTime(panel_, dt);
    if (change.display) Display();
    if (change.render) dirty_ = true;
    if (change.scene.empty()) return;
    try {
      scene_.Update(change.scene);
      stats_.refused.clear();
    } catch (const vkpt::Error& e) {
      stats_.refused = std::string("refused: ") + e.what();
      ReadScene(scene_, panel_);
    }
    Moved();
  }

  // A new render when the view or the window changed, or the camera came to rest.
  void Restart(bool moving) {
    const glm::uvec2 framebuffer = presenter_->FramebufferSize();
    if (framebuffer.x == 0 || framebuffer.y == 0) return;  // minimised
    if (framebuffer != size_) {
      size_ = framebuffer;
      dirty_ = true;
    }
    if (!dirty_ && !(preview_ && !moving) && render_) return;
    vkpt::RenderOptions options = RenderOptionsOf(s_.render, panel_);
    options.width = size_.x;
    options.height = size_.y;
    if (moving) {
      options.width = std::max(size_.x / kPreviewDivisor, 1u);
      options.height = std::max(size_.y / kPreviewDivisor, 1u);
      options.spp = 1;
      options.denoise = false;
    }
    Begin(moving, options);
  }

  void Begin(bool preview, const vkpt::RenderOptions& options) {
    render_.reset();  // the last render's device memory first
    render_ = std::make_unique<vkpt::ProgressiveRender>(scene_.Begin(moved_ ? moved_->ForRender() : base_, options));
    preview_ = preview;
    dirty_ = false;
    step_ = 1;
    began_ = Clock::now();
  }

  // One step of samples, sized to keep the window responsive, and the picture made anew;
  // false when the render has all its samples.
  bool Refine() {
    if (render_->Spp() >= render_->MaxSpp()) return false;
    const Clock::time_point t0 = Clock::now();
    render_->Advance(step_);
    last_ = render_->Result();
    const double seconds = Since(t0);
    if (seconds < kStepSeconds) step_ = std::min(step_ * 2, 64u);
    if (seconds > 2.0 * kStepSeconds) step_ = std::max(step_ / 2, 1u);
    stats_.spp = last_.spp;
    stats_.maxSpp = render_->MaxSpp();
    stats_.seconds = Since(began_);
    stats_.samplesPerSecond = last_.samples / std::max(stats_.seconds, 1e-9);
    stats_.relMse = last_.estimatedRelMse;
    stats_.engine = last_.engine;
    Display();
    return true;
  }

  // The last result as the panel says to show it.
  void Display() {
    const auto aov = last_.aovs.find(panel_.aov);
    pixels_ =
        aov != last_.aovs.end() ? DisplayAov(aov->second, panel_.aov) : DisplayPixels(last_.image, panel_.display);
    shownSize_ = {last_.image.width, last_.image.height};
  }

  void Summary() const {
    char line[256];
    std::snprintf(line, sizeof line,
                  "vkpt: viewer closed after %.1f s (the first picture after %.2f s): %u pictures while the camera "
                  "moved (%.1f a second, %u x %u), %u at rest (%.1f a second); the last view at %u spp",
                  Since(opened_), firstPicture_, moving_.frames, moving_.Rate(),
                  std::max(size_.x / kPreviewDivisor, 1u), std::max(size_.y / kPreviewDivisor, 1u), resting_.frames,
                  resting_.Rate(), render_->Spp());
    say(line);
  }

  // P: the render so far as PNG and EXR, and the command that renders it again.
  void Save() {
    if (preview_) {
      say("vkpt: P saves a resting view; let the camera rest first");
      return;
    }
    const std::filesystem::path png = s_.savePath, exr = std::filesystem::path(s_.savePath).replace_extension(".exr");
    const std::string view = ViewName(panel_.display.view);
    vkpt::Save(last_, png.string(), view, panel_.display.exposure);
    vkpt::Save(last_, exr.string(), view, panel_.display.exposure);
    say("vkpt: saved " + png.string() + " and " + exr.string() + " at " + std::to_string(last_.spp) + " spp");
    ViewedFrame frame{std::nullopt, last_.spp, last_.image.width, last_.image.height, panel_};
    if (moved_) frame.camera = moved_->ForRender();
    else if (base_.index) frame.camera = base_;
    if (s_.batchCommand) say(s_.batchCommand(frame));
  }

  const Clock::time_point opened_;  // before the scene loads
  const ViewerSettings& s_;
  vkpt::Scene scene_;
  const SceneBox box_;
  vkpt::Camera base_;                // the file's camera or the first view, unmoved
  std::optional<ViewCamera> moved_;  // since the user moved it
  uint32_t camera_ = 0;              // the file's camera C showed last
  PanelSettings panel_;
  PanelStats stats_;
  std::unique_ptr<vkpt::ProgressiveRender> render_;
  vkpt::RenderResult last_;  // render_'s, as last shown
  bool preview_ = false;     // render_ is a moving camera's small 1-spp frame
  bool dirty_ = false;       // the view changed since render_ began
  uint32_t step_ = 1;
  Clock::time_point lastChange_{}, began_{};
  glm::uvec2 size_{0};  // of the full-size render: the framebuffer's
  std::unique_ptr<Presenter> presenter_;
  std::unique_ptr<InputRecorder> input_;
  std::vector<uint8_t> pixels_;
  glm::uvec2 shownSize_{0};
  double firstPicture_ = 0.0;  // seconds from opened_ to the first picture shown
  FrameCount moving_, resting_;
};

}  // namespace

int RunViewer(const ViewerSettings& settings) { return Viewer(settings).Run(); }

}  // namespace vkpt::internal
