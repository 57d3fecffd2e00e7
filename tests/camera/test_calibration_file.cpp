// Calibration files (core/camera/calibration_file.h): the real Pose2Sim and Sports2D files,
// hand-written ones, and malformed text (typed errors naming the file and the line).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/camera/calibration_file.h"
#include "core/common/errors.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

constexpr const char* kOneCamera = R"([demo]
name = "demo"   # a comment
size = [ 1768, 994]
matrix = [ [ 2520.5, 0.0, 884.0], [ 0.0, 2519.5, 497.0], [ 0.0, 0.0, 1.0]]
distortions = [ 0.1, 0.0, 0.0, 0.0]
rotation = [ 1.2, 1.2, -1.2]
translation = [ -3.5, 1.7, 10.0]
fisheye = false

[metadata]
adjusted = false
error = 0.0
)";

TEST(CalibrationFile, ReadsACamera) {
  const auto cameras = parseCalibrationToml(kOneCamera, "demo.toml");
  ASSERT_EQ(cameras.size(), 1u);
  const CalibratedCamera& c = cameras.front();
  EXPECT_EQ(c.name, "demo");
  EXPECT_EQ(c.widthPx, 1768);
  EXPECT_EQ(c.heightPx, 994);
  EXPECT_EQ(c.fxPx, 2520.5);
  EXPECT_EQ(c.fyPx, 2519.5);
  EXPECT_EQ(c.focalPx(), 2520.0);
  EXPECT_EQ(c.cxPx, 884.0);
  EXPECT_EQ(c.cyPx, 497.0);
  EXPECT_EQ(c.distortions[0], 0.1);
}

// The error names the file and the line, and says what is wrong.
void expectMalformed(const std::string& text, const std::string& position, const std::string& words) {
  try {
    parseCalibrationToml(text, "calib.toml");
    FAIL() << "accepted:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed) << e.what();
    EXPECT_EQ(e.file(), "calib.toml");
    EXPECT_EQ(e.position(), position) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(CalibrationFile, MalformedTextIsAnErrorNamingTheLine) {
  expectMalformed("[c]\nmatrix = [[1, 0, 2], [0, 1, 3]]\n", "line 2", "3 rows of 3");
  expectMalformed("[c]\nmatrix = [[1, 0, 2], [0, 1, 3], [0, 0, 1]\n", "line 2", "unbalanced");
  expectMalformed("[c]\nmatrix = [[1, 0, x], [0, 1, 3], [0, 0, 1]]\n", "line 2", "not a number");
  expectMalformed("[c]\nmatrix = [[-5, 0, 2], [0, 1, 3], [0, 0, 1]]\n", "line 2", "focal length -5 px");
  expectMalformed("[c]\nmatrix = [[1e999, 0, 2], [0, 1, 3], [0, 0, 1]]\n", "line 2", "not");
  expectMalformed("[c]\nmatrix = \"text\"\n", "line 2", "expected numbers");
  expectMalformed("matrix = [[1, 0, 2], [0, 1, 3], [0, 0, 1]]\n", "line 1", "before any [table]");
  expectMalformed("[c\nmatrix = 1\n", "line 1", "[name]");
  expectMalformed("[c]\nmatrix [[1]]\n", "line 2", "key = value");
  expectMalformed("[c]\nmatrix = [[[[[1]]]]]\n", "line 2", "nested");
  expectMalformed("[c]\nsize = [0, 10]\nmatrix = [[1000, 0, 2], [0, 1000, 3], [0, 0, 1]]\n", "line 2", "width, height");
  expectMalformed("[c]\nsize = [1e300, 10]\nmatrix = [[1000, 0, 2], [0, 1000, 3], [0, 0, 1]]\n", "line 2",
                  "width, height");
  EXPECT_THROW(parseCalibrationToml("[metadata]\nerror = 0\n", "calib.toml"), Error);
  EXPECT_THROW(parseCalibrationToml("", "calib.toml"), Error);
}

// Issue 53: a focal length of 5e-324 px dropped every keypoint as outside the picture (and
// crashed the gait cycles), one of 1e308 px was reported as "focal inf px". Each of fx and fy
// must be a camera's (core/camera/focal_length.h), the bounds themselves accepted.
TEST(CalibrationFile, AFocalLengthMustBeACamerasEach) {
  const auto withFocals = [](const std::string& fx, const std::string& fy) {
    return "[cam]\nsize = [1920, 1080]\nmatrix = [[" + fx + ", 0, 960], [0, " + fy + ", 540], [0, 0, 1]]\n";
  };
  expectMalformed(withFocals("5e-324", "5e-324"), "line 3", "focal length 4.94066e-324 px");
  expectMalformed(withFocals("1e308", "1e308"), "line 3", "focal length 1e+308 px: a camera's is finite and 50-100000 px");
  expectMalformed(withFocals("1400", "49.9"), "line 3", "focal length 49.9 px");
  expectMalformed(withFocals("100001", "1400"), "line 3", "[cam] matrix: focal length 100001 px");
  EXPECT_EQ(parseCalibrationToml(withFocals("50", "100000"), "calib.toml").front().focalPx(), 50025.0);
}

// Issue 53: a file saved by a Windows editor starts with a UTF-8 byte-order mark; it was
// refused as "line 1: expected key = value" while the same file with CRLF line ends was read.
TEST(CalibrationFile, AByteOrderMarkBeforeTheFirstTableIsSkipped) {
  std::string crlf;
  for (const char c : std::string(kOneCamera)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  for (const std::string& text : {"\xEF\xBB\xBF" + std::string(kOneCamera), "\xEF\xBB\xBF" + crlf}) {
    const auto cameras = parseCalibrationToml(text, "bom.toml");
    ASSERT_EQ(cameras.size(), 1u);
    EXPECT_EQ(cameras.front().table, "demo");
    EXPECT_EQ(cameras.front().name, "demo");
    EXPECT_EQ(cameras.front().focalPx(), 2520.0);
  }
}

// Issue 53: `name = "abc` was read as camera "ab" (the last character taken for the quote).
TEST(CalibrationFile, AStringMustBeClosedAndANameQuoted) {
  const std::string matrix = "matrix = [[1000, 0, 2], [0, 1000, 3], [0, 0, 1]]\n";
  expectMalformed("[c]\nname = \"abc\n" + matrix, "line 2", "name: the string has no closing '\"'");
  expectMalformed("[c]\nname = \"\n" + matrix, "line 2", "no closing");
  expectMalformed("[c]\n" + matrix + "model = \"pinhole  # a comment\n", "line 3", "model: the string has no closing");
  expectMalformed("[c]\nname = abc\n" + matrix, "line 2", "[c] name: expected a \"quoted\" name");
  EXPECT_EQ(parseCalibrationToml("[c]\nname = \"a # b\" # c\n" + matrix, "calib.toml").front().name, "a # b");
}

TEST(CalibrationFile, SeveralCamerasNeedAName) {
  const auto dir = test::makeTempDir("calib");
  const auto file = dir / "Calib_two.toml";
  std::ofstream(file) << "[cam_01]\nname = \"left\"\nmatrix = [[1000, 0, 500], [0, 1000, 400], [0, 0, 1]]\n"
                         "[cam_02]\nmatrix = [[1500, 0, 500], [0, 1500, 400], [0, 0, 1]]\n";
  EXPECT_EQ(readCalibratedCamera(file, std::string("left")).focalPx(), 1000.0);
  EXPECT_EQ(readCalibratedCamera(file, std::string("cam_01")).focalPx(), 1000.0);  // the table's name
  EXPECT_EQ(readCalibratedCamera(file, std::string("cam_02")).focalPx(), 1500.0);
  for (const std::optional<std::string>& name : {std::optional<std::string>(), std::optional<std::string>("right")}) {
    try {
      readCalibratedCamera(file, name);
      FAIL();
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadArgument);
      EXPECT_NE(std::string(e.what()).find("left, cam_02"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(readCalibratedCamera(dir / "absent.toml", std::nullopt), Error);
}

// The shared data's calibrations: Pose2Sim's four Qualisys cameras (1088 × 1920, focal
// ~1675-1682 px) and the Sports2D demo's one (1768 × 994, 2520.09 px).
TEST(CalibrationFile, ReadsThePose2SimAndSports2DFiles) {
  EW_REQUIRE_SHARED_DATA();
  const auto data = test::sharedDataDir();
  const auto qualisys = data / "pose2sim-balancing" / "Calib_qualisys.toml";
  const CalibratedCamera cam3 = readCalibratedCamera(qualisys, std::string("cam_03"));
  EXPECT_EQ(cam3.widthPx, 1088);
  EXPECT_EQ(cam3.heightPx, 1920);
  EXPECT_NEAR(cam3.focalPx(), 1681.55, 0.01);
  EXPECT_NEAR(cam3.cxPx, 513.21, 0.01);
  EXPECT_THROW(readCalibratedCamera(qualisys, std::nullopt), Error);  // four cameras: which?
  const CalibratedCamera demo = readCalibratedCamera(data / "video" / "sports2d-demo" / "Calib_demo.toml", std::nullopt);
  EXPECT_EQ(demo.name, "demo");
  EXPECT_NEAR(demo.focalPx(), 2520.09, 0.01);
  EXPECT_EQ(demo.widthPx, 1768);
}

}  // namespace
}  // namespace ew
