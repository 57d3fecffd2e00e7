#include "ui/app/app.h"

// [SECTION] Includes
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include "ui/gl/gl.h"  // epoxy before GLFW
#include "ui/gl/present.h"
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_platform.h"
#include "ui/app/audience_window.h"
#include "ui/app/app_state.h"
#include "ui/app/layout.h"
#include "ui/app/overflow.h"
#include "ui/app/screenshot.h"
#include "ui/app/settings.h"
#include "ui/app/shortcuts.h"
#include "ui/app/undo.h"
#include "ui/app/script.h"
#include "ui/app/theme.h"
#include "ui/render/backdrop.h"
#include "ui/render/compositor.h"
#include "ui/render/renderer.h"

namespace ew::ui {

namespace {

// [SECTION] The application

// EIGENWALKER_PRESENT=swap: show frames by swapping buffers even where copying only the
// changed rectangles is possible (docs/VIEWER_DESIGN.md, "Frame time").
bool swapRequested() {
  const char* v = std::getenv("EIGENWALKER_PRESENT");
  return v && std::string(v) == "swap";
}

// The saved settings when they are on (nothing otherwise); a problem reading them goes
// to `warning` (logged once the log exists) and the defaults are used.
std::optional<Settings> loadSettings(const AppOptions& options, std::string& warning) {
  if (!options.useSettings || settingsDisabledByEnvironment()) return std::nullopt;
  const auto file = settingsFile();
  if (!file) return std::nullopt;
  try {
    return readSettings(*file);
  } catch (const std::exception& e) {
    warning = e.what();
    return Settings{};
  }
}

int windowDimension(const AppOptions& o, const std::optional<Settings>& st, bool width) {
  const int given = width ? o.width : o.height;
  if (o.sizeGiven || !st || !st->windowWidth || !st->windowHeight) return given;
  const int saved = width ? *st->windowWidth : *st->windowHeight;
  return saved >= 320 && saved <= 16384 ? saved : given;
}

class App {
 public:
  explicit App(const AppOptions& options)
      : options_(options),
        settings_(loadSettings(options, settingsWarning_)),
        window_(createWindow(windowDimension(options, settings_, true), windowDimension(options, settings_, false))),
        imgui_(window_.get()),
        renderer_() {
    state_.log.setEcho(options.script.has_value() || options.screenshot.has_value() || options.benchFrames > 0);
    state_.log.info(gl::describeContext());
    state_.view.uiScale = options.uiScale;
    scripted_ = options.script.has_value() || options.screenshot.has_value() || options.benchFrames > 0;
    if (!options.fullRedraw && !swapRequested()) presenter_ = gl::SubBufferPresenter::forCurrentContext();
    compositor_ = Compositor(options.fullRedraw ? Compositor::Target::FullRedraw
                             : presenter_       ? Compositor::Target::Window
                                                : Compositor::Target::Layer);
    compositor_.setChecking(options.checkRepaint);
    glfwSwapInterval(scripted_ ? 0 : 1);
    if (options.script) runner_ = ScriptRunner(readScript(*options.script), options.script->string());
    std::vector<std::filesystem::path> data = options.data;
    if (settings_) {
      applySettings(state_, *settings_);
      if (options.uiScaleGiven) state_.view.uiScale = options.uiScale;
      if (const auto file = settingsFile()) state_.log.info("settings: " + file->string());
      if (data.empty() && !settings_->data.empty()) {
        std::vector<std::filesystem::path> last(settings_->data.begin(), settings_->data.end());
        std::error_code ec;
        const bool allThere = std::all_of(last.begin(), last.end(),
                                          [&ec](const auto& p) { return std::filesystem::exists(p, ec); });
        if (allThere) {
          data = std::move(last);
        } else {
          state_.log.warning("settings: the data last opened is gone; opening the synthetic default");
        }
      }
    }
    if (!settingsWarning_.empty()) state_.log.warning(settingsWarning_);
    actions::open(state_, data);
    glfwSetWindowUserPointer(window_.get(), this);
    glfwSetDropCallback(window_.get(), &App::onDrop);
    glfwSetWindowRefreshCallback(window_.get(), &App::onRefresh);
  }

  // Runs the frame loop; saves the settings (when on) however it ends.
  int run() {
    const int code = reportRepaintCheck(loop());
    if (settings_) {
      if (const auto file = settingsFile()) {
        int w = 0, h = 0;
        glfwGetWindowSize(window_.get(), &w, &h);
        try {
          writeSettings(*file, captureSettings(state_, w, h));
        } catch (const std::exception& e) {
          std::fprintf(stderr, "eigenwalker: %s\n", e.what());
        }
      }
    }
    return code;
  }

 private:
  // Files / folders dropped on the window: the same action as the script's "drop".
  static void onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (!app || count <= 0) return;
    // Nothing may leave a GLFW callback (C code) by an exception: a refused drop is shown.
    try {
      const std::vector<std::filesystem::path> dropped(paths, paths + count);
      try {
        actions::drop(app->state_, dropped);
      } catch (const std::exception& e) {
        actions::reportOpenError(app->state_, dropped, e.what());
      }
    } catch (...) {
      app->state_.log.error("a drop could not be handled");
    }
  }

  // --check-repaint: says how the frames compared; a difference fails the run.
  int reportRepaintCheck(int code) const {
    if (!options_.checkRepaint) return code;
    const auto& c = compositor_.checks();
    std::printf("repaint check: %d frames, %d of them repainted in part, %d differ from a full redraw\n", c.frames,
                c.partialFrames, c.mismatchedFrames);
    if (c.mismatchedFrames == 0) return code;
    std::fprintf(stderr, "eigenwalker: repaint check failed, %s\n", c.firstMismatch.value_or("").c_str());
    return code == 0 ? 1 : code;
  }

  // The window system lost (some of) the window's pixels: show the whole frame again.
  static void onRefresh(GLFWwindow* window) {
    if (auto* app = static_cast<App*>(glfwGetWindowUserPointer(window))) app->compositor_.invalidate();
  }

  // Shows the frame just drawn: the changed rectangles when the back buffer is kept,
  // a swap otherwise. Without swaps nothing waits for the display, so an interactive
  // run sleeps out the rest of a 60 Hz frame instead of redrawing as fast as it can. A
  // scripted run draws as fast as it can, except while it waits for a background job (a
  // detection, a track, a model build): then 10 frames a second, and the job has the processor
  // (with software GL, as under xvfb, a frame costs as much as a detected one).
  void present(std::chrono::steady_clock::time_point frameStart) {
    if (!presenter_) {
      glfwSwapBuffers(window_.get());
    } else {
      int w = 0, h = 0;
      glfwGetFramebufferSize(window_.get(), &w, &h);
      presenter_->present(compositor_.changed(), h);
      if (!scripted_) std::this_thread::sleep_until(frameStart + std::chrono::microseconds(16667));
    }
    if (scripted_ && state_.jobsBusy()) std::this_thread::sleep_until(frameStart + std::chrono::milliseconds(100));
  }

  int loop() {
    auto last = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(window_.get()) && !state_.quitRequested) {
      const auto start = std::chrono::steady_clock::now();
      const double dt = std::min(0.1, std::chrono::duration<double>(start - last).count());
      last = start;
      glfwPollEvents();
      updateScale();

      update(dt);
      if (runner_.failed()) {
        std::fprintf(stderr, "eigenwalker: %s\n", runner_.error().c_str());
        return 1;
      }

      const auto t0 = std::chrono::steady_clock::now();
      drawFrame(dt);
      if (profile_) {
        gl::finish();
        profile_->draw += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      }
      capturePng();
      if (auto file = runner_.takeCapture()) {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_.get(), &w, &h);
        try {
          writeScreenshot(*file, w, h);
          state_.log.info("screenshot " + file->string());
        } catch (const std::exception& e) {
          std::fprintf(stderr, "eigenwalker: %s\n", e.what());
          return 1;
        }
      }
      audience_.frame(state_, window_.get(), renderer_);
      const auto t1 = std::chrono::steady_clock::now();
      present(start);
      if (profile_) {
        gl::finish();
        profile_->swap += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
        if (++profile_->frames % 60 == 0) {
          std::fprintf(stderr,
                       "eigenwalker: profile: frame %.2f ms (of which the two views %.2f ms, compositing "
                       "the UI %.2f ms for %d vertices, %.0f %% of the pixels repainted), swap %.2f ms "
                       "(means of 60)\n",
                       profile_->draw / 60.0, profile_->views / 60.0, profile_->imgui / 60.0,
                       profile_->vertices / 60, 100.0 * profile_->repainted / 60.0, profile_->swap / 60.0);
          profile_->draw = profile_->swap = profile_->views = profile_->imgui = profile_->repainted = 0.0;
          profile_->vertices = 0;
        }
      }
      ++state_.frame;

      if (benchRemaining_ > 0) {
        stats_.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        if (--benchRemaining_ == 0) {
          std::printf("%s\n", stats_.json().c_str());
          std::fflush(stdout);
          return 0;
        }
      } else if (scripted_ && runner_.finished() && !state_.busy()) {
        if (!finalScreenshotRequested_ && options_.screenshot) {
          finalScreenshotRequested_ = true;
          runner_.requestCapture(*options_.screenshot);
        } else if (options_.benchFrames > 0 && !benchStarted_) {
          benchStarted_ = true;
          benchRemaining_ = options_.benchFrames;
          state_.view.playback.playing = true;
        } else if (options_.benchFrames == 0 || benchStarted_) {
          if (!state_.notices.lastError.empty() && !options_.script) {
            std::fprintf(stderr, "eigenwalker: %s\n", state_.notices.lastError.c_str());
            return 1;
          }
          return 0;
        }
      }
    }
    return 0;
  }

 private:
  // [SECTION] One frame's work before drawing

  // Background results, the script, derived results, playback, the video export. Whatever
  // goes wrong here is shown in the window and the session goes on (a failed load or model
  // build keeps what the user had: actions::pollJobs).
  void update(double dt) {
    try {
      actions::pollJobs(state_);
      actions::followModelSigma2(state_);  // before the script reads or exports the state
      runner_.step(state_);
      actions::followModelSigma2(state_);  // the script may have changed the model
      state_.derived.update(state_.doc);
      actions::advancePlayback(state_, dt);
      actions::advanceStage(state_, dt);
      stepVideoExport();
    } catch (const std::exception& e) {
      reportUnexpected(e.what());
    } catch (...) {
      reportUnexpected("an exception of unknown type");
    }
  }

  // Shown once, not every frame, while the same error repeats.
  void reportUnexpected(const std::string& what) {
    if (what == lastUnexpected_) return;
    lastUnexpected_ = what;
    actions::reportError(state_, "Something went wrong", what);
  }

  // [SECTION] Exports that need the GL context: video frames and PNG read-back

  void stepVideoExport() {
    auto& e = state_.exports;
    if (!e.video) return;
    try {
      // Scripted runs spend most of the time encoding; interactive runs keep the UI responsive.
      if (e.video->step(state_, renderer_, scripted_ ? 400.0 : 40.0)) {
        state_.log.info("Wrote " + e.video->settings().path.string() + " (" +
                        std::to_string(e.video->frameCount()) + " frames in " +
                        std::to_string(e.video->seconds()) + " s)");
        e.video.reset();
      }
    } catch (const std::exception& ex) {
      actions::reportExportError(state_, ex.what());
      e.video.reset();
    }
  }

  void capturePng() {
    auto& e = state_.exports;
    if (!e.png) return;
    if (e.png->settleFrames > 0) {
      --e.png->settleFrames;
      return;
    }
    const PngRequest request = std::move(*e.png);
    e.png.reset();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_.get(), &w, &h);
    std::optional<PixelRect> crop;
    if (request.view != CaptureView::Window) {
      const PanelRect r = request.view == CaptureView::Input ? state_.panels.input.lastImage
                                                             : state_.panels.reconstruction.lastImage;
      const ImVec2 fb = ImGui::GetIO().DisplayFramebufferScale;
      const int x = static_cast<int>(r.pos.x * fb.x), y = static_cast<int>(r.pos.y * fb.y);
      crop = PixelRect{x, y, x + static_cast<int>(r.size.x * fb.x), y + static_cast<int>(r.size.y * fb.y)};
      if (crop->empty()) {
        actions::reportExportError(state_, request.path.string() + ": the view is not on screen");
        return;
      }
    }
    try {
      writeScreenshot(request.path, w, h, crop);
      state_.log.info("Wrote " + request.path.string());
    } catch (const std::exception& ex) {
      actions::reportExportError(state_, ex.what());
    }
  }

  // [SECTION] Keyboard shortcuts (only when no text field has the keyboard)

  void handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || io.KeyAlt || io.KeySuper) return;
    for (const ShortcutRow& row : shortcutRows())
      for (const KeyBinding& b : row.bindings)
        if (b.chord.ctrl == io.KeyCtrl && b.chord.shift == io.KeyShift && ImGui::IsKeyPressed(b.chord.key, b.repeats))
          b.apply(state_);
  }

  // A change is one undo step once it has settled: no control held by the mouse (a slider being
  // dragged), no repeating key down (] held to sweep α).
  bool parametersSettled() const {
    if (ImGui::IsAnyItemActive()) return false;
    for (const ShortcutRow& row : shortcutRows())
      for (const KeyBinding& b : row.bindings)
        if (b.repeats && ImGui::IsKeyDown(b.chord.key)) return false;
    return true;
  }

  void updateScale() {
    float xs = 1.0f, ys = 1.0f;
    glfwGetWindowContentScale(window_.get(), &xs, &ys);
    state_.view.contentScale = std::max(xs, 0.5f);
    const float wanted = state_.view.contentScale * state_.view.uiScale *
                         (state_.view.theme == Theme::Projector ? kProjectorScale : 1.0f);
    // A scale that would leave fewer than kMinLogicalWindow UI pixels is limited (in steps of
    // 1/8, so that resizing rebuilds the fonts rarely), never below the monitor's own scale.
    int w = 0, h = 0;
    glfwGetWindowSize(window_.get(), &w, &h);
    const float fits = std::min(static_cast<float>(w) / kMinLogicalWindowW, static_cast<float>(h) / kMinLogicalWindowH);
    const float limit = std::max(state_.view.contentScale, std::floor(fits * 8.0f) / 8.0f);
    const float scale = std::min(wanted, limit);
    state_.view.uiScaleLimit = wanted > limit ? scale / (wanted / state_.view.uiScale) : 0.0f;
    if (scale != themeScale_ || state_.view.theme != appliedTheme_) {
      themeScale_ = scale;
      appliedTheme_ = state_.view.theme;
      applyTheme(state_.fonts, state_.presentationFonts, scale, state_.view.theme);
      ImGui_ImplOpenGL3_DestroyFontsTexture();
      ImGui_ImplOpenGL3_CreateFontsTexture();
      compositor_.invalidate();  // the same draw lists now sample another texture
    }
  }

  // [SECTION] The panels of a frame: the workspace, or presentation mode

  // Notes a panel as drawn this frame (export_state reports the list).
  void drawn(const char* name) { state_.lastFrame.drawn.emplace_back(name); }

  // The two views, then a wait for their rendering before ImGui composites them: on llvmpipe,
  // letting it overlap the UI's made the median 1600×900 frame ~25 ms instead of ~17
  // (measured with --bench-frames; the rasteriser threads and the UI thread share two cores).
  void drawViews(const Layout& l, const FrameContext& ctx) {
    auto& p = state_.panels;
    const auto v0 = std::chrono::steady_clock::now();
    p.input.draw(state_, ctx, l.input);
    p.reconstruction.draw(state_, ctx, l.reconstruction);
    drawn("input");
    drawn("reconstruction");
    gl::finish();
    if (profile_)
      profile_->views += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - v0).count();
  }

  // The notice row, when the layout gave it room (an error or warning is shown).
  void drawNotice(const Layout& l, const FrameContext& ctx) {
    state_.panels.notice.draw(state_, ctx, l.notice);
    if (l.notice.size.y > 0.0f) drawn("notice");
  }

  void drawWorkspace(const Layout& l, const FrameContext& ctx) {
    auto& p = state_.panels;
    // In the drawer layout the side and bottom panels share one place: only the active tab's is drawn.
    const auto shown = [&](DrawerTab tab) { return !l.drawer || p.drawer.shows(tab); };
    const auto panel = [&](auto& which, const char* name, const PanelRect& rect) {
      which.draw(state_, ctx, rect);
      drawn(name);
    };
    panel(p.header, "header", l.header);
    drawNotice(l, ctx);
    p.drawer.inUse = l.drawer;
    if (l.drawer) panel(p.drawer, "drawer_tabs", l.drawerTabs);
    if (shown(DrawerTab::Subjects)) panel(p.subjects, "subjects", l.subjects);
    if (shown(DrawerTab::Controls)) panel(p.controls, "controls", l.controls);
    panel(p.metrics, "metrics", l.metrics);
    drawViews(l, ctx);
    panel(p.playback, "playback", l.playback);
    if (shown(DrawerTab::Coefficients)) panel(p.coefficients, "coefficients", l.coefficients);
    if (shown(DrawerTab::JointErrors)) panel(p.jointErrors, "joint_errors", l.jointErrors);
    if (shown(DrawerTab::Profile)) panel(p.profile, "profile", l.profile);
    if (shown(DrawerTab::Log)) panel(p.log, "log", l.log);
  }

  // The views and the bar in presentation fonts and sizes when the views are wide enough for
  // them. Narrower views (a large UI scale on a small window) draw their text smaller instead,
  // so that captions and legends keep clear of the walker.
  void drawPresentation(const Layout& l, const FrameContext& ctx) {
    auto& p = state_.panels;
    drawNotice(l, ctx);
    p.drawer.inUse = false;
    constexpr float kViewWidth = 360.0f;  // of the scale's pixels, for a caption on one or two lines
    const float room = l.input.size.x / (kViewWidth * ctx.scale);
    if (room >= kPresentationTextScale) {
      const ScopedFonts fonts(state_, state_.presentationFonts);
      const FrameContext large{ctx.renderer, ctx.backdrop, ctx.scale * kPresentationTextScale, ctx.dtS};
      drawViews(l, large);
      p.presentationBar.draw(state_, large, l.presentationBar);
    } else {
      const float shrink = std::clamp(room, 0.6f, 1.0f);
      {
        const ScopedFontScale smaller(shrink);
        drawViews(l, {ctx.renderer, ctx.backdrop, ctx.scale * shrink, ctx.dtS});
      }
      p.presentationBar.draw(state_, ctx, l.presentationBar);
    }
    drawn("presentation_bar");
  }

  // Floating windows. Presentation mode keeps the tour's card (above the bar), the help, and
  // the analysis window while the tour shows it.
  void drawFloating(const Layout& l, const FrameContext& ctx) {
    auto& p = state_.panels;
    p.tour.bottom = l.presentation ? l.presentationBar.pos.y : 0.0f;
    p.tour.left = l.drawer ? l.drawerTabs.pos.x + l.drawerTabs.size.x : 0.0f;
    if (!l.presentation) {
      p.exports.draw(state_, ctx);
      p.gait.draw(state_, ctx);
      p.data.draw(state_, ctx);
    }
    if (!l.presentation || p.tour.active) p.analysis.draw(state_, ctx);
    p.tour.draw(state_, ctx);
    p.quiz.draw(state_, ctx);
    p.help.draw(state_, ctx);
    if (!l.presentation) {
      p.header.drawModelMenu(state_, ctx);
      p.notice.drawDetails(state_, ctx);
    }
  }

  void applyScriptedPointer() {
    ImGuiIO& io = ImGui::GetIO();
    auto& p = state_.pointer;
    io.MousePos = p.present ? ImVec2(p.x, p.y) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (std::size_t i = 0; i < p.down.size(); ++i) io.MouseDown[i] = p.down[i];
    io.MouseWheel = std::exchange(p.wheel, 0.0f);
    // ImGui's clicks and double clicks are timed: a frame's real time under a loaded CI machine
    // would make them depend on its load.
    io.DeltaTime = 1.0f / 60.0f;
  }

  void drawFrame(double dt) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    // A scripted run ignores the real pointer (under Xvfb it rests mid-screen, and its hover
    // highlights and tooltips would land in screenshots at random) for the script's own.
    if (scripted_) applyScriptedPointer();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    const bool notice = state_.panels.notice.visible(state_);
    const Layout l = state_.view.presentation
                         ? computePresentationLayout(io.DisplaySize.x, io.DisplaySize.y, themeScale_, notice)
                         : computeLayout(io.DisplaySize.x, io.DisplaySize.y, themeScale_, notice);
    state_.lastFrame = FrameRecord{};
    state_.lastFrame.layout = l;
    FrameContext ctx{renderer_, backdrop_, themeScale_, dt};
    try {
      if (l.presentation) {
        drawPresentation(l, ctx);
      } else {
        drawWorkspace(l, ctx);
      }
      drawFloating(l, ctx);
      handleShortcuts();
      state_.history.observe(captureParameters(state_), captureParameterContext(state_), parametersSettled());
    } catch (const std::exception& e) {
      // An action refused its input, or GL failed: say so, keep running.
      ImGui::ErrorCheckEndFrameRecover(nullptr);
      state_.log.error(e.what());
    } catch (...) {
      ImGui::ErrorCheckEndFrameRecover(nullptr);
      reportUnexpected("an exception of unknown type while drawing");
    }
    state_.lastFrame.overflow = windowsCutOnTheRight();
    ImGui::Render();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_.get(), &w, &h);
    const auto r0 = std::chrono::steady_clock::now();
    compositor_.draw(backdrop_, *ImGui::GetDrawData(),
                     state_.view.theme == Theme::Light ? glm::vec4{0.93f, 0.935f, 0.945f, 1.0f}
                                                       : glm::vec4{0.05f, 0.055f, 0.065f, 1.0f},
                     w, h);
    recordRepaintedShare();
    if (profile_) {
      gl::finish();
      profile_->imgui += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r0).count();
      profile_->vertices += ImGui::GetDrawData()->TotalVtxCount;
      profile_->repainted += compositor_.lastRepaintedShare();
    }
  }

  // For export_state (AppState::repaintedShares).
  void recordRepaintedShare() {
    auto& shares = state_.repaintedShares;
    shares.push_back(compositor_.lastRepaintedShare());
    if (shares.size() > AppState::kRepaintHistoryFrames) shares.pop_front();
  }

  AppOptions options_;
  std::string settingsWarning_;
  std::optional<Settings> settings_;  // loaded at start; nothing when settings are off
  GlfwSession glfw_;  // members initialise in this order: GLFW, window, ImGui, GL objects
  WindowPtr window_;
  ImGuiSession imgui_;
  Renderer renderer_;
  AudienceWindow audience_;  // destroyed before the main window, whose context it shares
  Backdrop backdrop_;
  Compositor compositor_;
  std::optional<gl::SubBufferPresenter> presenter_;  // when the back buffer is never swapped
  AppState state_;
  ScriptRunner runner_;
  float themeScale_ = 0.0f;
  Theme appliedTheme_ = Theme::Dark;
  bool scripted_ = false;
  bool finalScreenshotRequested_ = false;
  bool benchStarted_ = false;
  int benchRemaining_ = 0;
  std::string lastUnexpected_;
  FrameStats stats_;
  struct Profile {
    double draw = 0.0, swap = 0.0, views = 0.0, imgui = 0.0, repainted = 0.0;
    int frames = 0, vertices = 0;
  };
  // EW_PROFILE=1: per-phase frame times on stderr (adds glFinish, so slower overall).
  std::optional<Profile> profile_ = std::getenv("EW_PROFILE") ? std::optional<Profile>(Profile{}) : std::nullopt;
};

}  // namespace

int runApp(const AppOptions& options) {
  try {
    App app(options);
    return app.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "eigenwalker: %s\n", e.what());
    return 1;
  } catch (...) {
    std::fprintf(stderr, "eigenwalker: an exception of unknown type\n");
    return 1;
  }
}

}  // namespace ew::ui
