#pragma once
// A fitted camera's tilt and height as a reader says them, for captions and the header.

#include <cmath>
#include <cstdio>
#include <string>

namespace ew::ui {

// "1.2° down", "0.9° up" (the fit's elevation is positive looking down).
inline std::string tiltText(double elevationDeg) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f° %s", std::abs(elevationDeg), elevationDeg < 0.0 ? "up" : "down");
  return s;
}

// " ± 2.5°" for an angle's SD (CameraFit::sd); "" where the fit gives none or it was given.
// The spaces are no-break ones: a wrapped caption keeps the SD with its value.
inline std::string degreesSdText(double sdDeg) {
  if (!(std::isfinite(sdDeg) && sdDeg > 0.0)) return "";
  char s[32];
  std::snprintf(s, sizeof s, "\u00a0±\u00a0%.1f°", sdDeg);
  return s;
}

// The eye's height over the walker's canonical z = 0, which is her ankles' level (METHOD §2:
// the 5th percentile of the lower ankle), not the floor: "1.20 m above the ankles".
inline std::string heightOverAnklesText(double heightMm) {
  char s[48];
  std::snprintf(s, sizeof s, "%.2f m %s the ankles", std::abs(heightMm) / 1000.0, heightMm < 0.0 ? "below" : "above");
  return s;
}

}  // namespace ew::ui
