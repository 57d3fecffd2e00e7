// Picking up the open video's background work (ui/app/video_poll.h): a detection becomes the
// clip to fit, a track becomes the clip to fit, and what failed is said in the banner.
#include "ui/app/video_poll.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

#include "ui/app/actions.h"

namespace ew::ui {

namespace {

// The track asked for again after an edit that came while one ran (actions::letGoOfJoint).
void trackAgain(AppState& s) {
  s.video.session->trackAgainWhenStopped = false;
  try {
    actions::startTracking(s);
  } catch (const std::exception& e) {
    s.log.error(e.what());
  }
}

}  // namespace

// A frame the stream does not have (a file cut short, a damaged frame) is said once, in the
// banner, with how long the video now is: scrubbing never shows it, it only stops short.
void reportDecodingError(AppState& s) {
  if (!s.video.session || !s.video.session->frames) return;
  VideoSession& v = *s.video.session;
  const std::string error = v.frames->error();
  if (error.empty() || error == v.decodeErrorShown) return;
  v.decodeErrorShown = error;
  actions::reportError(s, "Part of " + v.path.filename().string() + " cannot be decoded",
                       error + "; the video is taken to end after " + std::to_string(v.frameCount()) +
                           (v.frameCount() == 1 ? " frame" : " frames"));
}

namespace {

// A finished detection: the walker's keypoints fitted as the clip; nobody found, or a
// detection that failed, said in the banner; a cancelled one logged.
void takeDetection(AppState& s, JobOutcome<std::shared_ptr<const DetectedVideo>>& outcome) {
  VideoSession& v = *s.video.session;
  const std::string name = v.path.filename().string();
  v.detecting.reset();
  v.followDetection = false;
  if (!outcome.value) {
    if (outcome.error.find("cancelled") != std::string::npos) {
      s.log.info("Detection cancelled");
      return;
    }
    ++s.notices.failures;
    v.detectError = outcome.error;
    actions::reportError(s, "Could not detect people in " + name, outcome.error);
    s.notices.banner->shortTitle = "Detection failed";
    return;
  }
  v.detected = *outcome.value;
  const DetectedVideo& d = *v.detected;
  s.log.info("Detected in " + name + ": " + detectionSummary(d));
  for (const auto& w : d.warnings) s.log.warning(w);
  if (d.people == 0) {
    ++s.notices.failures;
    v.detectError = "nobody found in its " + std::to_string(d.framesRead) + " frames";
    actions::reportError(s, "Nobody found in " + name,
                         "the detector found no person in its " + std::to_string(d.framesRead) +
                             " frames. Mark the walker's joints on one frame and track them (Mark the joints).");
    s.notices.banner->shortTitle = "Nobody found";
    v.frame = 0;
    return;
  }
  v.showWalkerWhenFitted = true;
  actions::fitDetections(s);
}

}  // namespace

void pollVideo(AppState& s) {
  reportDecodingError(s);
  if (auto detection = s.video.detect.poll()) {
    // A detection of a video closed since is no detection of this one.
    if (s.video.session &&
        (!detection->value || (*detection->value)->video == s.video.session->path))
      takeDetection(s, *detection);
  }
  if (s.video.session && s.video.session->detecting && s.video.session->followDetection)
    s.video.session->frame = std::max(s.video.session->detecting->latestFrame(), 0);
  auto outcome = s.video.track.poll();
  if (!outcome || !s.video.session) return;
  VideoSession& v = *s.video.session;
  // A track of a video closed since (cancelled, or finished first) is no track of this one.
  if (outcome->value && (*outcome->value)->video != v.path) return;
  if (!outcome->value) {
    const bool cancelled = outcome->error.find("cancelled") != std::string::npos;
    v.trackError = cancelled ? "" : outcome->error;
    if (cancelled && v.trackAgainWhenStopped) {
      trackAgain(s);
      return;
    }
    if (cancelled) {
      s.log.info("Tracking cancelled");
    } else {
      ++s.notices.failures;
      actions::reportError(s, "Could not track " + v.path.filename().string(), outcome->error);
    }
    return;
  }
  v.tracked = *outcome->value;
  char buf[160];
  std::snprintf(buf, sizeof buf, "Tracked %s%d frames (%d-%d) in %.1f s (%.0f frames/s)",
                v.tracked->ranPart() ? "again " : "", v.tracked->framesRan(), v.tracked->ranFirst,
                v.tracked->ranLast, v.tracked->seconds, v.tracked->framesRan() / std::max(v.tracked->seconds, 1e-9));
  s.log.info(buf);
  for (const auto& w : v.tracked->trial->warnings) s.log.warning(w);
  // Fitted as a clip, keeping the camera values the user held for this video.
  ClipSettings c = s.clip.settings && s.clip.settings->path == v.path ? *s.clip.settings : ClipSettings{};
  c.path = v.path;
  c.tracked = v.tracked->trial;
  // A track's fit is not held to the scene's horizon, only checked against it: on the sports2d
  // demo's track (about 28 px RMS against the detector's 10) the held fit's focal length went
  // from 2890 to 3600 px, and the walker's distance from 10.7 to 13.0 m, away from Sports2D's
  // 2520 px and 10 m (docs/CAMERA.md, "The scene's horizon").
  c.horizonRowPx = v.tracked->horizon.rowPx();
  c.holdToHorizon = false;
  s.clip.settings = c;
  s.doc.mode = Mode::Clip;
  s.clip.fits.retry();
  // A joint let go while this track ran, which finished before it saw the cancel.
  if (v.trackAgainWhenStopped) trackAgain(s);
}

}  // namespace ew::ui
