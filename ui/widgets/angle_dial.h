#pragma once
// The view angle as a dial: the walking line seen from above, the walker in the middle facing
// the α = 0° camera at the bottom, and the camera on the rim at α (the 3D view's camera glyph:
// positive α to the right). Click or drag on it to move the camera.

namespace ew::ui {

// Returns true when the user moved the camera; `alphaDeg` then holds the new angle (whole
// degrees, in [-180, 180]).
bool angleDial(const char* id, double& alphaDeg, float radius);

}  // namespace ew::ui
