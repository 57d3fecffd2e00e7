#include "ui/render/backdrop.h"

#include <cmath>

#include "ui/gl/gl.h"

namespace ew::ui {

void Backdrop::drawAndReset(int fbHeight, glm::vec2 fbScale) {
  for (const Fill& f : fills_) {
    const int x0 = static_cast<int>(std::lround(f.pos.x * fbScale.x));
    const int x1 = static_cast<int>(std::lround((f.pos.x + f.size.x) * fbScale.x));
    const int top = static_cast<int>(std::lround(f.pos.y * fbScale.y));
    const int bottom = static_cast<int>(std::lround((f.pos.y + f.size.y) * fbScale.y));
    gl::fillRect(x0, fbHeight - bottom, x1 - x0, bottom - top, f.colour);
  }
  for (const Image& im : images_) {
    // The target was sized from the same position and size (truncated to whole pixels).
    const int x = static_cast<int>(im.pos.x * fbScale.x);
    const int top = static_cast<int>(im.pos.y * fbScale.y);
    im.target->blitToDefault(x, fbHeight - top - im.target->height());
  }
  fills_.clear();
  images_.clear();
}

}  // namespace ew::ui
