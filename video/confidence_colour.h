#pragma once
// A tracked joint's confidence as a colour, one ramp for the CLI's overlays
// (video/track_overlay.cpp) and the viewer (ui/render/palette.h): red (lost) to blue (sure),
// RGB in [0, 1]. Why these two: ui/render/palette.h, confidenceColour.

namespace ew {

struct ConfidenceRgb {
  double r, g, b;
};

inline constexpr ConfidenceRgb kLostRgb{0.86, 0.12, 0.02};
inline constexpr ConfidenceRgb kSureRgb{0.34, 0.51, 0.98};

// `c` clamped to [0, 1]: lost at 0, sure at 1, a straight line between.
inline ConfidenceRgb confidenceRgb(double c) {
  c = c < 0.0 ? 0.0 : (c > 1.0 ? 1.0 : c);
  return {kLostRgb.r + (kSureRgb.r - kLostRgb.r) * c, kLostRgb.g + (kSureRgb.g - kLostRgb.g) * c,
          kLostRgb.b + (kSureRgb.b - kLostRgb.b) * c};
}

}  // namespace ew
