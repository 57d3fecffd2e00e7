#pragma once
// The viewer's colours, chosen to separate on a dark background and on a projector:
// reconstruction warm (amber), ground truth cool (blue ghost), 2D input neutral white,
// errors magenta, the view camera teal, the estimated camera red. Depth error uses a
// sequential colour map. The colours that must be told apart stay apart for the common
// colour vision deficiencies too: tests/ui/test_colour_vision.cpp measures them
// (ui/render/colour_vision.h).

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>

#include "video/confidence_colour.h"

namespace ew::ui::palette {

inline constexpr glm::vec4 kReconRight{1.00f, 0.60f, 0.22f, 1.0f};
inline constexpr glm::vec4 kReconLeft{1.00f, 0.84f, 0.55f, 1.0f};
inline constexpr glm::vec4 kReconMid{1.00f, 0.72f, 0.38f, 1.0f};
inline constexpr glm::vec4 kGhostRight{0.36f, 0.62f, 1.00f, 0.38f};
inline constexpr glm::vec4 kGhostLeft{0.62f, 0.80f, 1.00f, 0.38f};
inline constexpr glm::vec4 kGhostMid{0.50f, 0.72f, 1.00f, 0.38f};
inline constexpr glm::vec4 kInputPoint{0.96f, 0.97f, 1.00f, 1.0f};
// A joint the trial's marker set lacks, estimated from a model: not a measured point-light.
// A neutral grey: on the reconstruction it stands among joints coloured by the error map,
// every one of whose colours it stays apart from for each colour vision.
inline constexpr glm::vec4 kModelEstimated{0.46f, 0.48f, 0.51f, 1.0f};
inline constexpr glm::vec4 kInputBoneRight{0.62f, 0.68f, 0.78f, 0.85f};
inline constexpr glm::vec4 kInputBoneLeft{0.42f, 0.47f, 0.56f, 0.85f};
// (Green 0.20, not 0.28: at 0.28 it was 11 CIEDE2000 from the camera's teal for a deuteranope.)
inline constexpr glm::vec4 kError{1.00f, 0.20f, 0.60f, 0.95f};
inline constexpr glm::vec4 kCamera{0.32f, 0.88f, 0.76f, 1.0f};
// Red: apart from the errors' magenta (it was a pink 2.5 CIEDE2000 from it for a tritanope
// and 6 for anyone) and from the true camera's teal, on the dark views and the light theme.
inline constexpr glm::vec4 kCameraEstimate{0.90f, 0.15f, 0.10f, 1.0f};
// The people of a keypoint clip besides the one fitted (the person picker's other tracks):
// a muted khaki, apart from the residuals' magenta (the violet it replaces was 3.6 CIEDE2000
// from it for a protanope), the keypoints' white, the reprojection's amber and the camera.
inline constexpr glm::vec4 kOtherPerson{0.58f, 0.55f, 0.22f, 0.75f};
inline constexpr glm::vec4 kTrail{0.55f, 0.75f, 1.00f, 0.30f};
// The horizon the footage's level lines give, dashed over the video: a pale steel, apart from
// the camera's teal (the fitted camera's horizon) and the keypoints' white.
inline constexpr glm::vec4 kSceneHorizon{0.72f, 0.78f, 0.90f, 0.80f};
inline constexpr glm::vec4 kAxis{0.40f, 0.44f, 0.50f, 0.8f};

// Compare mode: one colour per engine (index of kEngineKinds: eigenwalker, snippet,
// skeleton), the eigenwalker keeping the reconstruction's amber: a bluish green and a
// magenta, each apart from the others, the ground truth's blue and the camera's teal for
// every simulated dichromacy (the violet they replace was 1.6 CIEDE2000 from the truth's
// blue for a deuteranope).
inline constexpr std::array<glm::vec4, 3> kEngineRight{{{1.00f, 0.60f, 0.22f, 1.0f},
                                                         {0.05f, 0.61f, 0.38f, 1.0f},
                                                         {0.99f, 0.06f, 0.72f, 1.0f}}};
// The analysis window's estimators (with the engines' colours beside them when asked).
inline constexpr glm::vec4 kLsq{0.43f, 0.67f, 1.00f, 1.0f};
inline constexpr glm::vec4 kMap{1.00f, 0.63f, 0.24f, 1.0f};  // amber, as the reconstruction
// A local minimum of J(α) or a camera fit's start that is not the best (the best one is
// kCameraEstimate).
inline constexpr glm::vec4 kOtherMinimum{0.98f, 0.78f, 0.35f, 1.0f};
inline glm::vec4 engineLighter(const glm::vec4& c, float t) { return {glm::mix(glm::vec3(c), glm::vec3(1.0f), t), c.a}; }

// Sequential map for errors, t in [0, 1]: pale mint → cyan → lavender → violet → purple,
// lightness falling all the way, so that its order reads for every colour vision (each step
// further from its start for a typical eye and each simulated dichromat), apart from the
// reconstruction's amber it colours the joints of, and never too dark for the dark views.
// (Until 2026-11-27 it ran teal → green-yellow → amber → red → magenta: its middle was the
// figure's own amber, and a red-green dichromat could not order its upper half; for a
// deuteranope its top was nearer its start than its middle, 23 against 35 CIEDE2000.)
inline glm::vec4 errorColour(float t) {
  constexpr std::array<glm::vec3, 5> stops{{{0.78f, 1.00f, 0.90f},
                                             {0.39f, 0.87f, 0.90f},
                                             {0.76f, 0.54f, 1.00f},
                                             {0.79f, 0.24f, 0.99f},
                                             {0.70f, 0.00f, 0.87f}}};
  const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(stops.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(x), stops.size() - 2);
  const float f = x - static_cast<float>(i);
  return {glm::mix(stops[i], stops[i + 1], f), 1.0f};
}

// A tracked joint's confidence, c in [0, 1]: red (lost) to blue (sure), whose order every
// simulated dichromacy keeps (red to green did not: amber, half sure, looked further from
// red than green to a deuteranope), each apart from the keyframe marks' teal (a lighter sky
// blue was 7.4 CIEDE2000 from it for a tritanope). The viewer and video/track_overlay.cpp
// draw it (the ramp itself: video/confidence_colour.h, which the footage library shares).
inline glm::vec4 confidenceColour(float c) {
  const ConfidenceRgb rgb = confidenceRgb(c);
  return {static_cast<float>(rgb.r), static_cast<float>(rgb.g), static_cast<float>(rgb.b), 1.0f};
}

// The colour bar's top value: a round number of mm at or above `maxMm` (at least 20).
inline float errorScaleMm(float maxMm) {
  const std::array<float, 9> steps{20.f, 30.f, 50.f, 75.f, 100.f, 150.f, 200.f, 300.f, 500.f};
  for (float s : steps)
    if (maxMm <= s) return s;
  return std::ceil(maxMm / 500.0f) * 500.0f;
}

}  // namespace ew::ui::palette
