// TRC files of points in a plane: a view of the walker, not its 3D walk (docs/KEYPOINTS.md,
// "2D TRC files"). Sports2D writes its results so, Z 0 throughout; Kinovea and others too.
// Declared in keypoint_trial.h.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/load_trial.h"
#include "core/io/text_table.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// Sports2D (after 0.5) writes pixels under "Units m": read as metres, its points lie hundreds
// of metres to kilometres from the origin. No camera sees a walk 100 m across; beyond, the
// metres were pixels.
constexpr double kPixelsLabelledMetresMm = 1.0e5;

// Counts the points of a data row ("Frame#, Time, X1, Y1, Z1, …") that are placed (X or Y not
// 0) and those of them with Z not 0.
void countRow(std::string_view line, int& placed, int& outOfPlane) {
  const auto fields = splitTabs(line);
  for (std::size_t x = 2; x + 2 < fields.size(); x += 3) {
    double u = 0.0, v = 0.0, z = 0.0;
    if (!parseFinite(fields[x], u) || !parseFinite(fields[x + 1], v) || !parseFinite(fields[x + 2], z)) continue;
    if (u == 0.0 && v == 0.0) continue;  // a point written as 0, 0, 0: not there
    ++placed;
    if (z != 0.0) ++outOfPlane;
  }
}

// The vertical axis of the plane (1 = Y, 0 = X) and whether it points up: the axis along which
// the head and the ankles lie furthest apart, up when the head has the larger value.
struct PlaneAxes {
  int vertical = 1;
  bool up = true;
};

PlaneAxes planeAxes(const Eigen::MatrixXd& mm, const std::string& file) {
  double along[2] = {0.0, 0.0};
  int frames = 0;
  for (Eigen::Index f = 0; f < mm.rows(); ++f) {
    const Eigen::Vector3d head = jointAt(mm, static_cast<int>(f), Joint::Head);
    const Eigen::Vector3d ankles = 0.5 * (jointAt(mm, static_cast<int>(f), Joint::RAnkle) +
                                          jointAt(mm, static_cast<int>(f), Joint::LAnkle));
    if (!head.allFinite() || !ankles.allFinite()) continue;
    along[0] += head.x() - ankles.x(), along[1] += head.y() - ankles.y();
    ++frames;
  }
  if (frames == 0) throw Error(ErrorKind::BadData, file, "", "no frame shows the head and both ankles");
  PlaneAxes a;
  a.vertical = std::abs(along[1]) >= std::abs(along[0]) ? 1 : 0;
  a.up = along[a.vertical] > 0.0;
  return a;
}

// The joints as image points (u right, v down) in the file's unit, and each one's confidence
// (1 placed, 0 not).
void toImage(const JointTrial& joints, double scale, Eigen::MatrixXd& px, Eigen::MatrixXd& confidence) {
  const PlaneAxes axes = planeAxes(joints.positionsMm, joints.file);
  const int horizontal = 1 - axes.vertical;
  px.resize(joints.positionsMm.rows(), 2 * kJointCount);
  confidence.setZero(joints.positionsMm.rows(), kJointCount);
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d p = joints.positionsMm.block<1, 3>(f, 3 * j).transpose();
      const bool placed = p.allFinite() && (p.x() != 0.0 || p.y() != 0.0);
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      px(f, 2 * j) = placed ? p(horizontal) * scale : kNaN;
      px(f, 2 * j + 1) = placed ? (axes.up ? -1.0 : 1.0) * p(axes.vertical) * scale : kNaN;
      confidence(f, j) = placed ? 1.0 : 0.0;
    }
  }
}

// Every point the file places (X or Y not 0) lies in the plane Z = 0, or the file is refused.
void requirePlanar(const RawTrial& raw) {
  for (Eigen::Index f = 0; f < raw.positionsMm.rows(); ++f) {
    for (int p = 0; p < raw.pointCount(); ++p) {
      const Eigen::Vector3d q = raw.positionsMm.block<1, 3>(f, 3 * p).transpose();
      if (q.allFinite() && (q.x() != 0.0 || q.y() != 0.0) && q.z() != 0.0)
        throw Error(ErrorKind::BadData, raw.file, "frame " + std::to_string(f + 1),
                    raw.labels[static_cast<std::size_t>(p)] +
                        " has Z = " + std::to_string(q.z()) + " mm where the first frames' points are in the plane Z = 0: "
                        "neither a 2D view nor a 3D walk");
    }
  }
}

// Points written as 0, 0, 0 (Sports2D's gaps) made missing before the joints are built from
// them: a joint that is the mean of two points, one of them a gap, is no joint.
RawTrial withoutUnplacedPoints(RawTrial raw) {
  for (Eigen::Index f = 0; f < raw.positionsMm.rows(); ++f) {
    for (int p = 0; p < raw.pointCount(); ++p) {
      auto q = raw.positionsMm.block<1, 3>(f, 3 * p);
      if (q(0) == 0.0 && q(1) == 0.0) q.setConstant(std::numeric_limits<double>::quiet_NaN());
    }
  }
  return raw;
}

}  // namespace

bool isPlanarTrc(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  std::error_code ec;
  if (ext != ".trc" || !fs::is_regular_file(path, ec)) return false;
  const std::string text = readFileStart(path);
  const auto lines = splitLines(text);
  // The rows after the "X1 Y1 Z1" row; the last may be cut by the 64 KiB.
  std::size_t data = 0;
  while (data < lines.size() && data < 20 && lines[data].text.find("X1") == std::string_view::npos) ++data;
  int placed = 0, outOfPlane = 0;
  for (std::size_t i = data + 1; i + 1 < lines.size(); ++i) countRow(lines[i].text, placed, outOfPlane);
  return placed > 0 && outOfPlane == 0;
}

KeypointTrial readPlanarTrc(const fs::path& path, const KeypointOptions& options) {
  LoadOptions load;
  load.mappingFile = options.mappingFile;
  return planarTrcTrial(readRawTrial(path, load), options);
}

KeypointTrial planarTrcTrial(const RawTrial& raw, const KeypointOptions& options) {
  LoadOptions load;
  load.mappingFile = options.mappingFile;
  requirePlanar(raw);
  const JointTrial joints = mapRawTrial(withoutUnplacedPoints(raw), load);
  // The file's unit as millimetres, except pixels written as metres (see above).
  double scale = 1.0;
  const double extent = (joints.positionsMm.array().isFinite()).select(joints.positionsMm.array().abs(), 0.0).maxCoeff();
  std::vector<std::string> notes;
  if (extent > kPixelsLabelledMetresMm) {
    scale = 1e-3;
    notes.push_back("its points are read as pixels: under 'Units " + raw.units +
                    "' they would lie over 100 m from the origin (Sports2D writes pixels so)");
  }
  Eigen::MatrixXd px, confidence;
  toImage(joints, scale, px, confidence);
  KeypointOptions o = options;
  if (!o.fps) o.fps = raw.rateHz;
  KeypointTrial t = trialFromJoints(px, confidence, raw.file, "TRC (2D)", o);
  t.layoutSource = joints.source + ", by the file's point names";
  t.chosenReason = "the file's one person";
  t.rateSource = options.fps ? "given" : "the file";
  for (int j = 0; j < kJointCount; ++j) t.derived[static_cast<std::size_t>(j)] = joints.estimated[static_cast<std::size_t>(j)];
  t.warnings.push_back("a TRC whose points all lie in the plane Z = 0: a 2D view, read as the image of the walker");
  for (const auto& n : notes) t.warnings.push_back(n);
  return t;
}

}  // namespace ew
