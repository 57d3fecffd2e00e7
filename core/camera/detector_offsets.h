#pragma once
// A pose estimator's hips are not motion capture's hip-joint centres (Needham et al. 2021,
// Sci Rep 11:20673, measured systematic differences of 30–50 mm at the hips and knees): the
// images were annotated by people clicking "the hip", not by a regression from pelvis
// markers. The fit through the unknown camera therefore compares the image with the model's
// walker moved by the layout's detector offsets (KeypointLayout::detectorOffsetMm), and the
// walker it reports has them taken off again: joint centres, as the model's walkers are.

#include <array>

#include "core/camera/camera_reconstruction.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/model.h"
#include "core/keypoints/keypoint_layout.h"

namespace ew {

struct KeypointTrial;

// The model whose mean walker stands where the detector would put its points (the offsets
// added to the mean posture p0; the eigenwalkers are unchanged, so coefficients carry over).
EigenwalkerModel modelAsDetected(const EigenwalkerModel& model, const JointOffsetsMm& offsets);

// A walker (225, METHOD §3) fitted to detector points, moved back to joint centres.
void removeOffsets(Eigen::VectorXd& w, const JointOffsetsMm& offsets);
// A walker's frames (T × 45) as the detector would place its points.
void addOffsets(Eigen::MatrixXd& framesMm, const JointOffsetsMm& offsets);

// Where a sternum made as the shoulders' midpoint sits on the model's walkers: the mean
// walker's shoulders' midpoint less its sternum, over its mean posture (mm; on the default model
// 40.6 mm behind and 66.5 mm below: its sternum is the neck base between C7 and the jugular
// notch, its shoulders the glenohumeral centres, docs/JOINTS.md). Without it the fit bent the
// trunk to bring its sternum down to the image's.
Eigen::Vector3d sternumAsShouldersMidpointOffsetMm(const EigenwalkerModel& model);

// reconstructUnknownCamera on the trial's joints, with the trial's detector offsets
// (KeypointTrial::detectorOffsetMm) accounted for: CameraFit::w is the walker of joint centres.
// The trial's image, when known and the options give none, is the fit's image (the principal
// point's prior: CameraFitOptions::imageSizePx).
CameraFit reconstructDetectedWalker(const EigenwalkerModel& model, const KeypointTrial& trial,
                                    CameraFitOptions options);

// The detector's lateral hip offset learned against the model (docs/KEYPOINTS.md, "Detector
// hips"): half of how much wider a detector's hips stand than the model's walkers' hip-joint
// centres would for the same shank: (W − r̄ S) / 2, W and S the detector's hip width and
// shank length (knee to ankle, both sides), r̄ the mean over the model's walkers of their hip
// width over their shank length (each averaged over a gait cycle). Mm; Error(BadArgument)
// for lengths that are not positive and finite or a model without walkers.
double lateralHipOffsetMm(const EigenwalkerModel& model, double detectorHipWidthMm, double detectorShankMm);

}  // namespace ew
