#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/render/palette.h"
#include "video/pose_model_files.h"
#include "ui/panels/clip_controls.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/section_title.h"

namespace ew::ui {

namespace {

template <class F>
void apply(AppState& s, F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    s.log.error(e.what());
  }
}

void scrubber(AppState& s, const VideoSession& v) {
  int frame = actions::shownVideoFrame(s);
  ImGui::SetNextItemWidth(-1.0f);
  char format[64];
  std::snprintf(format, sizeof format, "frame %%d of %d", v.frameCount());
  if (ImGui::SliderInt("##videoframe", &frame, 0, std::max(v.frameCount() - 1, 0), format,
                       ImGuiSliderFlags_AlwaysClamp))
    apply(s, [&] { actions::setVideoFrame(s, frame); });
  switch (buttonRow({{"<< 10", true}, {"< 1", true}, {"1 >", true}, {"10 >>", true}})) {
    case 0:
      apply(s, [&] { actions::setVideoFrame(s, frame - 10); });
      break;
    case 1:
      apply(s, [&] { actions::setVideoFrame(s, frame - 1); });
      break;
    case 2:
      apply(s, [&] { actions::setVideoFrame(s, frame + 1); });
      break;
    case 3:
      apply(s, [&] { actions::setVideoFrame(s, frame + 10); });
      break;
    default:
      break;
  }
}

// The built-in detector (ui/app/detection.h): which model, Detect with its progress and Cancel,
// what it found; without the models, the command that fetches them.
void detecting(AppState& s, const VideoSession& v) {
  sectionTitle("Detect the walker");
  if (s.video.detect.running()) {
    ImGui::ProgressBar(s.video.detect.fraction(), ImVec2(-1.0f, 0.0f),
                       s.video.detect.what().c_str());
    if (buttonRow({{"Cancel", true}}) == 0) actions::cancelDetection(s);
    return;
  }
  const bool haveModels = findPoseModels(s.video.detectorModel).has_value();
  const char* const labels[] = {"Lite", "Full", "Heavy"};
  int choice = static_cast<int>(s.video.detectorModel);
  if (radioRow(labels, 3, &choice)) apply(s, [&] { actions::setDetectorModel(s, static_cast<PoseModelSize>(choice)); });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("BlazePose's landmark model: lite is fastest, heavy most accurate (docs/DETECTOR.md)");
  const char* label = v.detected ? "Detect again" : "Detect people";
  if (buttonRow({{label, haveModels && !s.video.track.running()}}) == 0)
    apply(s, [&] { actions::startDetection(s); });
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Find the people on every frame with the built-in detector (the walker's\n"
                      "keypoints are then fitted through the unknown camera). Detections are\n"
                      "cached per video: a second time is quick.");
  if (!haveModels) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.78f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", missingPoseModelAdvice().c_str());
    ImGui::PopStyleColor();
  }
  if (v.detected) {
    textDisabledWrapped(detectionSummary(*v.detected).c_str());
    if (v.detected->people > 0 && !actions::showsDetectionFit(s) && !s.clip.fits.running() &&
        buttonRow({{"Fit the detections", true}}) == 0)
      apply(s, [&] { actions::fitDetections(s); });
  }
  if (!v.detectError.empty() && haveModels) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.55f, 1.0f));
    ImGui::TextWrapped("%s", v.detectError.c_str());
    ImGui::PopStyleColor();
  }
  bool onOpen = s.video.detectWhenOpens;
  if (checkboxWrapped("Detect when a video opens", &onOpen)) actions::setDetectWhenVideoOpens(s, onOpen);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A video opened alone is handed to the detector at once\n"
                      "(opened with its keyframe file, it is for marking and tracking)");
}

// The keypoint file or folder typed in the Mark section.
std::array<char, 1024> keypointsField{};

// A pose estimator's detections on the frame shown as its keyframe (actions::markFromKeypoints).
void markingFromKeypoints(AppState& s) {
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##keypoints", "keypoint file or folder", keypointsField.data(),
                           keypointsField.size());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("OpenPose, AlphaPose or MMPose JSON, or a keypoint CSV, of this video\n"
                      "(its first frame the video's first)");
  if (buttonRow({{"Mark this frame from it", keypointsField[0] != '\0'}}) == 0)
    apply(s, [&] { actions::markFromKeypoints(s, keypointsField.data()); });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("This frame's joints as the pose estimator found them: a keyframe to\n"
                      "track from, instead of clicking each joint");
}

void marking(AppState& s, const VideoSession& v) {
  sectionTitle("Mark the joints");
  const int shown = actions::shownVideoFrame(s);
  const Keyframe* k = v.keyframeAt(shown);
  const int marked = k ? static_cast<int>(k->jointsPx.array().isFinite().count() / 2) : 0;
  // On a detected video the marks are corrections of the detections (actions::correctsDetections).
  const bool correcting = actions::correctsDetections(s);
  char status[96];
  std::snprintf(status, sizeof status, "%zu %s%s · this frame: %d of 15 joints", v.keyframes.keyframes.size(),
                correcting ? "correction" : "keyframe", v.keyframes.keyframes.size() == 1 ? "" : "s", marked);
  textDisabledWrapped(status);
  if (correcting && !v.marking)
    textDisabledWrapped("Drag a joint where the detector went wrong: the track is redone around it "
                        "and fitted again.");
  if (!v.marking) {
    if (buttonRow({{"Mark this frame", true}}) == 0) apply(s, [&] { actions::startMarking(s); });
  } else {
    switch (buttonRow({{"Skip joint", v.markStep < kJointCount}, {"Done", true}})) {
      case 0:
        apply(s, [&] { actions::skipMarkedJoint(s); });
        break;
      case 1:
        apply(s, [&] { actions::stopMarking(s); });
        break;
      default:
        break;
    }
  }
  switch (
      buttonRow({{"Undo", !v.undo.empty()}, {"Redo", !v.redo.empty()}, {"Remove", k != nullptr}})) {
    case 0:
      apply(s, [&] { actions::undoKeyframes(s); });
      break;
    case 1:
      apply(s, [&] { actions::redoKeyframes(s); });
      break;
    case 2:
      apply(s, [&] { actions::removeKeyframe(s, shown); });
      break;
    default:
      break;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Forget the joints marked on this frame");
  const int before = actions::neighbouringKeyframe(s, -1), after = actions::neighbouringKeyframe(s, 1);
  switch (buttonRow({{"< Keyframe", before >= 0}, {"Keyframe >", after >= 0}})) {
    case 0:
      apply(s, [&] { actions::setVideoFrame(s, before); });
      break;
    case 1:
      apply(s, [&] { actions::setVideoFrame(s, after); });
      break;
    default:
      break;
  }
  markingFromKeypoints(s);
  const std::string hint = std::string(v.marking ? "S: skip the joint · Enter: done · " : "") +
                           (v.zoom > 1.0 ? "wheel: zoom · right-drag: move · right double-click: whole picture"
                                         : "wheel over the picture: zoom in to mark");
  textDisabledWrapped(hint.c_str());
}

// Optical flow (video/joint_tracker.h) or Zou et al.'s appearance tracker
// (video/appearance_tracker.h): the second is there to compare, as issue 16 asks.
void trackerChoice(AppState& s, const VideoSession& v) {
  static const char* const labels[] = {"Optical flow", "Appearance (Zou)"};
  int choice = v.tracker == TrackerKind::Appearance ? 1 : 0;
  if (radioRow(labels, 2, &choice))
    apply(s, [&] {
      actions::setTracker(s, choice == 1 ? TrackerKind::Appearance : TrackerKind::OpticalFlow);
    });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Optical flow: each joint's own flow, checked against its keyframe look.\n"
        "Appearance: Zou et al. 2009, each segment's colours from the marked frame,\n"
        "joints sought down the body's tree (slower, measured less accurate: docs/TRACKING.md).");
}

// The flow tracker can flatten a fixed camera's still background first: thin limbs over a
// textured background then move the flow by their own texture (docs/TRACKING.md).
void backgroundChoice(AppState& s, const VideoSession& v) {
  ImGui::BeginDisabled(v.tracker != TrackerKind::OpticalFlow);
  bool flatten = v.flattenBackground;
  if (ImGui::Checkbox("Flatten background", &flatten))
    apply(s, [&] { actions::setFlattenBackground(s, flatten); });
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "For a camera that does not move: each pixel's median over the clip is the\n"
        "background, set to one grey before the optical flow, so that only the person\n"
        "moves it. Skipped, with the reason, when the camera moves or the person\n"
        "stays in place. Optical flow only.");
}

// A bare upper body gives the shoulders' flow nothing to hold along the arms; the trunk can
// (docs/TRACKING.md, "Holding the trunk").
void trunkChoice(AppState& s, const VideoSession& v) {
  bool hold = v.holdTheTrunk;
  ImGui::BeginDisabled(v.tracker != TrackerKind::OpticalFlow);
  if (ImGui::Checkbox("Hold the trunk", &hold)) apply(s, [&] { actions::setHoldTheTrunk(s, hold); });
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "The shoulders and hips move with the pelvis-sternum line, as on the first\n"
        "keyframe: where their own flow strays from there, they are put there.\n"
        "For a bare or plain upper body that bends but turns little; measured worse\n"
        "on walkers filmed from the side (docs/TRACKING.md). Optical flow only.");
}

// Howe, Leventon & Freeman's feedback: the walker fitted to a track guides the next one
// (video/model_loop.h). Rounds 0-10; the flow tracker only.
void modelLoopChoice(AppState& s, const VideoSession& v) {
  ImGui::BeginDisabled(v.tracker != TrackerKind::OpticalFlow);
  int rounds = v.modelLoopRounds;
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderInt("##loop", &rounds, 0, 10,
                       rounds == 0 ? "model loop: off" : rounds == 1 ? "model loop: 1 round" : "model loop: %d rounds"))
    apply(s, [&] { actions::setModelLoopRounds(s, rounds); });
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Fit the walker through the camera to the track, draw it back, and track again\n"
        "seeking each joint that strays where the walk puts it (Howe, Leventon &\n"
        "Freeman 1999). Brings lost wrists and ankles back; each round costs a track\n"
        "and a fit. Optical flow only.");
}

std::string loopNote(const TrackedVideo& t) {
  if (t.modelLoopRounds == 0) return "";
  char text[160];
  if (t.loopRounds.empty()) return "model loop stopped: " + t.loopStopped;
  std::snprintf(text, sizeof text,
                "model loop: %zu of %d rounds, fit %.1f → %.1f px\n%d joint-frames behind the "
                "body, placed by the walk",
                t.loopRounds.size(), t.modelLoopRounds, t.loopRounds.front().reprojectionRmsPx,
                t.loopRounds.back().reprojectionRmsPx, t.loopRounds.back().hiddenJointFrames);
  std::string note = text;
  if (!t.loopStopped.empty()) note += "; stopped: " + t.loopStopped;
  return note;
}

ImU32 u32(const glm::vec4& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }

// The track's mean confidence per frame as a strip the panel's width, coloured as the tracked
// joints are (sure blue, lost red), the fit's 0.3 as a faint line, the keyframes as teal ticks
// and the frame shown as a white line; a click or drag on it goes to that frame. Where the
// curve dips is where to look for joints that strayed.
void confidenceStrip(AppState& s, const VideoSession& v, float scale) {
  const TrackedVideo& t = *v.tracked;
  const int n = t.frames();
  if (n < 2) return;
  const float w = ImGui::GetContentRegionAvail().x, h = 34.0f * scale;
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##confidence", ImVec2(w, h));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), ImGui::GetColorU32(ImGuiCol_FrameBg));
  const auto x = [&](double frame) { return p0.x + static_cast<float>((frame - t.track.firstFrame + 0.5) / n) * w; };
  const auto y = [&](double c) { return p0.y + h - 2.0f - (h - 4.0f) * static_cast<float>(std::clamp(c, 0.0, 1.0)); };
  dl->AddLine(ImVec2(p0.x, y(0.3)), ImVec2(p0.x + w, y(0.3)), ImGui::GetColorU32(ImGuiCol_TextDisabled, 0.5f));
  // A long track is drawn a point per pixel column, each its frames' lowest mean: a dip of one
  // frame in a ten-minute clip still shows.
  const int points = std::clamp(static_cast<int>(w), 2, n);
  const Eigen::VectorXd& means = t.meanConfidence;
  const auto column = [&](int c) {
    const int from = static_cast<int>(static_cast<long long>(c) * n / points);
    const int to = std::max(from + 1, static_cast<int>(static_cast<long long>(c + 1) * n / points));
    return std::pair{t.track.firstFrame + 0.5 * (from + to - 1), means.segment(from, to - from).minCoeff()};
  };
  auto [fa, a] = column(0);
  for (int c = 1; c < points; ++c) {
    const auto [fb, b] = column(c);
    dl->AddLine(ImVec2(x(fa), y(a)), ImVec2(x(fb), y(b)),
                u32(palette::confidenceColour(static_cast<float>(0.5 * (a + b)))), 1.5f * scale);
    fa = fb;
    a = b;
  }
  for (const Keyframe& k : v.keyframes.keyframes)
    if (k.frame >= t.track.firstFrame && k.frame <= t.lastFrame())
      dl->AddLine(ImVec2(x(k.frame), p0.y), ImVec2(x(k.frame), p0.y + h), u32(palette::kCamera), 1.5f * scale);
  const int shown = actions::shownVideoFrame(s);
  if (shown >= t.track.firstFrame && shown <= t.lastFrame())
    dl->AddLine(ImVec2(x(shown), p0.y), ImVec2(x(shown), p0.y + h), IM_COL32(240, 242, 248, 230), 1.0f * scale);
  const int under = t.track.firstFrame +
                    std::clamp(static_cast<int>((ImGui::GetIO().MousePos.x - p0.x) / w * static_cast<float>(n)), 0, n - 1);
  if (ImGui::IsItemActive() && under != shown) apply(s, [&] { actions::setVideoFrame(s, under); });
  if (ImGui::IsItemHovered()) {
    const Eigen::Index r = under - t.track.firstFrame;
    Eigen::Index weakest = 0;
    t.track.confidence.row(r).minCoeff(&weakest);
    ImGui::SetTooltip("frame %d: mean confidence %.2f, least sure %s (%.2f)\nclick or drag: go to the frame",
                      under, means(r), std::string(kJointNames[weakest]).c_str(),
                      t.track.confidence(r, weakest));
  }
}

// A full-width button to a suggested frame ("Name (N)"; greyed when there is none, frame < 0),
// with its tooltip.
void goToFrameButton(AppState& s, const char* name, int frame, const char* tooltip) {
  char label[64];
  std::snprintf(label, sizeof label, frame >= 0 ? "%s (%d)" : "%s", name, frame);
  if (buttonRow({{label, frame >= 0}}) == 0) apply(s, [&] { actions::setVideoFrame(s, frame); });
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", tooltip);
}

// The strip; a button to the frame whose marks would help the track most, and one to the
// frame the tracker was least sure of (no keyframe): the place to check first, and to drag the
// joints that strayed (the frame becomes a keyframe).
void refining(AppState& s, const VideoSession& v, float scale) {
  confidenceStrip(s, v, scale);
  goToFrameButton(s, "Frame to mark next", actions::nextFrameToMark(s),
                  "The frame that, marked, helps the track most: the tracker drifts with the\n"
                  "motion it follows, and this frame leaves the least of the joints' motion\n"
                  "between each frame and its nearest keyframe. Drag its joints that strayed\n"
                  "(the frame becomes a keyframe and the track is redone from it)");
  goToFrameButton(s, "Least sure frame", actions::leastSureTrackedFrame(s),
                  "The tracked frame, not a keyframe, with the lowest mean confidence: check it,\n"
                  "and drag any joint that strayed (the frame becomes a keyframe and the\n"
                  "track is redone from it)");
}

std::string backgroundNote(const std::string& background) {
  return background == "flattened" ? "background flattened" : "background kept: " + background;
}

void tracking(AppState& s, const VideoSession& v, float scale) {
  sectionTitle("Track");
  int range[2] = {v.firstFrame, v.lastFrame < 0 ? v.frameCount() - 1 : v.lastFrame};
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputInt2("##range", range, ImGuiInputTextFlags_EnterReturnsTrue))
    apply(s, [&] { actions::setTrackRange(s, range[0], range[1]); });
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The first and last frame to track (Enter)");
  trackerChoice(s, v);
  backgroundChoice(s, v);
  trunkChoice(s, v);
  modelLoopChoice(s, v);
  const bool stale =
      v.tracked &&
      (v.tracked->tracker != v.tracker || v.tracked->flattenBackground != v.flattenBackground ||
       v.tracked->holdTheTrunk != (v.tracker == TrackerKind::OpticalFlow && v.holdTheTrunk) ||
       v.tracked->modelLoopRounds !=
           (v.tracker == TrackerKind::OpticalFlow ? v.modelLoopRounds : 0) ||
       v.tracked->track.firstFrame != v.firstFrame || !sameKeyframes(v.tracked->keyframes, v.keyframes));
  char label[96];
  std::snprintf(label, sizeof label, "%s frames %d-%d",
                stale       ? "Track again,"
                : v.tracked ? "Track"
                            : "Track",
                range[0], range[1]);
  if (s.video.track.running()) {
    ImGui::ProgressBar(s.video.track.fraction(), ImVec2(-1.0f, 0.0f), s.video.track.what().c_str());
    if (buttonRow({{"Cancel", true}}) == 0) actions::cancelTracking(s);
  } else if (buttonRow({{label, !v.keyframes.keyframes.empty()}}) == 0) {
    apply(s, [&] { actions::startTracking(s); });
  }
  if (stale)
    textDisabledWrapped("the keyframes or the tracker's settings changed since the last track");
  if (v.tracked) {
    const auto& t = *v.tracked;
    char done[128];
    std::snprintf(done, sizeof done, "tracked %s%d-%d by %s in %.1f s (%.0f frames/s)",
                  t.ranPart() ? "again " : "", t.ranFirst, t.ranLast,
                  t.tracker == TrackerKind::Appearance ? "appearance" : "optical flow", t.seconds,
                  t.framesRan() / std::max(t.seconds, 1e-9));
    textDisabledWrapped(done);
    ImGui::TextDisabled("mean confidence %.2f", t.meanConfidence.mean());
    if (t.flattenBackground) textDisabledWrapped(backgroundNote(t.track.background).c_str());
    if (t.holdTheTrunk) textDisabledWrapped("shoulders and hips held to the trunk");
    if (t.modelLoopRounds > 0) textDisabledWrapped(loopNote(t).c_str());
    refining(s, v, scale);
  }
  if (!v.trackError.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.55f, 1.0f));
    ImGui::TextWrapped("%s", v.trackError.c_str());
    ImGui::PopStyleColor();
  }
}

// The folder the keyframes and the track are saved into, and the video it was offered for.
std::array<char, 1024> saveField{};
std::filesystem::path saveFieldVideo;

void saveTooltip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

// The marks and the track kept where `eigenwalker-cli track` and other tools read them.
void saving(AppState& s, const VideoSession& v) {
  sectionTitle("Save");
  if (saveFieldVideo != v.path) {
    const std::string folder = actions::defaultTrackFolder(s).string();
    saveField.fill('\0');
    std::copy_n(folder.begin(), std::min(folder.size(), saveField.size() - 1), saveField.begin());
    saveFieldVideo = v.path;
  }
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##savefolder", "folder", saveField.data(), saveField.size());
  saveTooltip("The folder to save into (made when missing; a relative one is\n"
              "in the folder the viewer was started in)");
  const std::filesystem::path folder(saveField.data());
  const auto attempt = [&](const char* what, auto&& save) {
    try {
      save();
    } catch (const std::exception& e) {
      actions::reportError(s, std::string("Could not save ") + what, e.what());
    }
  };
  const int clicked = buttonRow({{"Save keyframes", !v.keyframes.keyframes.empty() && saveField[0] != '\0'},
                                 {"Save the track", v.tracked != nullptr && saveField[0] != '\0'}});
  if (clicked == 0)
    attempt("the keyframes", [&] { actions::saveKeyframesInto(s, folder); });
  if (clicked == 1) attempt("the track", [&] { actions::saveTrack(s, folder); });
  saveTooltip("Save keyframes: the joints marked, as NAME_keyframes.json (track --keyframes).\n"
              "Save the track: keypoints/ as OpenPose JSON, track_2d.csv, confidence.csv and\n"
              "the keyframes it was tracked from, as `eigenwalker-cli track --out` writes them.");
}

}  // namespace

void drawVideoControls(AppState& s, float scale) {
  if (!s.video.session) return;
  const VideoSession& v = *s.video.session;
  sectionTitle("Video");
  ImGui::TextWrapped("%s", v.path.filename().string().c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", v.path.string().c_str());
  const VideoInfo& i = v.frames->info();
  char info[128];
  std::snprintf(info, sizeof info, "%d×%d · %.4g fps · %d frames", i.widthPx, i.heightPx, i.fps,
                v.frameCount());
  textDisabledWrapped(info);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("codec %s", i.codec.empty() ? "unknown" : i.codec.c_str());
  scrubber(s, v);
  detecting(s, v);
  marking(s, v);
  tracking(s, v, scale);
  saving(s, v);
  if (buttonRow({{"Close the video", true}}) == 0) actions::closeVideo(s);
}

}  // namespace ew::ui
