#pragma once
// Draws a Scene into an offscreen render target: background, floor grid, opaque
// impostors (joints and bones), one translucent layer (the ghost), point-lights and
// lines. The only user of ui/gl/ besides the app's frame loop.

#include <cstdint>
#include <memory>

#include "ui/gl/gl.h"
#include "ui/render/scene.h"

namespace ew::ui {

class Renderer {
 public:
  // Compiles the shaders in shaders/ (found through gl::resourcePath); throws
  // gl::GlError naming the file when one does not compile.
  Renderer();

  // Renders `scene` seen by `camera` into `target` and resolves it for display.
  void render(gl::RenderTarget& target, const Scene& scene, const CameraMatrices& camera);

  // Multisampling of the view targets (clamped to what the driver offers).
  int samples() const { return samples_; }

 private:
  void drawSpheres(const std::vector<SphereInstance>& items, const CameraMatrices& camera, int mode);
  void drawTubes(const std::vector<TubeInstance>& items, const CameraMatrices& camera);
  void drawLines(const std::vector<LineInstance>& items, const CameraMatrices& camera,
                 glm::vec2 viewportPx);

  void drawImage(const SceneImage& image, const CameraMatrices& camera);

  gl::Program background_, floor_, sphere_, tube_, line_, image_;
  gl::Texture2D imageTexture_;
  std::uint64_t imageKey_ = 0;
  gl::Buffer sphereBuffer_, tubeBuffer_, lineBuffer_;
  gl::VertexArray sphereVao_, tubeVao_, lineVao_, emptyVao_;
  int samples_ = 4;
};

}  // namespace ew::ui
