#include "ui/app/clip.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/engine/model.h"
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

}  // namespace

ClipResult fitClip(const ClipSettings& settings, const ClipModel& model) {
  const auto start = std::chrono::steady_clock::now();
  KeypointOptions k;
  if (!settings.layout.empty()) k.layout = settings.layout;
  if (settings.fps > 0.0) k.fps = settings.fps;
  if (settings.person >= 0) k.person = settings.person;
  k.imageSize = settings.imageSize;
  k.video = settings.video;  // what the file does not store, from the video it was made from
  CameraFitOptions o;
  // The σ² the model stores as its optimum, as `reconstruct --unknown-camera` uses.
  o.estimator = {Estimator::Map, defaultSigma2Mm2(*model.model)};
  o.focalPx = settings.focalPx;
  o.alphaDeg = settings.alphaDeg;
  o.elevationDeg = settings.elevationDeg;
  // A tracker's joints: its trunk holds where the crossing feet are lost (docs/TRACKING_DESIGN.md).
  if (settings.tracked) holdTheTrunksStride(*settings.tracked, o);
  ClipResult r{settings, model, {}, 0.0, {}, {}};
  if (settings.tracked) {
    r.rec = reconstructKeypointTrial(*model.model, *settings.tracked, o);
  } else if (settings.detected) {
    // As `reconstruct --input V.mp4` reads a video (app/cli/video_input.cpp): the size and
    // the rate are the video's, said so.
    KeypointFrames frames = *settings.detected;
    frames.imageSize.reset();
    frames.rateHz.reset();
    KeypointTrial walker = cleanKeypoints(frames, k);
    if (settings.corrections) correctTrial(walker, *settings.corrections);
    r.rec = reconstructKeypointTrial(*model.model, walker, o);
  } else {
    r.rec = reconstructKeypointClip(*model.model, settings.path, k, o);
  }
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
