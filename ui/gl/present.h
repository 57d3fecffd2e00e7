#pragma once
// Shows a frame by copying the rectangles that changed from the back buffer to the window
// (GLX_MESA_copy_sub_buffer, offered by Mesa's software rasterisers) instead of swapping
// buffers. The back buffer is then never swapped, so it keeps the previous frame's pixels
// (which a swap leaves undefined): a frame draws only what changed (ui/render/compositor.h)
// and sends only that to the window. Under llvmpipe the alternative, copying a whole
// offscreen frame into a fresh back buffer, costs ~4 ms at 1600×900
// (docs/VIEWER_DESIGN.md, "Frame time").

#include <optional>
#include <span>

#include "ui/pixel_rect.h"

namespace ew::gl {

class SubBufferPresenter {
 public:
  // For the window of the current context; nothing when the context is not GLX, lacks
  // the extension, or is not a software rasteriser (a GPU swaps whole frames for free
  // and in step with the display).
  static std::optional<SubBufferPresenter> forCurrentContext();

  // Copies the rectangles (framebuffer pixels, origin top-left) of the back buffer to the
  // window; the GL is flushed first.
  void present(std::span<const ui::PixelRect> rects, int fbHeight) const;

 private:
  SubBufferPresenter(void* display, unsigned long drawable)
      : display_(display), drawable_(drawable) {}
  void* display_;           // Display*
  unsigned long drawable_;  // GLXDrawable
};

}  // namespace ew::gl
