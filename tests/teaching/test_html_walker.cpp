// core/teaching/html_walker.h: the self-contained HTML walker and where it draws its dots.
#include <gtest/gtest.h>

#include <numbers>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/teaching/html_walker.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// Walker 3 of the default model of real walkers, its time origin at φ = 0.7 rad.
HtmlWalker realWalker() {
  const EigenwalkerModel& model = defaultRealModel();
  HtmlWalker walker;
  walker.w = storedWalkerVectors(model).col(3);
  walker.omegaRadS = model.omegasRadS(3);
  walker.phaseRad = 0.7;
  walker.name = "walker " + model.walkerIds[3];
  return walker;
}

TEST(HtmlWalker, PageIsSelfContained) {
  HtmlWalkerSettings s;
  s.title = "Walker <one> & \"two\"";
  s.caption = "line one\nline two";
  const std::string page = walkerHtml(realWalker(), s);
  for (const char* banned :
       {"http:", "https:", "://", "src=", "fetch", "XMLHttpRequest", "import", "url(", "<link",
        "<img", "<iframe", "WebSocket", "EventSource", "sendBeacon", "<script src"})
    EXPECT_EQ(page.find(banned), std::string::npos) << banned;
  EXPECT_NE(page.find("Content-Security-Policy\" content=\"default-src 'none';"),
            std::string::npos);
  EXPECT_EQ(page.find("<one>"), std::string::npos) << "the title is escaped";
  EXPECT_NE(page.find("Walker &lt;one&gt; &amp; &quot;two&quot;"), std::string::npos);
  EXPECT_NE(page.find("line one<br>line two"), std::string::npos);
  EXPECT_EQ(page.find("</script>"), page.rfind("</script>")) << "one inline script";
}

// Every coefficient is in the page with 17 significant digits: parsed back, bit for bit.
TEST(HtmlWalker, PageHoldsTheCoefficientsExactly) {
  const HtmlWalker walker = realWalker();
  const std::string page = walkerHtml(walker, {});
  const std::size_t begin = page.find("const W = [");
  ASSERT_NE(begin, std::string::npos);
  std::istringstream in(page.substr(begin + 11, page.find(']', begin) - begin - 11));
  Eigen::VectorXd parsed(kFourierDims3);
  for (Eigen::Index i = 0; i < parsed.size(); ++i) {
    std::string item;
    ASSERT_TRUE(std::getline(in, item, ',')) << "value " << i;
    parsed(i) = std::stod(item);
  }
  EXPECT_TRUE(test::bitwiseEqual(parsed, walker.w));
  char omega[96];
  std::snprintf(omega, sizeof omega, "const OMEGA = %.17g, PHI = %.17g;", walker.omegaRadS,
                walker.phaseRad);
  EXPECT_NE(page.find(omega), std::string::npos);
}

// In the viewer's framing the dots are the viewer's 2D view: its frameAtPhase of the walker
// projected at α (ui/app/derived.cpp), through its image camera (2350 mm high, v = 975 mm at
// the centre row; ui/panels/input_view_panel.cpp), at the same phase.
TEST(HtmlWalker, FirstFrameIsTheViewersProjection) {
  const HtmlWalker walker = realWalker();
  HtmlWalkerSettings s;
  s.framing = HtmlFraming::Viewer;
  for (double alpha : {-135.0, 0.0, 30.0, 90.0}) {
    for (double phase01 : {0.0, 0.25, 0.6}) {
      s.viewAngleDeg = alpha;
      s.startPhase01 = phase01;
      s.translate = true;  // no progression yet at τ = 0
      const Eigen::MatrixXd dots = htmlWalkerDotsPx(walker, s, 0.0);
      Eigen::VectorXd theta(1);
      theta(0) = 2.0 * std::numbers::pi * phase01;
      const Eigen::MatrixXd uv = synthesizeFrames(projectToView(walker.w, alpha), 1.0, 0.0, theta);
      const double pxPerMm = 600.0 / 2350.0;
      for (int j = 0; j < kJointCount; ++j) {
        EXPECT_NEAR(dots(j, 0), 400.0 + pxPerMm * uv(0, 2 * j), 1e-9)
            << "α " << alpha << " joint " << j;
        EXPECT_NEAR(dots(j, 1), 300.0 - pxPerMm * (uv(0, 2 * j + 1) - 975.0), 1e-9)
            << "α " << alpha;
      }
    }
  }
}

// τ seconds later the page shows p(t0 + speed·τ): the cycle angle 2π·startPhase01 + ω·speed·τ,
// whatever the walker's own time origin φ.
TEST(HtmlWalker, DotsFollowTheWalkersTime) {
  const HtmlWalker walker = realWalker();
  HtmlWalker shifted = walker;
  shifted.phaseRad = -2.1;
  HtmlWalkerSettings s;
  s.playbackSpeed = -0.5;
  s.startPhase01 = 0.3;
  for (double tau : {0.0, 0.37, 2.0})
    EXPECT_LT((htmlWalkerDotsPx(walker, s, tau) - htmlWalkerDotsPx(shifted, s, tau))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-9);
  // One stride at speed −0.5 is 2 · 2π/ω seconds of page time: the same frame again.
  const double stride = 2.0 * 2.0 * std::numbers::pi / walker.omegaRadS;
  EXPECT_LT((htmlWalkerDotsPx(walker, s, stride) - htmlWalkerDotsPx(walker, s, 0.0))
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
}

// The fitted framing keeps every dot inside the canvas, by its margin, at every α and phase.
TEST(HtmlWalker, FitFramingKeepsTheWalkerInside) {
  const HtmlWalker walker = realWalker();
  for (double elevation : {0.0, 30.0}) {
    HtmlWalkerSettings s;
    s.elevationDeg = elevation;
    s.widthPx = 500;
    s.heightPx = 700;
    const double margin = s.dotRadiusPx + 0.05 * 500;
    double lowest = 1e9, highest = -1e9;
    for (double alpha = -180.0; alpha < 180.0; alpha += 15.0) {
      s.viewAngleDeg = alpha;
      for (double tau = 0.0; tau < 1.2; tau += 0.05) {
        const Eigen::MatrixXd dots = htmlWalkerDotsPx(walker, s, tau);
        EXPECT_GE(dots.col(0).minCoeff(), margin - 1e-6);
        EXPECT_LE(dots.col(0).maxCoeff(), 500.0 - margin + 1e-6);
        EXPECT_GE(dots.col(1).minCoeff(), margin - 1e-6);
        EXPECT_LE(dots.col(1).maxCoeff(), 700.0 - margin + 1e-6);
        lowest = std::min(lowest, dots.col(1).minCoeff());
        highest = std::max(highest, dots.col(1).maxCoeff());
      }
    }
    // A tall canvas: the walker's height fills it (to a few pixels of the margin).
    if (elevation == 0.0) {
      EXPECT_LT(lowest - margin, 3.0);
      EXPECT_GT(highest, 700.0 - margin - 3.0);
    }
  }
}

// Overground, the walker moves by its speed in the image and wraps round the canvas.
TEST(HtmlWalker, TranslationMovesAndWraps) {
  const HtmlWalker walker = realWalker();
  HtmlWalkerSettings s;
  s.viewAngleDeg = 90.0;
  s.translateSpeedMps = 1.0;
  const Eigen::MatrixXd still = htmlWalkerDotsPx(walker, s, 0.25);
  s.translate = true;
  const HtmlCanvasMapping m = htmlCanvasMapping(walker, s);
  const Eigen::MatrixXd moved = htmlWalkerDotsPx(walker, s, 0.25);
  EXPECT_NEAR((moved.col(0) - still.col(0)).mean(), 250.0 * m.pxPerMm,
              1e-6);  // 250 mm to the right
  EXPECT_LT((moved.col(1) - still.col(1)).cwiseAbs().maxCoeff(), 1e-9);
  // Later, past the right edge: back from the left, the offset within half a period.
  const double tau = 0.8 * m.wrapXPx / (1000.0 * m.pxPerMm);
  HtmlWalkerSettings treadmill = s;
  treadmill.translate = false;
  const double offset =
      (htmlWalkerDotsPx(walker, s, tau) - htmlWalkerDotsPx(walker, treadmill, tau)).col(0).mean();
  EXPECT_NEAR(offset, (0.8 - 1.0) * m.wrapXPx, 1e-6);
}

TEST(HtmlWalker, RefusesBadInputNamingTheFile) {
  const auto dir = test::makeTempDir("html_walker_bad");
  const auto path = dir / "walker.html";
  const HtmlWalker good = realWalker();
  auto refuses = [&](const HtmlWalker& w, const HtmlWalkerSettings& s, std::string_view part) {
    EXPECT_TRUE(test::throwsError([&] { writeWalkerHtml(path, w, s); }, ErrorKind::BadArgument,
                                  {path.string(), "HTML walker: ", part}));
    EXPECT_FALSE(std::filesystem::exists(path));
  };
  HtmlWalker w = good;
  w.w(17) = std::numeric_limits<double>::quiet_NaN();
  refuses(w, {}, "non-finite");
  w = good;
  w.w.conservativeResize(150);
  refuses(w, {}, "225 values");
  w = good;
  w.omegaRadS = 0.0;
  refuses(w, {}, "ω must be positive");
  w = good;
  w.phaseRad = std::numeric_limits<double>::infinity();
  refuses(w, {}, "φ must be finite");
  w = good;
  w.w.setZero();
  refuses(w, {}, "no extent");
  const auto bad = [&](auto change, std::string_view part) {
    HtmlWalkerSettings s;
    change(s);
    refuses(good, s, part);
  };
  bad([](HtmlWalkerSettings& s) { s.viewAngleDeg = std::nan(""); }, "view angle");
  bad([](HtmlWalkerSettings& s) { s.elevationDeg = 95.0; }, "elevation");
  bad([](HtmlWalkerSettings& s) { s.playbackSpeed = 7.0; }, "playback speed");
  bad([](HtmlWalkerSettings& s) { s.startPhase01 = std::nan(""); }, "start phase");
  bad([](HtmlWalkerSettings& s) { s.translateSpeedMps = -1.0; }, "translation speed");
  bad([](HtmlWalkerSettings& s) { s.widthPx = 10; }, "canvas width");
  bad([](HtmlWalkerSettings& s) { s.dotRadiusPx = 0.0; }, "dot radius");
  bad([](HtmlWalkerSettings& s) { s.heightPx = 100, s.dotRadiusPx = 40.0; }, "too little room");
  bad([](HtmlWalkerSettings& s) { s.dotColour = "white"; }, "#rrggbb");
  bad([](HtmlWalkerSettings& s) { s.backgroundColour = "#12345g"; }, "#rrggbb");
  bad([](HtmlWalkerSettings& s) { s.title = "a\tb"; }, "control character");
  bad([](HtmlWalkerSettings& s) { s.caption = std::string(2001, 'x'); }, "at most 2000");
  EXPECT_TRUE(test::throwsError([&] { htmlWalkerDotsPx(good, {}, std::nan("")); },
                                ErrorKind::BadArgument, {"time must be finite"}));
}

TEST(HtmlWalker, WritesThePageAtomically) {
  const auto dir = test::makeTempDir("html_walker_write");
  HtmlWalkerSettings s;
  s.theme = HtmlTheme::Light;
  s.lines = true;
  writeWalkerHtml(dir / "walker.html", realWalker(), s);
  EXPECT_EQ(test::readTextFile(dir / "walker.html"), walkerHtml(realWalker(), s));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1)
      << "no temporary file left";
  EXPECT_EQ(htmlColours(s).background, "#ffffff");
  EXPECT_EQ(htmlFrozenFragment(0.25), "#t=0.25");
}

}  // namespace
}  // namespace ew
