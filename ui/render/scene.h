#pragma once
// What the renderer draws: plain instance records (the layout the shaders read) and the
// camera matrices. Built by the panels' scene builders each frame; no GL here.

#include <glm/glm.hpp>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ew::ui {

// A shaded sphere impostor (joints, heads; discs in the 2D view).
struct SphereInstance {
  glm::vec3 centre{0.0f};
  float radius = 10.0f;  // world units (mm)
  glm::vec4 colour{1.0f};
};

// A shaded cylinder impostor between two points (bones).
struct TubeInstance {
  glm::vec3 a{0.0f};
  float radius = 10.0f;  // mm
  glm::vec3 b{0.0f};
  float unused = 0.0f;
  glm::vec4 colour{1.0f};
};

// An anti-aliased line of constant width in pixels, optionally dashed.
struct LineInstance {
  glm::vec3 a{0.0f};
  float widthPx = 2.0f;
  glm::vec3 b{0.0f};
  float dashPx = 0.0f;  // 0 = solid
  glm::vec4 colour{1.0f};
};

struct FloorGrid {
  bool visible = false;
  float extentMm = 3200.0f;     // half size of the floor square
  float scrollMm = 0.0f;        // treadmill offset along y
  glm::vec2 shadowCentre{0.0f}; // soft contact shadow under the walker
  float shadowRadiusMm = 380.0f;
};

// A picture behind everything (a video frame in the 2D view): 8-bit BGR rows, drawn on the
// rectangle [low, high] of the scene's plane z = 0 (low = the picture's bottom-left). The
// pixels must stay alive until the frame is rendered; `key` names them (the renderer
// uploads only when it changes).
struct SceneImage {
  const unsigned char* bgr = nullptr;
  int width = 0, height = 0;
  std::size_t strideBytes = 0;
  std::uint64_t key = 0;
  glm::vec2 low{0.0f}, high{0.0f};
  float brightness = 1.0f;  // dims the picture under the marks
  bool shown() const { return bgr != nullptr && width > 0 && height > 0; }
};

struct Scene {
  glm::vec4 backgroundTop{0.11f, 0.12f, 0.14f, 1.0f};
  glm::vec4 backgroundBottom{0.05f, 0.055f, 0.065f, 1.0f};
  FloorGrid floor;
  SceneImage image;
  std::vector<SphereInstance> spheres;       // opaque
  std::vector<TubeInstance> tubes;           // opaque
  std::vector<SphereInstance> ghostSpheres;  // one translucent layer (alpha of the colour)
  std::vector<TubeInstance> ghostTubes;
  std::vector<SphereInstance> glows;         // flat point-lights, drawn additively
  std::vector<LineInstance> lines;           // depth-tested
  std::vector<LineInstance> overlayLines;    // drawn on top of everything

  void clearItems() {
    image = {};
    spheres.clear();
    tubes.clear();
    ghostSpheres.clear();
    ghostTubes.clear();
    glows.clear();
    lines.clear();
    overlayLines.clear();
  }
};

struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  bool orthographic = false;
};

}  // namespace ew::ui
