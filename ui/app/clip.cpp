#include "ui/app/clip.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/camera/camera_knowledge.h"
#include "core/eigenwalker/model.h"
#include "core/engines/request.h"
#include "core/tracking/corrected_track.h"

namespace ew::ui {

namespace {

void extend(PixelBounds& b, const Eigen::MatrixXd& px) {
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    for (Eigen::Index j = 0; j + 1 < px.cols(); j += 2) {
      const Eigen::Vector2d p(px(f, j), px(f, j + 1));
      if (!p.allFinite()) continue;
      b.low = b.empty ? p : Eigen::Vector2d(b.low.cwiseMin(p));
      b.high = b.empty ? p : Eigen::Vector2d(b.high.cwiseMax(p));
      b.empty = false;
    }
  }
}

// What the viewer's fields say of the camera, resolved by the rule the CLI's options follow
// (core/camera/camera_knowledge.h), each field named in its errors.
CameraKnowledge cameraOf(const ClipSettings& settings) {
  CameraGivens g;
  g.focalPx = settings.focalPx;
  g.calibrationFile = settings.calibrationFile;
  if (!settings.calibrationCamera.empty()) g.calibrationCamera = settings.calibrationCamera;
  g.imageSize = settings.imageSize;
  g.alphaDeg = settings.alphaDeg;
  g.elevationDeg = settings.elevationDeg;
  g.names = {"the focal length", "the calibration file", "the image's size", "the azimuth", "the elevation"};
  CameraKnowledge k = resolveCameraKnowledge(g);
  if (!k.elevationDeg && settings.holdToHorizon) k.horizonRowPx = settings.horizonRowPx;  // a held elevation needs none
  return k;
}

// The eigenwalker through the camera (core/engines/request.h), with the σ² the model stores
// as its optimum, as `reconstruct --unknown-camera` fits; a calibrated lens undone first.
ClipReconstruction fitThroughCamera(const ClipModel& model, KeypointTrial trial, const CameraKnowledge& camera,
                                    bool tracked) {
  undistortKeypoints(camera, trial);
  CameraView view;
  view.keypoints = std::move(trial);
  view.camera = camera;
  // A tracker's joints: its trunk holds where the crossing feet are lost (docs/TRACKING_DESIGN.md).
  view.strideFromTrunk = tracked;
  const EigenwalkerEngine engine{*model.model, {Estimator::Map, defaultSigma2Mm2(*model.model)}, {}};
  return std::move(reconstruct(engine, {std::move(view)}).camera.eigenwalker->last);
}

}  // namespace

ClipResult fitClip(const ClipSettings& settings, const ClipModel& model) {
  const auto start = std::chrono::steady_clock::now();
  KeypointOptions k;
  if (!settings.layout.empty()) k.layout = settings.layout;
  if (settings.fps > 0.0) k.fps = settings.fps;
  if (settings.person >= 0) k.person = settings.person;
  const CameraKnowledge camera = cameraOf(settings);
  k.imageSize = camera.imageSize;
  k.video = settings.video;  // what the file does not store, from the video it was made from
  ClipResult r{settings, model, {}, 0.0, {}, {}};
  if (settings.tracked) {
    r.rec = fitThroughCamera(model, *settings.tracked, camera, true);
  } else if (settings.detected) {
    // As `reconstruct --input V.mp4` reads a video (app/cli/video_input.cpp): the size and
    // the rate are the video's, said so.
    KeypointFrames frames = *settings.detected;
    frames.imageSize.reset();
    frames.rateHz.reset();
    KeypointTrial walker = cleanKeypoints(frames, k);
    if (settings.corrections) correctTrial(walker, *settings.corrections);
    r.rec = fitThroughCamera(model, std::move(walker), camera, false);
  } else {
    r.rec = fitThroughCamera(model, readKeypointTrial(settings.path, k), camera, false);
  }
  if (settings.horizonRowPx)
    if (std::string caution = sceneHorizonCaution(r.rec.fit, *settings.horizonRowPx, camera.horizonRowPx.has_value());
        !caution.empty())
      r.rec.cautions.push_back(std::move(caution));
  // The reader took the size as given: say it was the calibration's, as the CLI's report does.
  if (camera.imageSizeFromCalibration && r.rec.trial.imageSize == camera.imageSize)
    r.rec.trial.imageSizeSource = "the calibration's";
  extend(r.keypointBounds, r.rec.trial.jointsPx);
  r.shownBounds = r.keypointBounds;
  extend(r.shownBounds, r.rec.reprojectedPx);
  // The other people the picker offers, when they stay long enough to be picked.
  for (const PersonTrack& person : r.rec.trial.people)
    if (10 * person.frames.size() >= static_cast<std::size_t>(r.rec.trial.frameCount))
      extend(r.shownBounds, person.jointsPx);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

const char* unfittedClipMessage(const std::string& fitError) {
  return fitError.find(kNeedsImageSize) != std::string::npos ? "type the image's size (Keypoint clip, under Controls)"
                                                              : "the clip could not be fitted";
}

int clipFrameAt(const ClipResult& clip, double cycles) {
  const int frames = clip.rec.trial.frameCount;
  const double strideHz = clip.rec.fit.strideHz;
  if (frames <= 0 || !(strideHz > 0.0)) return 0;
  const double t = std::fmod(std::max(cycles, 0.0) / strideHz, clip.durationS());
  return std::clamp(static_cast<int>(t * clip.rec.trial.rateHz), 0, frames - 1);
}

std::string heldCameraValues(const ClipSettings& settings) {
  std::vector<std::string> parts;
  char buf[64];
  if (!settings.calibrationFile.empty()) {
    std::string calibration = "calibration " + settings.calibrationFile.filename().string();
    if (!settings.calibrationCamera.empty()) calibration += " (" + settings.calibrationCamera + ")";
    parts.push_back(calibration);
  }
  if (settings.focalPx) {
    std::snprintf(buf, sizeof buf, "focal %.0f px", *settings.focalPx);
    parts.emplace_back(buf);
  }
  if (settings.alphaDeg) {
    std::snprintf(buf, sizeof buf, "azimuth %.1f°", *settings.alphaDeg);
    parts.emplace_back(buf);
  }
  if (settings.elevationDeg) {
    std::snprintf(buf, sizeof buf, "elevation %.1f°", *settings.elevationDeg);
    parts.emplace_back(buf);
  }
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : ", ") + p;
  return out;
}

}  // namespace ew::ui
