#pragma once
// The two views for a keypoint clip (Mode::Clip, docs/VIEWER.md "Keypoint clips"): the 2D
// input in image pixels (y down, as the video has them) with the 3D walker drawn back through
// the estimated camera, and the 3D walker with that camera where it stands. Both at the same
// input frame (clipFrameAt).

#include <glm/glm.hpp>
#include <vector>

#include "ui/app/clip.h"
#include "ui/render/camera.h"
#include "ui/render/scene.h"

namespace ew::ui {

struct AppState;

// The image region the 2D view shows: everything the clip's input and reprojection cover,
// padded. Scene coordinates are (u, −v) px so that the image's y runs down the screen.
struct ClipImageFrame {
  glm::vec2 centre{0.0f};  // scene coordinates
  float heightPx = 1.0f;
};
ClipImageFrame clipImageFrame(const ClipResult& clip, float aspect);
CameraMatrices clipInputCamera(const ClipImageFrame& frame, float aspect);

// The people in `frame` besides the one fitted: their track number (1-based, as the person
// picker names them) and the top of their keypoints (scene coordinates), for their label.
struct OtherPerson {
  int track = 0;
  glm::vec2 top{0.0f};
};
std::vector<OtherPerson> otherPeopleAt(const KeypointTrial& trial, int frame);

// `frame`: the input frame shown; `view`: the image region shown (points are sized to it).
// Return false when there is no fit to show.
bool buildClipInputScene(const AppState& s, Scene& scene, float lineScale, int frame, const ClipImageFrame& view);
bool buildClipReconstructionScene(const AppState& s, Scene& scene, float lineScale, int frame);

// The camera in the 3D view's coordinates (the walker's canonical frame with its origin where
// the walker stands mid-clip), and where the walker is at `frame`.
struct ClipWorld {
  glm::vec3 eye, lookAt, right, down, forward;
  glm::vec3 walkerOffset;  // add to the walker's canonical frame at this frame
  bool pinhole = true;
};
ClipWorld clipWorld(const ClipResult& clip, int frame);

// The 3D view's camera for a clip at `frame`: the user's orbit camera, its target taken
// relative to where the walker stands (the view follows the walker across the floor).
OrbitCamera clipViewCamera(const OrbitCamera& camera, const ClipResult& clip, int frame);

}  // namespace ew::ui
