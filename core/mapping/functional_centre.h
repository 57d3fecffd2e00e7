#pragma once
// Functional joint centre between two marker clusters (SCoRE: Ehrig et al. 2006, "A survey
// of formal methods for determining the centre of rotation of ball joints", J Biomech 39):
// the point fixed in both segments' frames over the trial, found by linear least squares.
// Used for sets whose knees and ankles carry technical clusters rather than anatomical
// markers (Qualisys hybrid, segment clusters). A hinge (the knee; in walking the ankle
// nearly so) leaves the point free along its axis: the minimum-norm solution would put it
// near the clusters, i.e. outside the leg. With an `anchor` (the joint above: hip for the
// knee, knee for the ankle) the point slides along the axis to the one nearest the anchor,
// the mechanical-axis assumption (hip, knee and ankle centres in one line across the leg).

#include <Eigen/Core>
#include <vector>

namespace ew {

using MarkerTrack = Eigen::MatrixX3d;  // frames x 3, mm, NaN = missing

// Frames in which both clusters are complete must number at least this many for a fit.
inline constexpr int kFunctionalMinFrames = 20;

// Per-frame joint centre (mean of its position carried by each cluster; the one cluster's
// when the other is incomplete; NaN when neither is complete). All NaN when the clusters
// (at least 3 markers each) are complete together in fewer than kFunctionalMinFrames frames.
MarkerTrack functionalJointCentre(const std::vector<MarkerTrack>& proximal,
                                  const std::vector<MarkerTrack>& distal,
                                  const MarkerTrack* anchor = nullptr);

// Both hip centres from a pelvis cluster and the two thigh clusters, when no pelvic
// landmarks give a regression hip (segment-cluster sets). A gait trial moves the hip mostly
// in flexion, so each fit is poorly placed along the left-right axis: on the 18 Schreiber
// trials the two fits were 132-328 mm apart against Harrington's 154-193 mm. The pair keeps
// the fits' midpoint and left-right direction and is set `widthMm` apart (docs/JOINTS.md).
struct HipPair {
  MarkerTrack left, right;
};
HipPair symmetricFunctionalHips(const std::vector<MarkerTrack>& pelvis,
                                const std::vector<MarkerTrack>& leftThigh,
                                const std::vector<MarkerTrack>& rightThigh, double widthMm);

}  // namespace ew
