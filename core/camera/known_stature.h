#pragma once
// A walker's stature, when the user knows it, fixes what no image can: the scale. A pinhole's
// image of a walker s times taller, s times further away and walking s times faster is the
// same image, so with everything unknown the fit's size is the model's prior on body size —
// off by SD 4.4 % on the camera experiment's clips (docs/RESULTS.md, "Gait measures from one
// camera"), and every distance and speed with it. Given the stature, the fit is scaled to it:
// the walker, the camera's distance and the walk over the floor, by the same s; the image,
// the angles and the focal length do not change.

#include "core/camera/clip_reconstruction.h"
#include "core/camera/detection_loop.h"

namespace ew {

// Statures a person has (m): outside these a given stature is a typo (cm for m, …).
inline constexpr double kMinStatureM = 0.5, kMaxStatureM = 2.5;

// The fit scaled so that its stature (CameraFit::statureMm, from its head height) is
// statureMm: every position, the camera's distance and look-at height, the walk's start and
// speed, the stride length, head height and stature. A scaled-orthographic camera's px/mm is
// divided instead; the SDs (CameraFit::sd) become those given the stature. Error(BadArgument)
// "stature: …" for a stature outside the range above or a fit with no stature. The model
// coefficients (CameraFit::k) stay the fit's before scaling: the scaled walker is w, not the
// model's mean plus k.
void scaleToStature(ClipReconstruction& clip, double statureMm);
void scaleToStature(DetectionLoop& loop, double statureMm);

}  // namespace ew
