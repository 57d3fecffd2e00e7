#pragma once
// The audience window's GLFW window and drawing (ui/app/audience.h says what it is). Owned by
// the app's frame loop: once a frame, after the main window is drawn, it opens, resizes or
// closes the window to match AudienceFeature, renders the stage's views in the main context
// into one image, and shows that image in its own context (which shares the main one's
// textures: a framebuffer of its own reads the image, as framebuffers are not shared).

#include <memory>

#include "ui/gl/gl.h"
#include "ui/render/scene.h"

struct GLFWwindow;

namespace ew::ui {

struct AppState;
class Renderer;

class AudienceWindow {
 public:
  AudienceWindow() = default;
  ~AudienceWindow();
  AudienceWindow(const AudienceWindow&) = delete;
  AudienceWindow& operator=(const AudienceWindow&) = delete;

  // `main` is the window whose context is current before and after.
  void frame(AppState& s, GLFWwindow* main, Renderer& renderer);

 private:
  void open(AppState& s, GLFWwindow* main);
  void close(AppState& s, GLFWwindow* main);
  void render(AppState& s, Renderer& renderer, int width, int height);
  void show(GLFWwindow* main, int width, int height);

  GLFWwindow* window_ = nullptr;
  GLuint readFbo_ = 0;  // in the audience window's context
  gl::RenderTarget inputTarget_, reconstructionTarget_, composed_;
  Scene inputScene_, reconstructionScene_;
};

}  // namespace ew::ui
