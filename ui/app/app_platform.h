#pragma once
// The frame loop's platform (ui/app/app.cpp): GLFW and Dear ImGui lifetimes, the window,
// frame timing for --bench-frames, and scoped font changes.

#include <memory>
#include <string>
#include <vector>

#include "ui/app/app_state.h"

struct GLFWwindow;

namespace ew::ui {

// [SECTION] Platform: GLFW and Dear ImGui lifetimes

struct GlfwSession {
  GlfwSession();
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
};

struct WindowDeleter {
  void operator()(GLFWwindow* w) const;
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

// An OpenGL 3.3 core window, its context current.
WindowPtr createWindow(int width, int height);

struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// [SECTION] Frame timing for --bench-frames

struct FrameStats {
  std::vector<double> ms;
  std::string json() const;
};

// [SECTION] Fonts

// Draws with another set of fonts (presentation mode's larger ones) until it goes out of scope:
// the panels read AppState::fonts and ImGui's current font.
class ScopedFonts {
 public:
  ScopedFonts(AppState& s, const Fonts& fonts);
  ~ScopedFonts();
  ScopedFonts(const ScopedFonts&) = delete;
  ScopedFonts& operator=(const ScopedFonts&) = delete;

 private:
  AppState& state_;
  Fonts saved_;
};

// Text drawn `factor` times its size until it goes out of scope (ImGui's global font scale,
// which windows begun meanwhile take up).
class ScopedFontScale {
 public:
  explicit ScopedFontScale(float factor);
  ~ScopedFontScale();
  ScopedFontScale(const ScopedFontScale&) = delete;
  ScopedFontScale& operator=(const ScopedFontScale&) = delete;

 private:
  float saved_;
};

}  // namespace ew::ui
