#include "video/model_loop.h"

#include "core/engines/request.h"
#include "core/camera/clip_reconstruction.h"
#include "core/camera/self_occlusion.h"
#include "core/common/errors.h"
#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {

ModelLoopResult trackWithModel(VideoSource& video, const Keyframes& keyframes,
                               const EigenwalkerModel& model, TrackerOptions options,
                               const ModelLoopOptions& loop, const TrackProgress& progress) {
  if (loop.rounds < 0 || loop.rounds > 10)
    throw Error(ErrorKind::BadArgument, video.info().file, "",
                "model loop rounds must lie in 0-10");
  // Each track is a share of the progress: round r of R+1 tracks.
  const double tracks = 1.0 + loop.rounds;
  int done = 0;
  const auto share = [&](double p) { return !progress || progress((done + p) / tracks); };
  ModelLoopResult result;
  result.track = trackJoints(video, keyframes, options, share);
  for (int round = 0; round < loop.rounds; ++round) {
    ++done;
    ClipReconstruction fit;
    try {
      // The track through the unknown camera, its trunk's bob holding the stride.
      CameraView view;
      view.keypoints = keypointTrialOf(result.track, video.info().file);
      view.strideFromTrunk = true;
      const EigenwalkerEngine engine{model, CameraFitOptions().estimator, {}};
      fit = std::move(reconstruct(engine, {std::move(view)}).camera.eigenwalker->last);
    } catch (const Error& e) {
      result.stoppedBecause = e.what();
      break;
    }
    options.firstFrame = result.track.firstFrame;
    options.priorPx = fit.reprojectedPx;
    options.priorHidden = hiddenJoints(fit.framesMm, fit.timesS, fit.fit.camera);
    result.rounds.push_back({fit.fit.reprojectionRmsPx, fit.fit.strideHz, fit.fit.camera.alphaDeg,
                             static_cast<int>(options.priorHidden.sum())});
    result.track = trackJoints(video, keyframes, options, share);
  }
  return result;
}

}  // namespace ew
