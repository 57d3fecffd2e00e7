#pragma once
// TRC marker files as OpenSim reads them (the Motion Analysis layout, as OpenSim's
// TRCFileAdapter and Pose2Sim write it):
//   PathFileType  4  (X/Y/Z)  <file name>
//   DataRate  CameraRate  NumFrames  NumMarkers  Units  OrigDataRate  OrigDataStartFrame  OrigNumFrames
//   <the eight values>
//   Frame#  Time  head  <tab> <tab>  sternum …      (one name per marker, two empty cells after it)
//   <tab> <tab>  X1  Y1  Z1  X2  Y2  Z2 …
//   <empty line>
//   1  0.000000  x y z …                          (tab-separated; an empty cell is a missing value)
// The 15 joints are the markers, named as in METHOD §1 and in its order (which our TRC reader
// recognises as canonical joints). Axes are OpenSim's: X forward, Y up, Z right — the
// canonical frame's (x right, y forward, z up) turned by a proper rotation (X, Y, Z) = (y, z, x).

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace ew {

// frames: T × 45 in the canonical frame, mm. units: "mm" or "m" (what the Units header says
// and the numbers are in). Written atomically. Throws Error(BadArgument) for a bad shape,
// rate or unit, Error(Io) when the file cannot be written.
void writeTrc(const std::filesystem::path& file, const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
              double rateHz, const std::string& units = "mm");

// The canonical frame's point in OpenSim's axes (X forward, Y up, Z right), and back.
Eigen::Vector3d canonicalToOpenSim(const Eigen::Vector3d& p);
Eigen::Vector3d openSimToCanonical(const Eigen::Vector3d& p);

// A 3D walker written by the file's extension (any case): .trc (writeTrc, mm), .c3d
// (writeWalkerWithFeetC3d, core/io/c3d_writer.h: the 15 joints, the feet's points when feetMm
// has them, the gait events of its own kinematics, the comment lines as MANUFACTURER:NOTES) or
// anything else as the project's joint CSV (core/io/joint_csv.h, with its comment lines; a TRC
// has no place for them). feetMm (JointTrial::feetMm) goes to the C3D only.
// feetInSagittalPlanes: JointTrial::feetInSagittalPlanes, kept in the C3D's point descriptions.
// writesC3d: whether writeJointTrajectories writes `file` as a C3D (the one with the feet).
void writeJointTrajectories(const std::filesystem::path& file, const Eigen::MatrixXd& framesMm,
                            double rateHz, const std::vector<std::string>& commentLines = {},
                            const Eigen::MatrixXd& feetMm = Eigen::MatrixXd(), bool feetInSagittalPlanes = false);
bool writesC3d(const std::filesystem::path& file);

}  // namespace ew
