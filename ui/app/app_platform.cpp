#include "ui/app/app_platform.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "ui/gl/gl.h"  // epoxy before GLFW
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace ew::ui {

// [SECTION] Platform: GLFW and Dear ImGui lifetimes

namespace {

void glfwErrorCallback(int code, const char* description) {
  std::fprintf(stderr, "eigenwalker: GLFW error %d: %s\n", code, description);
}

}  // namespace

GlfwSession::GlfwSession() {
  glfwSetErrorCallback(glfwErrorCallback);
  if (!glfwInit()) throw std::runtime_error("cannot initialise GLFW (no display?)");
}

GlfwSession::~GlfwSession() { glfwTerminate(); }

void WindowDeleter::operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }

WindowPtr createWindow(int width, int height) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  // The window only shows ImGui and the views' finished images: no depth or stencil
  // buffer (llvmpipe clears one tile by tile, a third of a 1600×900 frame's time).
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  WindowPtr window(glfwCreateWindow(width, height, "Eigenwalker", nullptr, nullptr));
  if (!window) throw std::runtime_error("cannot create an OpenGL 3.3 core window");
  glfwMakeContextCurrent(window.get());
  return window;
}

ImGuiSession::ImGuiSession(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; nothing to save
  if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) throw std::runtime_error("ImGui GLFW backend failed");
  if (!ImGui_ImplOpenGL3_Init("#version 330")) throw std::runtime_error("ImGui OpenGL3 backend failed");
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

// [SECTION] Frame timing for --bench-frames

std::string FrameStats::json() const {
  std::vector<double> v = ms;
  std::sort(v.begin(), v.end());
  auto pick = [&](double q) {
    if (v.empty()) return 0.0;
    const auto i = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
    return v[std::min(i, v.size() - 1)];
  };
  char buf[160];
  std::snprintf(buf, sizeof buf, "{\"frames\": %zu, \"median_ms\": %.3f, \"p95_ms\": %.3f, \"max_ms\": %.3f}",
                v.size(), pick(0.5), pick(0.95), v.empty() ? 0.0 : v.back());
  return buf;
}

// [SECTION] Fonts

ScopedFonts::ScopedFonts(AppState& s, const Fonts& fonts) : state_(s), saved_(s.fonts) {
  s.fonts = fonts;
  if (fonts.body) ImGui::PushFont(fonts.body);
}

ScopedFonts::~ScopedFonts() {
  if (state_.fonts.body) ImGui::PopFont();
  state_.fonts = saved_;
}

ScopedFontScale::ScopedFontScale(float factor) : saved_(ImGui::GetIO().FontGlobalScale) {
  ImGui::GetIO().FontGlobalScale = factor;
}

ScopedFontScale::~ScopedFontScale() { ImGui::GetIO().FontGlobalScale = saved_; }

}  // namespace ew::ui
