#pragma once
// The controls panel's part for a keypoint clip (Mode::Clip): layout, frame rate and person,
// and the camera values the user can hold (focal length typed, elevation and azimuth
// dragged), each refitting the clip in the background.

namespace ew::ui {

struct AppState;

void drawClipControls(AppState& s);

}  // namespace ew::ui
