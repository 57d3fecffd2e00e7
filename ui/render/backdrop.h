#pragma once
// What a frame draws beneath Dear ImGui's draw lists with plain GL copies and fills: the
// fixed panels' backgrounds (scissored clears) and the two views' images (framebuffer
// blits), collected while the panels are built. Under llvmpipe every ImGui pixel is a blended, textured fragment: drawing the
// window backgrounds this way cut ImGui's shaded area at 1600×900 from ~2.0 to ~0.5
// megapixels a frame (docs/VIEWER_DESIGN.md, "Frame time").

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace ew::gl {
class RenderTarget;
}

namespace ew::ui {

class Backdrop {
 public:
  // Positions and sizes in ImGui's screen coordinates (origin top-left).
  void fill(glm::vec2 pos, glm::vec2 size, glm::vec4 colour) { fills_.push_back({pos, size, colour}); }
  // The target must outlive the frame (the panels own theirs).
  void image(const gl::RenderTarget& target, glm::vec2 pos) { images_.push_back({&target, pos}); }

  struct Fill {
    glm::vec2 pos, size;
    glm::vec4 colour;
  };
  struct Image {
    const gl::RenderTarget* target;
    glm::vec2 pos;
  };
  // This frame's, in the order given; ui/render/compositor.h draws them, then forgets them.
  const std::vector<Fill>& fills() const { return fills_; }
  const std::vector<Image>& images() const { return images_; }
  void reset() {
    fills_.clear();
    images_.clear();
  }

 private:
  std::vector<Fill> fills_;
  std::vector<Image> images_;
};

}  // namespace ew::ui
