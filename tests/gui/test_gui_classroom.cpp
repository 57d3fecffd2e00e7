// The classroom kit in the viewer (issue 56): each display is one key and draws what it
// should in the 2D view; the quiz steps its noise by the answers and saves its trials; the
// audience window shows only the stage at its own size and theme; the walker exported as a
// web page draws, in headless Chromium, where the viewer's 2D view draws it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"
#include "tests/video/html_browser.h"

namespace ew::test::gui {
namespace {

using GuiClassroom = GuiTest;

// Blobs of saturated point-light pixels (area ≥ `least`), each one's centre.
std::vector<cv::Point2d> pointLightBlobs(const cv::Mat& bgr, int least = 12) {
  cv::Mat mask(bgr.size(), CV_8U);
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      mask.at<uchar>(y, x) = isPointLight(p[2], p[1], p[0]) ? 255 : 0;
    }
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  std::vector<cv::Point2d> blobs;
  for (int i = 1; i < n; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) >= least)
      blobs.push_back({centroids.at<double>(i, 0) + 0.5, centroids.at<double>(i, 1) + 0.5});
  return blobs;
}

// The depth-reversed walker's rings in the 2D view (palette::kOtherMinimum, a warm yellow).
bool isRingYellow(int r, int g, int b) { return r > 200 && g > 150 && b < 140 && r - b > 100; }

nlohmann::json readJson(const std::filesystem::path& file) { return nlohmann::json::parse(readAll(file)); }

TEST_F(GuiClassroom, EachDisplayIsOneKeyAndDrawsItsDots) {
  const auto d = dir.string();
  // Explore mode's walker in profile, dots only, held at one phase, in presentation mode (its
  // large views frame every display's walker alike); each display on by its key (then off
  // again), a screenshot and the state of each.
  std::string script = R"([{"set_mode": "explore"}, {"play": false}, {"set_angle": 90}, {"set_phase": 0.3},
    {"overlay": ["point_lights", true]}, {"presentation": true}, {"wait_frames": 2},
    {"screenshot": ")" + d + R"(/plain.png"}, {"export_state": ")" + d + R"(/plain.json"})";
  const std::vector<std::pair<std::string, std::string>> displays = {
      {"inverted", "i"}, {"scrambled", "x"}, {"masked", "k"}, {"lifetime", "l"},
      {"backwards", "w"}, {"overground", "o"}, {"reversed", "d"}};
  for (const auto& [name, key] : displays)
    script += R"(, {"key": ")" + key + R"("}, {"wait_frames": 2}, {"screenshot": ")" + d + "/" + name +
              R"(.png"}, {"export_state": ")" + d + "/" + name + R"(.json"}, {"key": "0"})";
  script += R"(, {"key": "t"}, {"wait_frames": 20}, {"export_state": ")" + d + R"(/turning.json"}, {"key": "t"}])";
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(writeScript(dir, script).string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const nlohmann::json plainState = readJson(dir / "plain.json");
  EXPECT_FALSE(plainState["stage"]["drawn"].get<bool>());
  const Region input = viewRegion(plainState, "input", 1600, 900);
  const cv::Mat plain = crop(load("plain.png"), input);
  const auto plainDots = pointLightBlobs(plain);
  std::printf("plain: %zu dots\n", plainDots.size());
  EXPECT_GE(plainDots.size(), 10u);
  EXPECT_LE(plainDots.size(), 15u);

  const auto stage = [&](const std::string& name) { return readJson(dir / (name + ".json"))["stage"]; };
  EXPECT_TRUE(stage("inverted")["inverted"].get<bool>());
  EXPECT_EQ(stage("scrambled")["scramble"], "phase");
  EXPECT_EQ(stage("masked")["mask_dots"], 100);
  EXPECT_GT(stage("lifetime")["dot_lifetime_s"].get<double>(), 0.0);
  EXPECT_TRUE(stage("backwards")["backwards"].get<bool>());
  EXPECT_TRUE(stage("overground")["overground"].get<bool>());
  EXPECT_TRUE(stage("reversed")["depth_reversed"].get<bool>());
  for (const auto& [name, key] : displays) {
    EXPECT_TRUE(stage(name)["drawn"].get<bool>()) << name;
    const cv::Mat shown = crop(load(name + ".png"), input);
    const double diff = meanAbsDiff(shown, plain);
    std::printf("%s: %zu dots, differs from the plain view by %.2f\n", name.c_str(), pointLightBlobs(shown).size(), diff);
    if (name != "reversed") {
      EXPECT_GT(diff, 0.3) << name << " looks like the plain walker";
    }
  }
  // The mask adds its 100 noise dots (some overlap); limited lifetime draws 8 dots.
  EXPECT_GE(pointLightBlobs(crop(load("masked.png"), input)).size(), plainDots.size() + 50);
  EXPECT_LE(pointLightBlobs(crop(load("lifetime.png"), input)).size(), 8u);
  // The depth-reversed walker projects onto the true one: each of its rings is centred on one
  // of the walker's dots: round each dot whose ring no other crosses, the yellow pixels at the
  // ring's radius have their centre within 1 px of the dot's.
  const cv::Mat reversed = crop(load("reversed.png"), input);
  EXPECT_GT(countPixels(reversed, isRingYellow), 200);
  const auto reversedDots = pointLightBlobs(reversed);
  EXPECT_GE(reversedDots.size(), plainDots.size() - 2);
  // The rings' radius: 1.5 dots of 34 mm, in a view 2350 mm high (the viewer's framing).
  const double ringPx = 51.0 * plainState["layout"]["input"][3].get<double>() / 2350.0;
  std::vector<double> offsets;
  for (const cv::Point2d& dot : reversedDots) {
    // Only dots whose ring no other ring crosses, and the crop does not cut.
    const double edge = ringPx + 4.0;
    bool alone = dot.x > edge && dot.y > edge && dot.x < reversed.cols - edge && dot.y < reversed.rows - edge;
    for (const cv::Point2d& other : reversedDots)
      if (other != dot && cv::norm(other - dot) < 2.0 * ringPx + 4.0) alone = false;
    if (!alone) continue;
    cv::Point2d sum(0.0, 0.0);
    int n = 0;
    for (int y = std::max(0, static_cast<int>(dot.y) - 25); y < std::min(reversed.rows, static_cast<int>(dot.y) + 25); ++y)
      for (int x = std::max(0, static_cast<int>(dot.x) - 25); x < std::min(reversed.cols, static_cast<int>(dot.x) + 25); ++x) {
        const cv::Vec3b p = reversed.at<cv::Vec3b>(y, x);
        const double fromDot = cv::norm(cv::Point2d(x + 0.5, y + 0.5) - dot);
        if (isRingYellow(p[2], p[1], p[0]) && std::abs(fromDot - ringPx) < 3.0)
          sum += cv::Point2d(x + 0.5, y + 0.5), ++n;
      }
    if (n > 20) offsets.push_back(cv::norm(sum / n - dot));
  }
  ASSERT_GE(offsets.size(), 4u);
  const double worst = *std::max_element(offsets.begin(), offsets.end());
  std::printf("depth-reversed rings: %zu apart, largest offset from their dots %.2f px\n", offsets.size(), worst);
  EXPECT_LE(worst, 1.0);
  // The turning stage turned while T was on, and the 3D camera with it.
  const nlohmann::json turning = readJson(dir / "turning.json");
  EXPECT_TRUE(turning["stage"]["turning"].get<bool>());
  EXPECT_GT(std::abs(turning["stage"]["turned_deg"].get<double>()), 0.1);
  EXPECT_NE(turning["view"]["camera"]["yaw_deg"].get<double>(), plainState["view"]["camera"]["yaw_deg"].get<double>());
}

// The quiz: answered by the arrow keys, stopped, saved; the CSV's noise follows the 1-up-2-down
// rule trial by trial, and its answers are the keys pressed.
TEST_F(GuiClassroom, QuizStepsTheNoiseByTheAnswersAndSavesThem) {
  const auto d = dir.string();
  const std::vector<std::string> keys = {"left", "left", "right", "left", "right", "right", "left",
                                         "right", "left", "left", "right", "left"};
  std::string script = R"([{"set_mode": "explore"}, {"play": false},
    {"quiz_start": {"start_dots": 40, "step_dots": 10, "reversals": 30, "averaged": 4, "seed": 7}},
    {"export_state": ")" + d + R"(/started.json"})";
  for (const std::string& k : keys) script += R"(, {"key": ")" + k + R"("})";
  script += R"(, {"screenshot": ")" + d + R"(/quiz.png"}, {"key": "q"}, {"export_state": ")" + d +
            R"(/stopped.json"}, {"save_quiz": ")" + d + R"(/quiz.csv"},
    {"expect_failure": {"quiz_answer": "left"}}])";
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(writeScript(dir, script).string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json started = readJson(dir / "started.json");
  EXPECT_TRUE(started["quiz"]["running"].get<bool>());
  EXPECT_EQ(started["quiz"]["noise_dots"], 40);
  EXPECT_EQ(started["stage"]["mask_dots"], 0) << "the quiz's noise is its own, not the stage's setting";
  const nlohmann::json stopped = readJson(dir / "stopped.json");
  EXPECT_FALSE(stopped["quiz"]["running"].get<bool>());
  EXPECT_EQ(stopped["quiz"]["trials"], keys.size());

  std::ifstream csv(dir / "quiz.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "trial,noise_dots,shown,answered,correct,reversal");
  // Levitt's rule as the quiz states it (core/teaching/staircase.h): two right in a row add
  // noise, a wrong answer takes it away, 20 dots a step until the second reversal, then 10.
  int rows = 0, expectedDots = 40, rightInARow = 0, lastStep = 0, reversals = 0;
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::string trial, dots, shown, answered, correct, reversal;
    std::getline(fields, trial, ',');
    std::getline(fields, dots, ',');
    std::getline(fields, shown, ',');
    std::getline(fields, answered, ',');
    std::getline(fields, correct, ',');
    std::getline(fields, reversal, ',');
    ASSERT_LT(rows, static_cast<int>(keys.size()));
    EXPECT_EQ(answered, keys[static_cast<std::size_t>(rows)]) << "trial " << trial;
    const bool right = shown == answered;
    EXPECT_EQ(correct, right ? "1" : "0") << line;
    EXPECT_EQ(std::stoi(dots), expectedDots) << "trial " << trial;
    int step = 0;
    if (!right) step = -1, rightInARow = 0;
    else if (++rightInARow == 2) step = +1, rightInARow = 0;
    const bool turned = step != 0 && lastStep != 0 && step != lastStep;
    EXPECT_EQ(reversal, turned ? "1" : "0") << line;
    if (step != 0) {
      reversals += turned ? 1 : 0;
      lastStep = step;
      expectedDots = std::clamp(expectedDots + step * (reversals < 2 ? 20 : 10), 0, 1000);
    }
    ++rows;
  }
  EXPECT_EQ(rows, static_cast<int>(keys.size()));
}

TEST_F(GuiClassroom, AudienceWindowShowsOnlyTheStageAtItsOwnSizeAndTheme) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([{"set_mode": "explore"}, {"play": false}, {"set_phase": 0.3},
    {"audience": {"size": [800, 450], "theme": "projector"}}, {"mask_dots": 40},
    {"audience_screenshot": ")" + d + R"(/both.png"}, {"export_state": ")" + d + R"(/open.json"},
    {"audience": {"views": "input", "theme": "dark"}},
    {"audience_screenshot": ")" + d + R"(/input.png"},
    {"screenshot": ")" + d + R"(/main.png"},
    {"key": "a"}, {"wait_frames": 2}, {"export_state": ")" + d + R"(/closed.json"},
    {"expect_failure": {"audience_screenshot": ")" + d + R"(/none.png"}},
    {"expect_failure": {"audience": {"theme": "light"}}}])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json open = readJson(dir / "open.json");
  EXPECT_TRUE(open["audience"]["shown"].get<bool>());
  EXPECT_FALSE(readJson(dir / "closed.json")["audience"]["shown"].get<bool>());
  const cv::Mat both = load("both.png"), input = load("input.png"), main = load("main.png");
  ASSERT_FALSE(both.empty() || input.empty());
  EXPECT_EQ(both.cols, 800);
  EXPECT_EQ(both.rows, 450);
  EXPECT_EQ(main.cols, 1280) << "the main window keeps its size";
  // Projector: black where nothing is drawn; dark: the views' own dark grey.
  const cv::Vec3b corner = both.at<cv::Vec3b>(2, 2);
  EXPECT_EQ(corner, cv::Vec3b(0, 0, 0));
  EXPECT_GT(input.at<cv::Vec3b>(2, 2)[0], 5);
  // The stage's dots (the walker's and the 40 noise dots) in the 2D half; the 3D half draws
  // the walker (the figure and the noise); no panel, caption or button anywhere.
  const cv::Mat left = both(cv::Rect(0, 0, 400, 450)), right = both(cv::Rect(400, 0, 400, 450));
  EXPECT_GE(pointLightBlobs(left, 6).size(), 35u);
  EXPECT_GT(countPixels(right, isAmber), 300);
  EXPECT_GE(pointLightBlobs(input, 6).size(), 35u) << "the input alone fills the window";
}

// The must-show of the web page: the page the viewer exports, opened in headless Chromium at
// 800 × 600, draws its first frame's dots where the viewer's 2D view draws them (the view's
// dots carried to the page's canvas by the viewer's framing: 2350 mm of height, v = 975 mm at
// the middle), each within 1 px.
TEST_F(GuiClassroom, WebPageDrawsTheWalkerWhereTheViewerDoes) {
  EW_REQUIRE_BROWSER();
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([{"set_mode": "explore"}, {"play": false}, {"set_angle": 45},
    {"set_phase": 0.3}, {"overlay": ["point_lights", true]}, {"presentation": true}, {"wait_frames": 2},
    {"export_html": ")" + d + R"(/walker.html"},
    {"export_png": {"path": ")" + d + R"(/view.png", "view": "input"}},
    {"export_state": ")" + d + R"(/state.json"}])");
  const RunResult r = runViewer(dir, "--size 1600x1000 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const cv::Mat view = load("view.png");
  ASSERT_FALSE(view.empty());
  const Screenshot page = screenshot(dir / "walker.html", 0.0, dir);
  ASSERT_FALSE(page.image.empty()) << page.log;
  HtmlWalkerSettings dark;
  const std::vector<Blob> browser = findDots(page.image, htmlColours(dark));

  // The view's dots (below its caption, which is white text) on the page's canvas.
  const nlohmann::json state = readJson(dir / "state.json");
  const auto& caption = state["layout"]["overlays"]["input.caption"];
  const auto& viewRect = state["layout"]["input"];
  const double captionBottom = caption[1].get<double>() + caption[3].get<double>() - viewRect[1].get<double>();
  std::vector<cv::Point2d> viewer;
  const double toCanvas = static_cast<double>(kBrowserHeight) / view.rows;
  for (const cv::Point2d& p : pointLightBlobs(view, 20))
    if (p.y > captionBottom + 4.0)
      viewer.push_back({0.5 * kBrowserWidth + (p.x - 0.5 * view.cols) * toCanvas,
                        0.5 * kBrowserHeight + (p.y - 0.5 * view.rows) * toCanvas});
  std::printf("view %dx%d: %zu dots; page: %zu dots\n", view.cols, view.rows, viewer.size(), browser.size());
  ASSERT_EQ(viewer.size(), browser.size());
  ASSERT_GE(browser.size(), 10u);
  double worst = 0.0;
  for (const Blob& b : browser) {
    double nearest = 1e9;
    for (const cv::Point2d& v : viewer) nearest = std::min(nearest, cv::norm(v - b.centre));
    worst = std::max(worst, nearest);
    EXPECT_LE(nearest, 1.0) << "page dot at (" << b.centre.x << ", " << b.centre.y << ")";
  }
  std::printf("largest distance between the page's and the viewer's dots: %.2f px at 800x600\n", worst);
}

}  // namespace
}  // namespace ew::test::gui
