// The viewer on the shared data set: opens the manifest, reconstructs a held-out CMU
// subject with an unknown view angle, and shows it.

#include <gtest/gtest.h>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

TEST(GuiRealData, OpensTheManifestAndReconstructsAHeldOutSubject) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = makeTempDir("gui_real");
  const auto manifest = sharedDataDir() / "walkers.csv";
  const auto shot = dir / "real.png";
  const auto script = writeScript(dir, R"([
    {"select_subject": "CMU07"},
    {"unknown_angle": true},
    {"set_angle": 45},
    {"play": false},
    {"set_phase": 0.3},
    {"screenshot": ")" + shot.string() + R"("}
  ])");
  const RunResult r = runViewer(dir, quote(manifest.string()) + " --size 1600x900 --script " +
                                         quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const cv::Mat image = cv::imread(shot.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_GT(countPixels(crop(image, kInputView), isPointLight), 60);
  EXPECT_GT(countPixels(crop(image, kReconView), isAmber), 300);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ew::test::gui
