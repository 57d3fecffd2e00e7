// The viewer's colours that must be told apart stay apart for a typical eye and for each
// simulated dichromacy (ui/render/colour_vision.h): about 1 man in 12 has a red-green
// deficiency, and a teacher's projector shows the palette to all of them.
//
// The floor, CIEDE2000 ≥ 12 between any two such colours under full-severity protanopia,
// deuteranopia and tritanopia (the worst case; the commoner anomalous trichromats see more):
// a difference of about 1 is just noticeable between two large patches side by side, and
// the smaller the marks (lines 2-3 px wide, joint spheres, legend swatches) the larger the
// difference they need (Stone, Szafir & Setlur 2014, "An engineering model for color
// difference as a function of size"). The palette before this test had pairs at 1.6
// (deuteranopia: the skeleton engine's violet and the ground truth's blue) and 2.5
// (tritanopia: the estimated camera and the errors), and 6.4 for a typical eye.

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "ui/render/colour_vision.h"
#include "ui/render/palette.h"
#include "video/track_overlay.h"

namespace ew::ui::colour {
namespace {

constexpr float kApart = 12.0f;
// The 3D views' background (the mean of their gradient, ui/render/scene.h): the ghost is
// translucent over it.
const glm::vec3 kViewBackground{0.10f, 0.11f, 0.12f};

struct Named {
  std::string name;
  glm::vec3 colour;
};

Named opaque(const char* name, const glm::vec4& c) { return {name, glm::vec3(c)}; }

// Every pair of `colours` at least kApart for every vision; prints the closest pair.
void expectAllApart(const std::vector<Named>& colours, const char* where) {
  float closest = 1e9f;
  std::string which;
  for (Vision v : kVisions) {
    for (std::size_t i = 0; i < colours.size(); ++i) {
      for (std::size_t j = i + 1; j < colours.size(); ++j) {
        const float d = difference(colours[i].colour, colours[j].colour, v);
        EXPECT_GE(d, kApart) << where << ": " << colours[i].name << " and " << colours[j].name
                             << " for " << visionName(v);
        if (d < closest) {
          closest = d;
          which = colours[i].name + " and " + colours[j].name + " (" + visionName(v) + ")";
        }
      }
    }
  }
  std::printf("%s: closest pair %s, CIEDE2000 %.1f\n", where, which.c_str(), closest);
}

TEST(ColourDifference, MatchesSharmaWuAndDalalsTestData) {
  // Pairs 1-3, 7 and 17-20 of Sharma, Wu & Dalal (2005), table 1: L*, a*, b* and ΔE00.
  struct Pair {
    glm::vec3 a, b;
    float deltaE;
  };
  const Pair pairs[] = {{{50.0f, 2.6772f, -79.7751f}, {50.0f, 0.0f, -82.7485f}, 2.0425f},
                        {{50.0f, 3.1571f, -77.2803f}, {50.0f, 0.0f, -82.7485f}, 2.8615f},
                        {{50.0f, 2.8361f, -74.0200f}, {50.0f, 0.0f, -82.7485f}, 3.4412f},
                        {{50.0f, 0.0f, 0.0f}, {50.0f, -1.0f, 2.0f}, 2.3669f},
                        {{50.0f, 2.5f, 0.0f}, {73.0f, 25.0f, -18.0f}, 27.1492f},
                        {{50.0f, 2.5f, 0.0f}, {61.0f, -5.0f, 29.0f}, 22.8977f},
                        {{50.0f, 2.5f, 0.0f}, {56.0f, -27.0f, -3.0f}, 31.9030f},
                        {{50.0f, 2.5f, 0.0f}, {58.0f, 24.0f, 15.0f}, 19.4535f}};
  for (const Pair& p : pairs) {
    EXPECT_NEAR(deltaE2000(p.a, p.b), p.deltaE, 1e-3f);
    EXPECT_NEAR(deltaE2000(p.b, p.a), p.deltaE, 1e-3f);  // symmetric
  }
  // sRGB white is L* 100, a* = b* = 0 under D65.
  const glm::vec3 white = lab(glm::vec3(1.0f));
  EXPECT_NEAR(white.x, 100.0f, 0.01f);
  EXPECT_NEAR(white.y, 0.0f, 0.01f);
  EXPECT_NEAR(white.z, 0.0f, 0.01f);
}

TEST(ColourVisionSimulation, KeepsGreysAndLosesWhatEachDeficiencyLoses) {
  for (Vision v : kVisions) {
    for (float grey : {0.0f, 0.25f, 0.5f, 1.0f})
      EXPECT_LT(difference(glm::vec3(grey), seenAs(glm::vec3(grey), v), Vision::Typical), 0.5f)
          << visionName(v);
  }
  // Red against green: apart for a typical eye and a tritanope, close for the red-green
  // dichromats; blue against green: close only for a tritanope.
  const glm::vec3 red{0.8f, 0.2f, 0.1f}, green{0.3f, 0.6f, 0.1f}, blue{0.2f, 0.5f, 0.9f},
      teal{0.2f, 0.7f, 0.7f};
  const float redGreenTypical = difference(red, green, Vision::Typical);
  EXPECT_GT(redGreenTypical, 40.0f);
  EXPECT_GT(difference(red, green, Vision::Tritanopia), 30.0f);
  EXPECT_LT(difference(red, green, Vision::Protanopia), 0.5f * redGreenTypical);
  EXPECT_LT(difference(red, green, Vision::Deuteranopia), 0.5f * redGreenTypical);
  EXPECT_LT(difference(blue, teal, Vision::Tritanopia),
            0.5f * difference(blue, teal, Vision::Typical));
}

TEST(Palette, CompareModesColoursStayApartForEveryVision) {
  using namespace palette;
  const glm::vec3 truth(kGhostRight);  // the gait report's and the plots' motion capture, opaque
  // The 3D view: the ghost (translucent), the engines' walkers and the view's camera.
  expectAllApart({{"ghost", over(kGhostRight, kViewBackground)},
                  opaque("eigenwalker", kEngineRight[0]),
                  opaque("snippet", kEngineRight[1]),
                  opaque("skeleton", kEngineRight[2]),
                  opaque("camera", kCamera)},
                 "compare, 3D view");
  // The gait report's curves, the analysis window's and the errors panel's bars.
  expectAllApart({{"motion capture", truth},
                  opaque("eigenwalker", kEngineRight[0]),
                  opaque("snippet", kEngineRight[1]),
                  opaque("skeleton", kEngineRight[2])},
                 "compare, plots");
}

TEST(Palette, TheAnalysisAndProfilePlotsColoursStayApartForEveryVision) {
  using namespace palette;
  // The analysis window with the other engines: LSQ, MAP and the two engines' curves.
  expectAllApart({opaque("LSQ", kLsq), opaque("MAP", kMap), opaque("snippet", kEngineRight[1]),
                  opaque("skeleton", kEngineRight[2])},
                 "analysis");
  // J(α) and the camera fit's starts: the best minimum, the others, the true view, and in
  // compare mode the other engines' estimates.
  expectAllApart({opaque("best", kCameraEstimate), opaque("other minima", kOtherMinimum),
                  opaque("true view", kCamera), opaque("snippet", kEngineRight[1]),
                  opaque("skeleton", kEngineRight[2])},
                 "view-angle profile");
}

TEST(Palette, TheReconstructionViewsMarksStayApartForEveryVision) {
  using namespace palette;
  expectAllApart({{"ghost", over(kGhostRight, kViewBackground)},
                  opaque("reconstruction", kReconRight),
                  opaque("3D error", kError),
                  opaque("camera", kCamera),
                  opaque("estimated camera", kCameraEstimate)},
                 "reconstruction view");
}

TEST(Palette, TheTwoDInputViewsMarksStayApartForEveryVision) {
  using namespace palette;
  expectAllApart({opaque("input joints", kInputPoint), opaque("model-estimated", kModelEstimated),
                  opaque("reprojection", kReconRight), opaque("2D residual", kError)},
                 "2D input view");
}

TEST(Palette, AKeypointClipsMarksStayApartForEveryVision) {
  using namespace palette;
  // The clip's 2D view is darker than the 3D views (ui/panels/clip_view.cpp).
  const glm::vec3 clipBackground{0.06f, 0.07f, 0.08f};
  expectAllApart({opaque("keypoints", kInputPoint),
                  opaque("reprojection", kReconRight),
                  opaque("residual", kError),
                  opaque("principal point", kCamera),
                  {"other people", over(kOtherPerson, clipBackground)}},
                 "keypoint clip");
}

TEST(Palette, AVideosMarksStayApartForEveryVision) {
  using namespace palette;
  // Tracked, before the fit: the keyframe's marks and the joints by their confidence.
  expectAllApart(
      {opaque("keyframe marks", kCamera), opaque("lost", confidenceColour(0.0f)),
       opaque("half sure", confidenceColour(0.5f)), opaque("sure", confidenceColour(1.0f))},
      "video, tracked");
  // Fitted: the keyframe's marks, the tracked joints, the reprojection and its residuals. The
  // estimated principal point's cross shares the marks' teal (as the keypoint clip's does): a
  // thin cross, told from the marked skeleton by its shape.
  expectAllApart({opaque("keyframe marks", kCamera), opaque("tracked", kInputPoint),
                  opaque("reprojection", kReconRight), opaque("residual", kError)},
                 "video, fitted");
}

TEST(Palette, ATrackedJointsConfidenceReadsInOrderForEveryVision) {
  const auto at = [](float c) { return glm::vec3(palette::confidenceColour(c)); };
  for (Vision v : kVisions) {
    float previous = 0.0f;
    for (int k = 1; k <= 20; ++k) {
      const float fromLost = difference(at(0.0f), at(0.05f * static_cast<float>(k)), v);
      EXPECT_GT(fromLost, previous + 0.5f) << visionName(v) << " at confidence " << 0.05 * k;
      previous = fromLost;
    }
    EXPECT_GE(difference(at(0.0f), at(1.0f), v), 40.0f) << visionName(v);
    EXPECT_GE(difference(at(0.5f), at(1.0f), v), kApart) << visionName(v);
    EXPECT_GE(difference(at(0.0f), at(0.5f), v), kApart) << visionName(v);
  }
}

TEST(Palette, TheTrackOverlayWritesTheViewersConfidenceColours) {
  // One joint (the head) on a black frame, no bones: the dot's centre is its colour.
  for (float c : {0.0f, 0.5f, 1.0f}) {
    cv::Mat bgr(200, 200, CV_8UC3, cv::Scalar(0, 0, 0));
    Eigen::RowVectorXd joints =
        Eigen::RowVectorXd::Constant(30, std::numeric_limits<double>::quiet_NaN());
    joints(0) = 100.0;
    joints(1) = 100.0;
    Eigen::RowVectorXd confidence = Eigen::RowVectorXd::Constant(15, c);
    drawTrack(bgr, joints, confidence);
    const cv::Vec3b px = bgr.at<cv::Vec3b>(100, 100);
    const glm::vec4 want = palette::confidenceColour(c);
    EXPECT_NEAR(px[2], 255.0f * want.r, 1.5f) << "confidence " << c;
    EXPECT_NEAR(px[1], 255.0f * want.g, 1.5f) << "confidence " << c;
    EXPECT_NEAR(px[0], 255.0f * want.b, 1.5f) << "confidence " << c;
  }
}

TEST(Palette, TheDepthErrorMapReadsInOrderForEveryVisionOnTheReconstruction) {
  // Each step up the map further from its start for every vision (the map it replaced was
  // not, for a red-green dichromat: for a deuteranope its top was 23 CIEDE2000 from its start
  // and its middle 35), its ends far apart, and every colour of it apart from what it stands
  // among on the reconstruction: the figure's amber, the translucent ghost, the error lines,
  // a model-estimated joint's grey; and visible on the dark view.
  using namespace palette;
  const auto at = [](float t) { return glm::vec3(errorColour(t)); };
  const std::vector<Named> among{opaque("reconstruction", kReconRight),
                                 {"ghost", over(kGhostRight, kViewBackground)},
                                 opaque("3D error", kError),
                                 opaque("model-estimated", kModelEstimated)};
  for (Vision v : kVisions) {
    float previous = 0.0f;
    for (int k = 1; k <= 20; ++k) {
      const float t = 0.05f * static_cast<float>(k);
      const float fromStart = difference(at(0.0f), at(t), v);
      EXPECT_GT(fromStart, previous + 0.5f) << visionName(v) << " at t = " << t;
      previous = fromStart;
    }
    EXPECT_GE(difference(at(0.0f), at(1.0f), v), 40.0f) << visionName(v);
    for (int k = 0; k <= 20; ++k) {
      const float t = 0.05f * static_cast<float>(k);
      for (const Named& n : among)
        EXPECT_GE(difference(at(t), n.colour, v), kApart)
            << n.name << ", t = " << t << ", " << visionName(v);
      EXPECT_GE(difference(at(t), kViewBackground, v), 20.0f)
          << "t = " << t << ", " << visionName(v);
    }
  }
}

}  // namespace
}  // namespace ew::ui::colour
