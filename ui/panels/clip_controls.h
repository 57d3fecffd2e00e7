#pragma once
// The controls panel's part for a keypoint clip (Mode::Clip): layout, frame rate and person,
// and the camera values the user can hold (focal length typed, elevation and azimuth
// dragged), each refitting the clip in the background.

namespace ew::ui {

struct AppState;

void drawClipControls(AppState& s);
// A video's part (ui/app/video.h): scrub, mark joints (guided, undo / redo), the frames to
// track, Track with progress and Cancel, what the track gave (ui/panels/video_controls.cpp).
void drawVideoControls(AppState& s, float scale);

}  // namespace ew::ui
