#pragma once
// Issue 14's synthetic footage as a study (`eigenwalker-cli track-study`, docs/TRACKING_DESIGN.md
// "By view"): held-out shared walkers, each its own two-harmonic walk carried forward for a few
// strides and filmed by writeFootage from chosen azimuths, tracked from its true joints on the
// first frame with N rounds of the model loop; the track against the truth in pixels, and the
// walk fitted to it through the unknown camera by the model built without that subject, beside
// the same fit to the true 2D (MPJPE, translation removed): what `track --reconstruct` and
// `reconstruct --unknown-camera` fit.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/common/skeleton.h"
#include "core/eigenwalker/model.h"
#include "core/experiments/leave_one_out.h"
#include "core/tracking/keyframes.h"
#include "video/joint_tracker.h"

namespace ew {

struct TrackStudyOptions {
  std::vector<std::string> subjects;  // held out one at a time; empty: every subject
  std::vector<double> azimuthsDeg{-90, -60, -30, 0, 30, 60, 90};  // cameraBeside's azimuth
  int rounds = 1;                     // of the model loop (0: the tracker alone)
  double distanceMm = 6000.0;         // camera to the middle of the walk
  double speedMmS = 1200.0;           // the walk carried forward
  double strides = 3.0;
  double fps = 30.0;
  double sigma2Mm2 = 1000.0;          // MAP prior of both fits
  unsigned footageSeed = 7;           // writeFootage's background and limb prints
  bool holdTheTrunk = false;          // TrackerOptions::holdTheTrunk
  std::filesystem::path scratchDir;   // footage written here and removed; empty: the temp dir
};

// A subject held out: its first walker, and the model built without any of its walkers (shared
// by every view it is filmed from).
struct HeldOutSubject {
  ExperimentWalker walker;
  std::shared_ptr<const EigenwalkerModel> model;
};
// Error(BadArgument) naming `subject` when `walkers` has no such subject or only it.
HeldOutSubject holdOut(const std::vector<ExperimentWalker>& walkers, const std::string& subject);

// One held-out walker filmed from one azimuth: its footage on disk while this lives.
class FilmedHeldOutWalker {
 public:
  FilmedHeldOutWalker(const HeldOutSubject& held, double azimuthDeg,
                      const TrackStudyOptions& options);
  // holdOut(walkers, subject) filmed: its errors.
  FilmedHeldOutWalker(const std::vector<ExperimentWalker>& walkers, const std::string& subject,
                      double azimuthDeg, const TrackStudyOptions& options)
      : FilmedHeldOutWalker(holdOut(walkers, subject), azimuthDeg, options) {}
  ~FilmedHeldOutWalker();
  FilmedHeldOutWalker(const FilmedHeldOutWalker&) = delete;
  FilmedHeldOutWalker& operator=(const FilmedHeldOutWalker&) = delete;

  const EigenwalkerModel& model() const { return *model_; }  // built without the subject
  const std::filesystem::path& file() const { return file_; }
  const Eigen::MatrixXd& truthPx() const { return truthPx_; }  // frames × 30
  double strideHz() const { return strideHz_; }
  Keyframes firstFrameMarked() const;

  // METHOD §5's azimuth of the camera that filmed it: 90° − cameraBeside's azimuth, in (−180, 180].
  double alphaDeg() const { return alphaDeg_; }

  // A fit's MPJPE (mm, translation removed) against the walk filmed, and the azimuth it found.
  struct Fit {
    double mpjpeMm = 0.0, alphaDeg = 0.0;
  };
  // The fits: to the true 2D as a keypoint file is fitted, and to a track as `track
  // --reconstruct` fits it (the stride held at the trunk's bob when it is clear). Throw what
  // the fit throws.
  Fit fitToTruth() const;
  Fit fitToTrack(const JointTrack& track) const;
  double mpjpeFromTruthMm() const { return fitToTruth().mpjpeMm; }
  double mpjpeFromTrackMm(const JointTrack& track) const { return fitToTrack(track).mpjpeMm; }

 private:
  TrackStudyOptions options_;
  std::shared_ptr<const EigenwalkerModel> model_;
  Eigen::VectorXd times_;
  Eigen::MatrixXd inPlace_, truthPx_;
  KeypointImageSize imageSize_;  // the footage's frame
  std::filesystem::path dir_, file_;
  double strideHz_ = 0.0, alphaDeg_ = 0.0;

  Fit fitOf(const KeypointTrial& joints, bool tracked) const;
};

struct TrackStudyRow {
  std::string subject;
  double azimuthDeg = 0.0;
  int rounds = 0;
  int frames = 0;
  double medianPx = 0.0, p95Px = 0.0;        // the track against the truth, every joint-frame
  std::array<double, kJointCount> jointMedianPx{}, jointP95Px{};  // the same per joint
  double mpjpeTruthMm = 0.0, mpjpeTrackMm = 0.0;  // NaN where that fit refused
  double alphaDeg = 0.0;                          // the camera's, METHOD §5
  double alphaTruthFitDeg = 0.0, alphaTrackFitDeg = 0.0;  // what the fits found (NaN: refused)
  double strideHz = 0.0;                     // the walker's own
  std::string error;                         // a fit's refusal, else ""
};

// Called after each row with the rows done and the total.
using TrackStudyProgress = std::function<void(const TrackStudyRow&, int done, int total)>;

// Every subject × azimuth. Error(BadArgument) for an unknown subject, no azimuth, or rounds
// outside 0-10; a fit that refuses a walker is a row with its error, not a stop.
std::vector<TrackStudyRow> runTrackStudy(const std::vector<ExperimentWalker>& walkers,
                                         const TrackStudyOptions& options,
                                         const TrackStudyProgress& progress = {});

}  // namespace ew
