#pragma once
// Snippets (Howe, Leventon & Freeman 1999, §3): S consecutive frames of the 15 joints in
// 3D, as one column vector x ∈ R^{S·45}, frame-major (x[f·45 + 3·joint + axis], mm).
// Each snippet is expressed in its own frame: the middle frame's pelvis moved to the
// origin horizontally (height kept: the floor stays at z = 0) and the body turned about
// the vertical so the middle frame's heading, z × (r_hip − l_hip), is +y. Every trial is
// first resampled to one rate (the prior's, 30 Hz by default) so a snippet always spans
// the same time (11 frames ≈ 1/3 s).

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ew {

inline constexpr int kSnippetJointValues = 45;  // 15 joints × (x, y, z)

// Frames (T × C, any C) at `fromHz` resampled to `toHz` by linear interpolation over the
// same time span (the last output frame at or before the last input time). A value next
// to a NaN neighbour stays NaN. Rates positive and finite, else Error(BadArgument).
Eigen::MatrixXd resampleFrames(const Eigen::Ref<const Eigen::MatrixXd>& frames, double fromHz,
                               double toHz);

// Where a snippet's own frame sits in the trial's frame: pelvis (x, y) of the middle frame
// and the heading angle h (radians) that turns +y onto the middle frame's forward
// direction: forward = (−sin h, cos h).
struct SnippetPlacement {
  double originX = 0.0, originY = 0.0;
  double headingRad = 0.0;
};

// Placement from the middle frame of frames.block(start, 0, count, 45).
SnippetPlacement snippetPlacement(const Eigen::Ref<const Eigen::MatrixXd>& frames, int start,
                                  int count);

// The snippet vector of frames [start, start + count) in its own frame (placement above).
Eigen::VectorXd localSnippet(const Eigen::Ref<const Eigen::MatrixXd>& frames, int start,
                             int count, const SnippetPlacement& placement);

// Back into the trial's frame: count × 45.
Eigen::MatrixXd placeSnippet(const Eigen::Ref<const Eigen::VectorXd>& snippet, int count,
                             const SnippetPlacement& placement);

// A 3D trial the prior learns from: canonical-frame joints (METHOD §2), mm.
struct SnippetTrainingTrial {
  std::string subject;
  std::string name;           // file or walker id, for messages
  Eigen::MatrixXd framesMm;   // T × 45
  double rateHz = 0.0;
};

// All snippets of `count` frames every `hop` frames of each trial, resampled to `rateHz`,
// in their own frames (columns of the result, D × n). Snippets with a NaN are skipped.
// Trials shorter than a snippet give none.
Eigen::MatrixXd cutTrainingSnippets(const std::vector<SnippetTrainingTrial>& trials, int count,
                                    int hop, double rateHz);

}  // namespace ew
