#pragma once
// Runs the real viewer (EW_GUI_PATH) under xvfb-run with a script and reads back what it
// wrote; helpers to measure screenshots with OpenCV. Shared by tests/gui/test_gui_*.cpp.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <functional>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "tests/common/test_support.h"

namespace ew::test::gui {

struct RunResult {
  int exitCode = -1;
  std::string out, err;
};

inline std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string quote(const std::string& s) { return "'" + s + "'"; }

// Settings off: every run starts from the defaults and leaves no file behind (hermetic).
inline constexpr const char* kNoSettings = "EIGENWALKER_NO_SETTINGS=1";

// Runs `eigenwalker ARGS` in a fresh X server. `dir` receives out.txt / err.txt. `extraEnv`
// ("NAME=value …") replaces the default kNoSettings.
inline RunResult runViewer(const std::filesystem::path& dir, const std::string& args,
                           const std::string& extraEnv = kNoSettings) {
  // Leak checking is off for the viewer process: Mesa's driver is dlclose'd at exit, so
  // LeakSanitizer reports its allocations with no stack to attribute or suppress them by
  // (slow unwinding does not help and makes every run minutes long). AddressSanitizer's
  // memory-error checks and UBSan stay on; the suppressions cover the GL stack for whoever
  // turns leak checking back on (ASAN_OPTIONS=detect_leaks=1).
  const std::string env = std::string("ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 LSAN_OPTIONS=suppressions=") +
                          EW_GUI_LSAN_SUPPRESSIONS + ":print_suppressions=0 " + extraEnv + " ";
  const auto out = dir / "out.txt", err = dir / "err.txt", rc = dir / "rc.txt", runner = dir / "run.sh";
  // The viewer's exit status goes to rc.txt, not through xvfb-run's: xvfb-run replaces the
  // status with its own when its clean-up fails (exit 5, "problem while cleaning up
  // temporary directory", seen on a loaded CI machine), which would hide the viewer's.
  std::ofstream(runner) << "env " << env << quote(EW_GUI_PATH) << " " << args << " > " << quote(out.string())
                        << " 2> " << quote(err.string()) << "\necho $? > " << quote(rc.string()) << "\n";
  const std::string cmd = "xvfb-run -a -s '-screen 0 1920x1080x24' sh " + quote(runner.string()) + " 2> " +
                          quote((dir / "xvfb.txt").string());
  RunResult r;
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::filesystem::remove(rc);
    const int xvfbStatus = std::system(cmd.c_str());
    r.out = readAll(out);
    r.err = readAll(err);
    const std::string code = readAll(rc);
    // No rc.txt: the X server did not start (xvfb-run -a can race with another test for a
    // display number): try again.
    if (!code.empty()) {
      r.exitCode = std::stoi(code);
      break;
    }
    r.err += readAll(dir / "xvfb.txt") + "(xvfb-run status " + std::to_string(xvfbStatus) + ")\n";
  }
  return r;
}

// A fresh folder per test for its scripts, screenshots and the viewer's output; kept when
// the test fails, to look at what the viewer drew.
class GuiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = makeTempDir(::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name());
  }
  void TearDown() override {
    // EIGENWALKER_KEEP_GUI_OUTPUT=1 keeps it after a pass too, to look at the screenshots.
    const char* keep = std::getenv("EIGENWALKER_KEEP_GUI_OUTPUT");
    if (!HasFailure() && !(keep && *keep == '1')) std::filesystem::remove_all(dir);
    else std::cout << "viewer output kept in " << dir.string() << "\n";
  }
  // An image the viewer wrote into `dir` (empty, with a failure, when missing).
  cv::Mat load(const std::string& name) const {
    cv::Mat image = cv::imread((dir / name).string(), cv::IMREAD_COLOR);
    EXPECT_FALSE(image.empty()) << name << " missing";
    return image;
  }
  std::filesystem::path dir;
};

inline std::filesystem::path writeScript(const std::filesystem::path& dir, const std::string& json) {
  const auto file = dir / "script.json";
  std::ofstream(file) << json;
  return file;
}

// After the `opening` actions, the viewer's state into `dir` whole (whole.json), magnified by
// `zoomAction` ("video_zoom", "clip_zoom") `zoom` times about `centre` (zoomed.json) and whole
// again (again.json), at 1280x720.
inline RunResult runWholeZoomedWhole(const std::filesystem::path& dir, nlohmann::json opening,
                                     const std::string& zoomAction, double zoom, const nlohmann::json& centre) {
  const auto state = [&](const char* name) { return nlohmann::json{{"export_state", (dir / name).string()}}; };
  const auto zoomTo = [&](double z) { return nlohmann::json{{zoomAction, {{"zoom", z}, {"centre", centre}}}}; };
  const nlohmann::json wait = {{"wait_frames", 2}};
  for (const auto& a : {wait, state("whole.json"), zoomTo(zoom), wait, state("zoomed.json"), zoomTo(1.0), wait,
                        state("again.json")})
    opening.push_back(a);
  const auto file = writeScript(dir, opening.dump(2));
  return runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
}

// A region of the image as fractions of its size.
struct Region {
  double x0, y0, x1, y1;
};

// The 2D input view and the 3D view of the default layout (docs/VIEWER.md), inset so
// that small layout changes do not move them out.
inline constexpr Region kInputView{0.23, 0.22, 0.47, 0.64};
inline constexpr Region kReconView{0.54, 0.22, 0.78, 0.64};

// The inside of a view ("input" or "reconstruction") as the viewer laid it out, from the
// state's `layout` (export_state) of a window width × height: inset from its sides, below its
// caption and above its legend, as kInputView and kReconView are in the full layout. For
// windows whose layout is not the full one (the drawer at 1024×768).
inline Region viewRegion(const nlohmann::json& state, const char* view, double width, double height) {
  const auto& r = state.at("layout").at(view);
  const double x = r[0].get<double>(), y = r[1].get<double>(), w = r[2].get<double>(), h = r[3].get<double>();
  return {(x + 0.12 * w) / width, (y + 0.17 * h) / height, (x + 0.88 * w) / width, (y + 0.85 * h) / height};
}

inline cv::Mat crop(const cv::Mat& image, Region r) {
  const int x0 = static_cast<int>(r.x0 * image.cols), x1 = static_cast<int>(r.x1 * image.cols);
  const int y0 = static_cast<int>(r.y0 * image.rows), y1 = static_cast<int>(r.y1 * image.rows);
  return image(cv::Rect(x0, y0, x1 - x0, y1 - y0));
}

// Pixels (BGR image) for which `pred(r, g, b)` holds.
inline int countPixels(const cv::Mat& bgr, const std::function<bool(int, int, int)>& pred) {
  int n = 0;
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x)
      if (pred(row[x][2], row[x][1], row[x][0])) ++n;
  }
  return n;
}

// The 2D input's point-lights saturate to white (UI text never does).
inline bool isPointLight(int r, int g, int b) { return r >= 250 && g >= 250 && b >= 250; }
// The reconstruction's amber bones, lit and under the translucent blue ghost (which turns
// them to a duller brown, 160, 128, 96): red above green above blue, green 40-92 % of red
// (the estimated camera's red and the greys are outside). Its joints take the error map's
// colours (cyan to purple), none of them warm.
inline bool isAmber(int r, int g, int b) {
  return r > 110 && g > b && r - b > 50 && 10 * g > 4 * r && 100 * g < 92 * r;
}
// The ground-truth ghost: blue dominant.
inline bool isGhostBlue(int r, int g, int b) { return b > 60 && b - r > 35 && b > g + 15; }
// Error lines: magenta.
inline bool isMagenta(int r, int g, int b) { return r > 170 && b > 90 && g < 110 && r - g > 100; }

inline double meanAbsDiff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  const cv::Scalar m = cv::mean(d);
  return (m[0] + m[1] + m[2]) / 3.0;
}

}  // namespace ew::test::gui
