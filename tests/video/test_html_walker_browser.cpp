// The HTML walker (core/teaching/html_walker.h) opened in a real browser: headless Chromium
// loads the page, held at a frame by its #t= address, and screenshots it at 800 × 600; the
// dots found in the PNG (OpenCV) are where htmlWalkerDotsPx says, each within 1 px. In the
// viewer's framing that is the viewer's 2D view at the same phase and α
// (tests/teaching/test_html_walker.cpp, FirstFrameIsTheViewersProjection).
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/skeleton.h"
#include "core/eigenwalker/default_model.h"
#include "core/teaching/html_walker.h"
#include "tests/common/test_support.h"
#include "tests/video/html_browser.h"

namespace ew {
namespace {

using test::Blob;
using test::findDots;
using test::kBrowserHeight;
using test::kBrowserWidth;
using test::screenshot;
using test::Screenshot;
constexpr int kWidth = kBrowserWidth, kHeight = kBrowserHeight;

// Dots nearer each other than this may touch in the image: their blob is one. Those are
// checked as a group (a blob over them), the others one by one.
double touchingPx(double radiusPx) { return 2.0 * radiusPx + 3.0; }

struct Comparison {
  double maxErrorPx = 0.0, meanErrorPx = 0.0;
  int isolated = 0;
};

// Each dot alone has a blob within 1 px of where htmlWalkerDotsPx put it; dots that may
// touch have a blob near them; every blob is a dot's (nothing else is drawn in the colour).
Comparison compareDots(const std::vector<Blob>& blobs, const Eigen::MatrixXd& expected,
                       double radiusPx) {
  Comparison c;
  std::vector<int> group(kJointCount);
  for (int j = 0; j < kJointCount; ++j) group[static_cast<std::size_t>(j)] = j;
  const auto rootOf = [&](int j) {
    while (group[static_cast<std::size_t>(j)] != j) j = group[static_cast<std::size_t>(j)];
    return j;
  };
  for (int a = 0; a < kJointCount; ++a)
    for (int b = a + 1; b < kJointCount; ++b)
      if ((expected.row(a) - expected.row(b)).norm() < touchingPx(radiusPx))
        group[static_cast<std::size_t>(rootOf(b))] = rootOf(a);
  std::vector<int> roots;
  for (int j = 0; j < kJointCount; ++j) {
    const int r = rootOf(j);
    if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
  }
  EXPECT_GE(blobs.size(), roots.size()) << "a dot is missing";
  EXPECT_LE(blobs.size(), static_cast<std::size_t>(kJointCount)) << "more blobs than dots";
  for (const Blob& b : blobs) {  // nothing drawn where no dot is
    double nearest = 1e9;
    for (int j = 0; j < kJointCount; ++j)
      nearest = std::min(nearest, cv::norm(b.centre - cv::Point2d(expected(j, 0), expected(j, 1))));
    EXPECT_LE(nearest, 0.5 * touchingPx(radiusPx) + 1.0)
        << "a blob of " << b.area << " px at (" << b.centre.x << ", " << b.centre.y << ")";
  }
  double sum = 0.0;
  for (int j = 0; j < kJointCount; ++j) {
    const cv::Point2d want(expected(j, 0), expected(j, 1));
    const auto nearest =
        std::min_element(blobs.begin(), blobs.end(), [&](const Blob& a, const Blob& b) {
          return cv::norm(a.centre - want) < cv::norm(b.centre - want);
        });
    if (nearest == blobs.end()) {
      ADD_FAILURE() << "no dot drawn at all";
      return c;
    }
    const double error = cv::norm(nearest->centre - want);
    int members = 0;
    for (int k = 0; k < kJointCount; ++k) members += rootOf(k) == rootOf(j) ? 1 : 0;
    const bool alone = members == 1;
    if (alone) {
      EXPECT_LE(error, 1.0) << kJointNames[static_cast<std::size_t>(j)] << " drawn at ("
                            << nearest->centre.x << ", " << nearest->centre.y << "), expected ("
                            << want.x << ", " << want.y << ")";
      c.maxErrorPx = std::max(c.maxErrorPx, error);
      sum += error;
      ++c.isolated;
    } else {
      EXPECT_LE(error, touchingPx(radiusPx) * 2.0)
          << kJointNames[static_cast<std::size_t>(j)] << " (touching)";
    }
  }
  c.meanErrorPx = c.isolated > 0 ? sum / c.isolated : 0.0;
  return c;
}

HtmlWalker defaultMeanWalker() {
  const EigenwalkerModel& model = defaultRealModel();
  return {model.mean, model.omegasRadS.mean(), 0.4, "mean walker"};
}

void checkPage(const std::string& name, const HtmlWalker& walker,
               const HtmlWalkerSettings& settings, double timeS) {
  const auto dir = test::makeTempDir("html_walker_browser_" + name);
  const auto page = dir / (name + ".html");
  writeWalkerHtml(page, walker, settings);
  const Screenshot shot = screenshot(page, timeS, dir);
  ASSERT_FALSE(shot.image.empty()) << "no screenshot; Chromium said:\n" << shot.log;
  ASSERT_EQ(shot.image.cols, kWidth);
  ASSERT_EQ(shot.image.rows, kHeight);
  const Eigen::MatrixXd expected = htmlWalkerDotsPx(walker, settings, timeS);
  const Comparison c =
      compareDots(findDots(shot.image, htmlColours(settings)), expected, settings.dotRadiusPx);
  EXPECT_GE(c.isolated, 10) << "too few dots apart from the others to measure";
  // 1 px tells frames apart: 50 ms later some dot has moved several pixels.
  const Eigen::MatrixXd later = htmlWalkerDotsPx(walker, settings, timeS + 0.05);
  EXPECT_GT((later - expected).rowwise().norm().maxCoeff(), 3.0);
  std::cout << name << ": " << c.isolated << " dots apart, error max " << c.maxErrorPx
            << " px, mean " << c.meanErrorPx << " px; page " << std::filesystem::file_size(page)
            << " bytes; Chromium " << shot.seconds << " s\n";
  ::testing::Test::RecordProperty("max_error_px", std::to_string(c.maxErrorPx));
}

// The viewer's 2D view: its framing, at α = 45° and phase 0.3, the first frame.
TEST(HtmlWalkerBrowser, FirstFrameIsTheViewersView) {
  EW_REQUIRE_BROWSER();
  HtmlWalkerSettings s;
  s.framing = HtmlFraming::Viewer;
  s.viewAngleDeg = 45.0;
  s.startPhase01 = 0.3;
  s.dotRadiusPx = 4.0;
  checkPage("viewer_view", defaultMeanWalker(), s, 0.0);
}

// The fitted framing, light theme, the bones drawn, walking overground, elevated, 0.7 s on.
TEST(HtmlWalkerBrowser, LaterFrameOverground) {
  EW_REQUIRE_BROWSER();
  HtmlWalkerSettings s;
  s.theme = HtmlTheme::Light;
  s.lines = true;
  s.translate = true;
  s.viewAngleDeg = -60.0;
  s.elevationDeg = 10.0;
  s.playbackSpeed = 0.8;
  s.dotRadiusPx = 5.0;
  checkPage("overground", defaultMeanWalker(), s, 0.7);
}

}  // namespace
}  // namespace ew
