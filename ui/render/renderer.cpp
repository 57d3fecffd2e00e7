#include "ui/render/renderer.h"

#include <algorithm>
#include <cstdlib>
#include <array>
#include <cstddef>

#include "ui/gl/resources.h"

namespace ew::ui {

namespace {

gl::Program loadProgram(const char* stem) {
  return gl::Program::fromFiles(gl::resourcePath(std::string("shaders/") + stem + ".vert"),
                                gl::resourcePath(std::string("shaders/") + stem + ".frag"));
}

}  // namespace

Renderer::Renderer()
    : background_(loadProgram("background")),
      floor_(loadProgram("floor")),
      sphere_(loadProgram("sphere")),
      tube_(loadProgram("tube")),
      line_(loadProgram("line")),
      image_(loadProgram("image")) {
  static_assert(sizeof(SphereInstance) == 8 * sizeof(float));
  static_assert(sizeof(TubeInstance) == 12 * sizeof(float));
  static_assert(sizeof(LineInstance) == 12 * sizeof(float));
  const std::array<gl::InstanceAttribute, 2> sphereLayout{{
      {0, 4, offsetof(SphereInstance, centre)},
      {1, 4, offsetof(SphereInstance, colour)},
  }};
  sphereVao_.setInstanceLayout(sphereBuffer_, sizeof(SphereInstance), sphereLayout);
  const std::array<gl::InstanceAttribute, 3> tubeLayout{{
      {0, 4, offsetof(TubeInstance, a)},
      {1, 4, offsetof(TubeInstance, b)},
      {2, 4, offsetof(TubeInstance, colour)},
  }};
  tubeVao_.setInstanceLayout(tubeBuffer_, sizeof(TubeInstance), tubeLayout);
  const std::array<gl::InstanceAttribute, 3> lineLayout{{
      {0, 4, offsetof(LineInstance, a)},
      {1, 4, offsetof(LineInstance, b)},
      {2, 4, offsetof(LineInstance, colour)},
  }};
  lineVao_.setInstanceLayout(lineBuffer_, sizeof(LineInstance), lineLayout);
  // EW_SAMPLES overrides the multisampling of the views (1 = off; the impostors and lines
  // anti-alias their own edges, so 1 still looks smooth, and software GL is much faster).
  samples_ = 1;
  if (const char* env = std::getenv("EW_SAMPLES"); env && *env) samples_ = std::clamp(std::atoi(env), 1, 16);
  samples_ = std::min(samples_, gl::maxSamples());
}

void Renderer::drawSpheres(const std::vector<SphereInstance>& items, const CameraMatrices& camera,
                           int mode) {
  if (items.empty()) return;
  sphereBuffer_.upload(std::span<const SphereInstance>(items));
  sphere_.use();
  sphere_.set("uView", camera.view);
  sphere_.set("uProj", camera.projection);
  sphere_.set("uMode", mode);
  sphere_.set("uMargin", mode == 1 ? 1.0f : 1.15f);
  gl::drawQuads(sphereVao_, static_cast<int>(items.size()));
}

void Renderer::drawTubes(const std::vector<TubeInstance>& items, const CameraMatrices& camera) {
  if (items.empty()) return;
  tubeBuffer_.upload(std::span<const TubeInstance>(items));
  tube_.use();
  tube_.set("uView", camera.view);
  tube_.set("uProj", camera.projection);
  tube_.set("uOrtho", camera.orthographic ? 1 : 0);
  gl::drawQuads(tubeVao_, static_cast<int>(items.size()));
}

void Renderer::drawLines(const std::vector<LineInstance>& items, const CameraMatrices& camera,
                         glm::vec2 viewportPx) {
  if (items.empty()) return;
  lineBuffer_.upload(std::span<const LineInstance>(items));
  line_.use();
  line_.set("uView", camera.view);
  line_.set("uProj", camera.projection);
  line_.set("uViewport", viewportPx);
  gl::drawQuads(lineVao_, static_cast<int>(items.size()));
}

void Renderer::drawImage(const SceneImage& image, const CameraMatrices& camera) {
  if (!image.shown()) return;
  if (image.key != imageKey_ || imageTexture_.width() != image.width || imageTexture_.height() != image.height) {
    imageTexture_.uploadBgr(image.width, image.height, image.bgr, image.strideBytes);
    imageKey_ = image.key;
  }
  gl::apply({.depthTest = false, .depthWrite = false});
  image_.use();
  image_.set("uViewProj", camera.projection * camera.view);
  image_.set("uLow", image.low);
  image_.set("uHigh", image.high);
  image_.set("uBrightness", image.brightness);
  image_.set("uImage", 0);
  imageTexture_.bind(0);
  gl::drawQuad(emptyVao_);
}

void Renderer::render(gl::RenderTarget& target, const Scene& scene, const CameraMatrices& camera) {
  if (!target.valid()) return;
  target.begin();
  const glm::vec2 viewport{static_cast<float>(target.width()), static_cast<float>(target.height())};
  gl::clear(glm::mix(scene.backgroundBottom, scene.backgroundTop, 0.55f));

  // Background gradient (no depth): only in the multisampled quality mode; software GL
  // pays a full-screen pass for it.
  if (samples_ > 1) {
    gl::apply({.depthTest = false, .depthWrite = false});
    background_.use();
    background_.set("uTop", scene.backgroundTop);
    background_.set("uBottom", scene.backgroundBottom);
    gl::drawQuad(emptyVao_);
  }

  drawImage(scene.image, camera);

  // Floor: blended over the background, writes depth so what is below it is hidden.
  if (scene.floor.visible) {
    gl::apply({.depthTest = true, .depthWrite = true, .blend = gl::Blend::Alpha});
    floor_.use();
    floor_.set("uView", camera.view);
    floor_.set("uProj", camera.projection);
    floor_.set("uExtent", scene.floor.extentMm);
    floor_.set("uScroll", scene.floor.scrollMm);
    floor_.set("uShadowCentre", scene.floor.shadowCentre);
    floor_.set("uShadowRadius", scene.floor.shadowRadiusMm);
    gl::drawQuad(emptyVao_);
  }

  // Lines that live in the scene (glyphs, axes), depth-tested.
  gl::apply({.depthTest = true, .depthWrite = false, .blend = gl::Blend::Alpha});
  drawLines(scene.lines, camera, viewport);

  // Opaque figures; alpha-to-coverage smooths the impostors' silhouettes.
  gl::apply({.depthTest = true,
             .depthWrite = true,
             .blend = samples_ > 1 ? gl::Blend::None : gl::Blend::Alpha,
             .alphaToCoverage = samples_ > 1});
  drawTubes(scene.tubes, camera);
  drawSpheres(scene.spheres, camera, 0);

  // The ghost: a depth-only pass, then colour where the ghost's own surface is nearest,
  // so overlapping bones do not double their opacity.
  if (!scene.ghostSpheres.empty() || !scene.ghostTubes.empty()) {
    gl::apply({.depthTest = true, .depthWrite = true, .colourWrite = false});
    drawTubes(scene.ghostTubes, camera);
    drawSpheres(scene.ghostSpheres, camera, 0);
    gl::apply({.depthTest = true, .depthWrite = false, .blend = gl::Blend::Alpha,
               .depthEqual = true});
    drawTubes(scene.ghostTubes, camera);
    drawSpheres(scene.ghostSpheres, camera, 0);
  }

  // Point-lights (2D view), additive.
  gl::apply({.depthTest = false, .depthWrite = false, .blend = gl::Blend::Alpha});
  drawSpheres(scene.glows, camera, 1);

  // Overlays on top of everything.
  gl::apply({.depthTest = false, .depthWrite = false, .blend = gl::Blend::Alpha});
  drawLines(scene.overlayLines, camera, viewport);

  gl::apply({.depthTest = false, .depthWrite = true});
  target.end();
}

}  // namespace ew::ui
