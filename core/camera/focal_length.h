#pragma once
// One rule for a focal length in pixels (f = the lens's focal length / the pixel pitch),
// wherever one enters: a calibration file's matrix, --focal-px, the viewer's focal field and
// the scale-depth relation's estimate. Each caller throws its own kind of error with the
// sentence focalLengthProblem gives, so the rule and its wording live here once.

#include <string>

namespace ew {

// 50 px is a 162° field of view across a 640-px picture, wider than a pinhole models (a
// fisheye's); 100000 px is 1.1° across 1920 px, a 1.8 m walker filling a 1080-px picture from
// 170 m away. Outside, the number is a typo, a wrong unit (mm, m) or a corrupt file, and would
// only be reported back ("focal inf px") or drop every point as outside the picture.
inline constexpr double kMinFocalPx = 50.0, kMaxFocalPx = 100000.0;

// Finite and within [kMinFocalPx, kMaxFocalPx].
bool isPlausibleFocalPx(double focalPx);

// "" for a plausible focal length, else why it is not one ("focal length 1e+308 px: a
// camera's is finite and 50-100000 px").
std::string focalLengthProblem(double focalPx);

}  // namespace ew
