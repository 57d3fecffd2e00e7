#include "ui/gl/present.h"

#include <dlfcn.h>
#include <epoxy/glx.h>

#include <string>

namespace ew::gl {

namespace {

bool isSoftwareRasteriser() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer ? renderer : "";
  for (const char* software : {"llvmpipe", "softpipe", "swrast"})
    if (name.find(software) != std::string::npos) return true;
  return false;
}

// GLFW loads libGL for a GLX context; asking epoxy for GLX calls without it would abort.
bool glxLoaded() {
  void* lib = dlopen("libGL.so.1", RTLD_LAZY | RTLD_NOLOAD);
  if (lib) dlclose(lib);
  return lib != nullptr;
}

}  // namespace

std::optional<SubBufferPresenter> SubBufferPresenter::forCurrentContext() {
  if (!isSoftwareRasteriser() || !glxLoaded()) return std::nullopt;
  Display* display = glXGetCurrentDisplay();
  const GLXDrawable drawable = glXGetCurrentDrawable();
  if (!display || !drawable || !epoxy_has_glx(display)) return std::nullopt;
  if (!epoxy_has_glx_extension(display, DefaultScreen(display), "GLX_MESA_copy_sub_buffer"))
    return std::nullopt;
  return SubBufferPresenter(display, drawable);
}

void SubBufferPresenter::present(std::span<const ui::PixelRect> rects, int fbHeight) const {
  auto* display = static_cast<Display*>(display_);
  for (const ui::PixelRect& r : rects) {
    if (r.empty()) continue;
    glXCopySubBufferMESA(display, drawable_, r.x0, fbHeight - r.y1, r.x1 - r.x0, r.y1 - r.y0);
  }
}

}  // namespace ew::gl
