#pragma once
// The data a trial passes through on its way to the model:
//   file --(reader)--> RawTrial --(mapping)--> JointTrial --(normalise)--> WalkingTrial
// RawTrial keeps the file's own points (markers or skeleton joints) in the file's axes,
// already converted to millimetres. JointTrial has the 15 joints of METHOD §1.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/skeleton.h"

namespace ew {

enum class Side { Left, Right };

enum class GaitEventType { FootStrike, FootOff, Other };

struct GaitEvent {
  Side side = Side::Left;
  GaitEventType type = GaitEventType::Other;
  double timeS = 0.0;  // seconds from the trial's first frame (frame index 0 = 0 s)
  std::string label;   // as written in the file ("Foot Strike", "Foot Strike1", …)
};

// A vertical axis stated by the file format itself (BVH/ASF: +Y; C3D: from
// POINT:X_SCREEN/Y_SCREEN when present). axis 0,1,2 = file x,y,z; sign +1 or -1.
struct SignedAxis {
  int axis = 2;
  int sign = 1;
  bool operator==(const SignedAxis&) const = default;
};

enum class PointKind {
  Markers,         // skin markers (C3D, TRC): mapped by a marker set
  SkeletonJoints,  // joint centres of a kinematic skeleton (BVH, ASF/AMC)
  CanonicalJoints, // already our 15 joints (our CSV format)
};

struct RawTrial {
  std::string file;    // path as given by the caller
  std::string format;  // "C3D", "BVH", "ASF/AMC", "TRC", "CSV"
  PointKind kind = PointKind::Markers;
  double rateHz = 0.0;
  long firstFrame = 1;          // the file's number for row 0 (C3D first_frame, TRC Frame#)
  std::string units;            // the unit the file states (or assumed), e.g. "mm", "m"
  std::vector<std::string> labels;  // one per point, trimmed
  // One per point where the file describes its points (a C3D's POINT:DESCRIPTIONS), else empty.
  std::vector<std::string> descriptions;
  Eigen::MatrixXd positionsMm;      // frames x 3*labels, file axes, millimetres, NaN = missing
  std::optional<SignedAxis> upAxis; // vertical axis if the format or file states it
  std::vector<GaitEvent> events;
  // The subject's stature as the file records it (a C3D's SUBJECT group), mm.
  std::optional<double> subjectStatureMm;
  std::vector<std::string> warnings;

  int frameCount() const { return static_cast<int>(positionsMm.rows()); }
  int pointCount() const { return static_cast<int>(labels.size()); }
};

// The feet's points beside the 15 joints, where the input has them (Plug-in Gait's HEE and TOE,
// the ISB calcaneus and second metatarsal head, OpenCap's calcn and toe markers): a heel and a
// toe per foot. The 15 joints stay the engines' currency; these serve the gait events, the
// ankle angle and the foot progression (core/gait/foot_points.h).
enum class FootPoint : int { RHeel = 0, RToe = 1, LHeel = 2, LToe = 3 };
inline constexpr int kFootPointCount = 4;
inline constexpr int kFootDims3 = 3 * kFootPointCount;  // 12 columns per 3D frame
// Also the marker-set tables' keys and the CSV column stems (r_heel_x, …).
inline constexpr std::array<std::string_view, kFootPointCount> kFootPointNames = {
    "r_heel", "r_toe", "l_heel", "l_toe"};
constexpr int index(FootPoint p) { return static_cast<int>(p); }
inline FootPoint heelOf(Side side) { return side == Side::Left ? FootPoint::LHeel : FootPoint::RHeel; }
inline FootPoint toeOf(Side side) { return side == Side::Left ? FootPoint::LToe : FootPoint::RToe; }
// How our C3D describes feet lifted from one view onto the ankles' sagittal planes
// (core/camera/lifted_feet.h): their heel strikes, toe offs and ankle angle hold, their turn out
// of the plane is not in them, so no foot progression is read from them.
inline constexpr std::string_view kSagittalFootDescription =
    "lifted from one view onto the ankle's sagittal plane: no foot progression";

struct JointTrial {
  std::string file;
  std::string format;
  std::string source;             // marker set or skeleton the joints came from, e.g. "ISB (Schreiber-Moissenet)"
  double rateHz = 0.0;
  std::string units;              // units the file stated (data here is always mm)
  std::vector<std::string> sourceLabels;  // the markers / skeleton joints the file had
  Eigen::MatrixXd positionsMm;    // frames x 45, joint-major x,y,z; file axes until normalised
  std::array<bool, kJointCount> estimated{};  // joint estimated, not measured (METHOD §1)
  // Joint not measured at all (its columns are NaN in every frame): to be estimated from a
  // model (core/eigenwalker/joint_completion.h). Set by mappings whose marker set lacks it.
  std::array<bool, kJointCount> missing{};
  std::optional<SignedAxis> upAxis;
  std::vector<GaitEvent> events;
  std::vector<std::string> warnings;
  // The feet's heel and toe points (FootPoint order, x,y,z each), in the same axes, frames and
  // units as positionsMm: frames x 12, or empty (0 x 0) when the input has no foot point. A
  // point the input lacks, or lacks in a frame, is NaN there (a foot may have a toe and no heel).
  Eigen::MatrixXd feetMm;
  // The feet were lifted from one view onto the ankles' sagittal planes (kSagittalFootDescription):
  // no foot progression angle is measured from them.
  bool feetInSagittalPlanes = false;

  int frameCount() const { return static_cast<int>(positionsMm.rows()); }
  bool hasFeet() const { return feetMm.cols() == kFootDims3 && feetMm.rows() == positionsMm.rows(); }
};

// Convenience accessors on joint-major trajectory matrices.
inline Eigen::Vector3d jointAt(const Eigen::MatrixXd& framesX45, int frame, Joint j) {
  return framesX45.block<1, 3>(frame, 3 * index(j)).transpose();
}

}  // namespace ew
