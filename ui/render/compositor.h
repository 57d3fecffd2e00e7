#pragma once
// Puts a frame together: the backdrop (panel fills, the views' images) beneath Dear
// ImGui's draw lists, repainting only what changed since the last frame
// (ui/render/damage.h). That needs a framebuffer that still holds the last frame:
//  - Target::Window: the window's back buffer, when it is never swapped (the frames are
//    shown with gl::SubBufferPresenter, ui/gl/present.h);
//  - Target::Layer: an offscreen layer of the compositor's own, copied whole to the
//    window's back buffer every frame (which is then swapped);
//  - Target::FullRedraw: no memory of the last frame; everything, every frame, straight
//    into the back buffer (--full-redraw, the reference to compare with).

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "ui/gl/gl.h"
#include "ui/render/backdrop.h"
#include "ui/render/damage.h"

struct ImDrawData;

namespace ew::ui {

class Compositor {
 public:
  enum class Target { Window, Layer, FullRedraw };
  explicit Compositor(Target target = Target::Layer) : target_(target) {}

  // Draws the frame on a `background` colour into the window's back buffer
  // (fbWidth×fbHeight pixels); forgets the backdrop's items.
  void draw(Backdrop& backdrop, const ImDrawData& ui, glm::vec4 background, int fbWidth,
            int fbHeight);
  // The next frame is repainted whole (the window lost its pixels, or the font texture
  // was rebuilt: the same draw lists, other pixels).
  void invalidate() { damage_.invalidate(); }
  // What the last frame changed in the back buffer (for Target::Window's presenter).
  std::span<const PixelRect> changed() const { return changed_; }
  // The share of the last frame's pixels that were repainted (1 = all).
  double lastRepaintedShare() const { return lastShare_; }

  // Checking (--check-repaint, for the tests; slow): every frame is painted again, whole,
  // over what was painted, and the two are compared pixel for pixel.
  struct CheckResults {
    int frames = 0, partialFrames = 0, mismatchedFrames = 0;
    std::optional<std::string> firstMismatch;
  };
  void setChecking(bool on) { checking_ = on; }
  const CheckResults& checks() const { return checks_; }

 private:
  // Paints the plan into `into`, or into the window's back buffer when null.
  void paint(const RepaintPlan& plan, const Backdrop& backdrop, const ImDrawData& ui,
             gl::RenderTarget* into, int fbWidth, int fbHeight);
  void check(const RepaintPlan& plan, const Backdrop& backdrop, const ImDrawData& ui,
             gl::RenderTarget* into, int fbWidth, int fbHeight);

  Target target_;
  gl::RenderTarget layer_;
  DamageTracker damage_;
  glm::vec4 background_{-1.0f};
  std::vector<PixelRect> changed_;
  double lastShare_ = 1.0;
  bool checking_ = false;
  CheckResults checks_;
};

}  // namespace ew::ui
