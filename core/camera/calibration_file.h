#pragma once
// Camera calibration files of the Pose2Sim family (Pose2Sim's Calib_*.toml, Sports2D's
// Calib_demo.toml; docs/CAMERA.md): one TOML table per camera with `size` [w, h] px,
// `matrix` (the 3 × 3 intrinsics, focal lengths and principal point in px), `distortions`
// [k1, k2, p1, p2], `rotation` (Rodrigues vector) and `translation` (m), plus `[metadata]`.
// What the eigenwalker's camera uses of it: the focal length (a known focal length makes
// the fit a pinhole with one unknown less) and the image size. The skeleton engine also
// uses the principal point and the extrinsics (its reconstruction back in the world frame).

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

struct CalibratedCamera {
  std::string name;                         // its `name` (else the table's)
  std::string table;                        // the table's [name]
  double widthPx = 0.0, heightPx = 0.0;     // `size`
  double fxPx = 0.0, fyPx = 0.0;            // matrix[0][0], matrix[1][1]
  double cxPx = 0.0, cyPx = 0.0;            // matrix[0][2], matrix[1][2]
  std::array<double, 4> distortions{};      // k1, k2, p1, p2 (zero when absent)
  // World to camera (OpenCV's convention): x_cam = R(rotation) x_world + translation.
  bool hasExtrinsics = false;               // both `rotation` and `translation` given
  std::array<double, 3> rotation{};         // Rodrigues vector (axis × angle, rad)
  std::array<double, 3> translationMm{};    // `translation` (m in the file) in mm
  double focalPx() const { return 0.5 * (fxPx + fyPx); }
};

// Every camera table of a calibration file's text (tables other than [metadata] that have a
// `matrix`; a UTF-8 byte-order mark before the first line is skipped). Throws Error(Malformed)
// naming `file` and the line for text that is not the TOML these files use (tables,
// `key = value` with numbers, terminated "strings", booleans and nested arrays of numbers), a
// matrix that is not 3 × 3, focal lengths that are not a camera's (focal_length.h), a `size`
// that is not an image's, and Error(BadData) when no table is a camera.
std::vector<CalibratedCamera> parseCalibrationToml(std::string_view text, const std::string& file);

// The camera `name` (its `name` or its table) of the file (its only camera when `name` is empty). Throws Error(Io)
// for an unreadable file, and Error(BadArgument) listing the file's cameras when the name
// is not among them or several cameras leave the choice open.
CalibratedCamera readCalibratedCamera(const std::filesystem::path& file, const std::optional<std::string>& name);

}  // namespace ew
