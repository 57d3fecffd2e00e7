#include "ui/app/audience_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <exception>

#include "ui/app/app_state.h"
#include "ui/app/screenshot.h"
#include "ui/app/shortcuts.h"
#include "ui/panels/input_view_panel.h"
#include "ui/panels/reconstruction_view_panel.h"
#include "ui/render/renderer.h"

namespace ew::ui {

namespace {

// The presenter may have the projector's window in focus: its keys do what the main
// window's do (a C callback: nothing may be thrown through it).
void onAudienceKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_PRESS) return;
  auto* s = static_cast<AppState*>(glfwGetWindowUserPointer(window));
  if (!s) return;
  try {
    applyShortcut(*s, {key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0});
  } catch (const std::exception& e) {
    s->log.error(e.what());
  }
}

// The projector theme's views are black: a washed-out projector shows black as its darkest grey.
void darkenForProjector(Scene& scene, AudienceTheme theme) {
  if (theme != AudienceTheme::Projector) return;
  scene.backgroundTop = scene.backgroundBottom = {0.0f, 0.0f, 0.0f, 1.0f};
}

}  // namespace

AudienceWindow::~AudienceWindow() {
  if (window_) glfwDestroyWindow(window_);  // its framebuffer object goes with its context
}

void AudienceWindow::frame(AppState& s, GLFWwindow* main, Renderer& renderer) {
  AudienceFeature& a = s.audience;
  if (window_ && (!a.open || glfwWindowShouldClose(window_))) close(s, main);
  if (!a.open) return;
  if (!window_) open(s, main);
  if (!window_) return;
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  if (w != a.widthPx || h != a.heightPx) glfwSetWindowSize(window_, a.widthPx, a.heightPx);
  glfwGetFramebufferSize(window_, &w, &h);
  if (w < 2 || h < 2) return;  // minimised
  render(s, renderer, w, h);
  if (a.capture) {
    const auto file = *std::exchange(a.capture, std::nullopt);
    try {
      writeRgbPng(file, composed_.readPixelsRgb(), composed_.width(), composed_.height());
      s.log.info("Wrote " + file.string() + " (the audience window)");
    } catch (const std::exception& e) {
      s.log.error(e.what());
    }
  }
  show(main, w, h);
}

void AudienceWindow::open(AppState& s, GLFWwindow* main) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  window_ = glfwCreateWindow(s.audience.widthPx, s.audience.heightPx, "Eigenwalker — audience", nullptr, main);
  glfwMakeContextCurrent(main);
  if (!window_) {
    s.audience.open = false;
    s.audience.error = "the audience window could not be opened (the display refused a second OpenGL 3.3 window)";
    s.log.error(s.audience.error);
    return;
  }
  glfwSetWindowUserPointer(window_, &s);
  glfwSetKeyCallback(window_, &onAudienceKey);
  s.audience.shown = true;
  s.audience.error.clear();
  s.log.info("Audience window opened (" + std::to_string(s.audience.widthPx) + "×" +
             std::to_string(s.audience.heightPx) + ")");
}

void AudienceWindow::close(AppState& s, GLFWwindow* main) {
  glfwMakeContextCurrent(window_);
  if (readFbo_) glDeleteFramebuffers(1, &readFbo_);
  readFbo_ = 0;
  glfwMakeContextCurrent(main);
  glfwDestroyWindow(window_);
  window_ = nullptr;
  s.audience.open = false;
  s.audience.shown = false;
  s.log.info("Audience window closed");
}

void AudienceWindow::render(AppState& s, Renderer& renderer, int width, int height) {
  const AudienceViews views = s.audience.views;
  const bool both = views == AudienceViews::Both;
  const int inputW = both ? width / 2 : views == AudienceViews::Input ? width : 0;
  const int reconW = width - inputW;
  const float lineScale = std::max(1.0f, static_cast<float>(height) / 720.0f);
  composed_.ensure(width, height, 1, false);
  if (inputW > 0) {
    inputScene_.clearItems();
    buildInputScene(s, inputScene_, lineScale, s.view.playback.phase());
    darkenForProjector(inputScene_, s.audience.theme);
    inputTarget_.ensure(inputW, height, renderer.samples());
    renderer.render(inputTarget_, inputScene_, inputViewCamera(static_cast<float>(inputW) / static_cast<float>(height)));
    inputTarget_.blitInto(composed_, 0, 0);
  }
  if (reconW > 0) {
    float errorScale = 1.0f;
    reconstructionScene_.clearItems();
    buildReconstructionScene(s, reconstructionScene_, lineScale, s.view.playback.cycles, &errorScale);
    darkenForProjector(reconstructionScene_, s.audience.theme);
    reconstructionTarget_.ensure(reconW, height, renderer.samples());
    renderer.render(reconstructionTarget_, reconstructionScene_,
                    s.view.camera.matrices(static_cast<float>(reconW) / static_cast<float>(height)));
    reconstructionTarget_.blitInto(composed_, inputW, 0);
  }
  glFinish();  // the image complete before the other context reads it
}

void AudienceWindow::show(GLFWwindow* main, int width, int height) {
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the main window's swap keeps the pace
  if (!readFbo_) glGenFramebuffers(1, &readFbo_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, readFbo_);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, composed_.texture().id(), 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glBlitFramebuffer(0, 0, composed_.width(), composed_.height(), 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glfwSwapBuffers(window_);
  glfwMakeContextCurrent(main);
}

}  // namespace ew::ui
