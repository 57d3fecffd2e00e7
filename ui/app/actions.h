#pragma once
// The operations on the document, shared by the panels and the script runner so that a
// script does exactly what a click does. Each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/mapping/mapping_file.h"
#include "ui/app/app_state.h"

namespace ew::ui::actions {

// Starts loading `paths` (empty = the synthetic default population) in the background.
// The data on screen stays until the new data has loaded; a load that fails leaves it, and
// everything the user chose, as it was, and says why (reportOpenError).
void open(AppState& s, std::vector<std::filesystem::path> paths);
// Picks up finished background jobs; starts the model build after a load. Call once a frame.
// A model build that fails puts back the data shown before the load.
void pollJobs(AppState& s);

// [SECTION] Errors the user sees: the log, and the banner over the views (OpenNotice).
// "walk.csv", "a.bvh, b.bvh, c.bvh, … (2 more)", "the synthetic default population".
std::string describePaths(const std::vector<std::filesystem::path>& paths);
// An error banner (title, the reason, what is still shown) and lastError; no Retry.
void reportError(AppState& s, const std::string& title, const std::string& detail);
// An amber banner (not an error: nothing failed, but the user should know), and the log.
void reportNote(AppState& s, const std::string& title, const std::string& detail,
                const std::string& shortTitle = "");
// "Could not open PATHS" with the reason, and Retry (which opens `paths` again).
void reportOpenError(AppState& s, const std::vector<std::filesystem::path>& paths,
                     const std::string& message);
void dismissNotice(AppState& s);  // hides the banner, clears lastError

void selectWalker(AppState& s, int index);
void selectSubject(AppState& s, const std::string& subjectOrId);
void setMode(AppState& s, Mode mode);
void setAngle(AppState& s, double alphaDeg);
void setEstimator(AppState& s, Estimator estimator);
// The engine that reconstructs in reconstruct mode (its name: engineName).
void setEngine(AppState& s, EngineKind engine);
// Compare mode: every engine reconstructs the walker, drawn together (reconstruct mode).
void setCompareEngines(AppState& s, bool on);
// Which engines compare mode draws.
void setCompareShown(AppState& s, EngineKind engine, bool shown);
void setSigma2(AppState& s, double sigma2Mm2);  // the user's choice: stops following the model
// Until the user sets σ², it is the held model's stored optimum (or the paper's 70 mm²).
void followModelSigma2(AppState& s);
void setComponents(AppState& s, int components);  // 0 = auto (95 %)
void setUnknownAngle(AppState& s, bool unknown);
// index from 0; value in SD units, clamped to ±3. Explore mode: the explorer's
// coefficients; reconstruct mode: an edit of the estimate.
void setCoefficient(AppState& s, int index, double sd);
void resetCoefficients(AppState& s);
void randomiseCoefficients(AppState& s, unsigned seed);
void coefficientsFromWalker(AppState& s);  // explorer starts from the selected walker

// [SECTION] Semantic axes (explore mode; ui/app/semantic.h)
ExploreState exploreState(const AppState& s);
// The explorer's walker = `from` moved by `delta` (the attribute's units) along the axis of
// `attribute` (coefficients clamped to ±3 SD). Throws std::invalid_argument for an unknown axis.
void moveAlongAxis(AppState& s, const std::string& attribute, const ExploreState& from,
                   double delta);
// The axis's predictor reading of the explorer's walker.
double semanticReading(const AppState& s, const std::string& attribute);
// Moves the walker along the axis by what it takes from its reading to `value`.
void setSemanticValue(AppState& s, const std::string& attribute, double value);
void setPhase(AppState& s, double phase01);
void setPlaying(AppState& s, bool playing);
// Overlay names: depth_error, error_lines, error_bars, metrics, ghost, camera, grid,
// reprojection, stick_figure, trails, point_lights.
void setOverlay(AppState& s, const std::string& name, bool on);
std::vector<std::string> overlayNames();
bool overlay(const AppState& s, const std::string& name);  // throws for an unknown name
void setCamera(AppState& s, const std::string& preset);    // three_quarter, front, side, top

// [SECTION] Export (ui/app/export.h). Paths are written atomically.
// A PNG of the window or of one view, written after the next frames are drawn.
void requestPng(AppState& s, std::filesystem::path path, CaptureView view);
CaptureView captureViewFromName(const std::string& name);  // window, input, reconstruction
// Starts rendering a video in the background of the frame loop (a progress bar shows
// it); throws std::invalid_argument / std::runtime_error when it cannot start.
void startVideoExport(AppState& s, const VideoSettings& settings);
void cancelVideoExport(AppState& s);
// The displayed walker (displayedWalkerMotion) as 15-joint CSV / BVH; the model the
// reconstruction uses (the leave-one-out model of the held-out subject, every component;
// explore mode: the model of every walker). Throw with a readable message on failure.
void exportCsv(AppState& s, const std::filesystem::path& path,
               std::optional<double> cycles = std::nullopt);
void exportBvh(AppState& s, const std::filesystem::path& path,
               std::optional<double> cycles = std::nullopt);
void exportModel(AppState& s, const std::filesystem::path& path);
// The document, the view settings, the banner and the log as JSON (ui/app/state_json.h), for
// scripts and tests to check what the viewer holds.
void exportState(AppState& s, const std::filesystem::path& path);
// Records a failed PNG / video export: log, header, failure count.
void reportExportError(AppState& s, const std::string& message);

// [SECTION] Analysis (ui/app/analysis.h)
// The analysis holds out the walkers of the model the walkers are reconstructed against: the
// loaded population's, or the held model's (the default model, an opened .ewm).
AnalysisKey analysisKey(const AppState& s);
// The selected walker's subject among the analysed ones ("" when it is none of them).
std::string analysisSubject(const AppState& s);
// Starts the analysis for the current inputs in the background unless cached or running.
void requestAnalysis(AppState& s);
// The analysis for the current inputs: cached, or computed now (blocking; scripts).
std::shared_ptr<const AnalysisResult> analysisNow(AppState& s);
// The current curves (selected subject and mean, LSQ and MAP, every metric) as CSV.
void exportAnalysisCsv(AppState& s, const std::filesystem::path& path);
// The plotted metric: "E_a", "E_r" or "MPJPE".
void setAnalysisMetric(AppState& s, const std::string& name);

// [SECTION] Gait report (ui/app/gait_report.h, ui/panels/gait_panel.h)
// By the extension: .csv or .json the report; .trc the reconstruction walked over the floor at
// its measured speed as an OpenSim marker file, and its joint angles beside it as .mot.
// Throws ew::Error naming the file, std::invalid_argument when there is nothing to export.
void exportGaitReport(AppState& s, const std::filesystem::path& path);

// [SECTION] Opening data
// Files or folders dropped on the window (or the script action "drop"): the items that exist
// and are a folder or a supported file (.c3d .bvh .asf .amc .trc .csv .tsv) are opened, the others
// skipped with a warning; throws std::invalid_argument (and opens nothing) when none is.
void drop(AppState& s, const std::vector<std::filesystem::path>& paths);
// Unit ("" = the file's; mm, cm, m, in, cmu) and frame rate (0 = the file's) for one file;
// takes effect at the next open (reloadWithOverrides reopens the current data).
void setFileOverride(AppState& s, const std::filesystem::path& file, const std::string& units,
                     double rateHz);
void reloadWithOverrides(AppState& s);
// Writes `mapping` (core/mapping/mapping_file.h) to `out` and makes it `file`'s mapping for the
// next open (a per-file override); `openNow`: opens `file` with it at once. Throws ew::Error
// naming the file when it cannot be written.
void writeJointMapping(AppState& s, const std::filesystem::path& file,
                       const std::filesystem::path& out, const JointMapping& mapping, bool openNow);
// The data table for the current data: started in the background / computed now (scripts).
void requestDataSummary(AppState& s);
std::shared_ptr<const DataSummary> dataSummaryNow(AppState& s);
void exportDataSummary(AppState& s, const std::filesystem::path& path);

// [SECTION] Teaching
void setTheme(AppState& s, const std::string& name);  // dark, light, projector
// Presentation mode (F5): only the two views, large captions, play / pause and the view angle.
void setPresentation(AppState& s, bool on);
// The guided tour (ui/app/tour.h): each step applies its actions through applyAction,
// exactly as a script would. Next on the last step ends the tour.
void tourStart(AppState& s);
void tourNext(AppState& s);
void tourBack(AppState& s);
void tourEnd(AppState& s);

// Floating panels: "export", "analysis", "help", "data", "notice_details" (the full message of
// the notice row), "model" (the model selector); throws for an unknown name.
void showPanel(AppState& s, const std::string& name, bool shown);

// [SECTION] The model held (docs/VIEWER.md, "Models and walkers")
// "population" (the loaded population's leave-one-out models), "default" (the default model
// of real walkers), or an opened .ewm by file name or path (a path not opened yet is read).
// Every walker is then inspected against it. Throws std::invalid_argument with the reason.
void setModelSource(AppState& s, const std::string& which);

// [SECTION] Keypoint clips (ui/app/clip.h, docs/VIEWER.md "Keypoint clips")
// True for what openClip takes: an OpenPose folder, a keypoint JSON, a MediaPipe / DLC CSV.
bool isKeypointClip(const std::filesystem::path& path);
// Opens a pose estimator's clip in Mode::Clip; its camera fit runs in the background. A clip
// that cannot be read or fitted is reported as a failed open, and what was shown stays.
void openClip(AppState& s, const std::filesystem::path& path);
// The clip fit's choices, each refitting in the background; nullopt / "" / 0 / -1: estimated,
// guessed, the file's or 30 fps, the walker. Throw std::invalid_argument for values out of range.
void setClipFocal(AppState& s, std::optional<double> focalPx);
void setClipAzimuth(AppState& s, std::optional<double> alphaDeg);
void setClipElevation(AppState& s, std::optional<double> elevationDeg);
void setClipLayout(AppState& s, const std::string& layout);
void setClipFps(AppState& s, double fps);
void setClipPerson(AppState& s, int person);
// The image's size in pixels (nullopt: the file's, else the video's beside it); a clip whose
// points are fractions of the image opens without one and waits for it.
void setClipImageSize(AppState& s, std::optional<KeypointImageSize> size);
void closeClip(AppState& s);
// Shows the clip's frame `frame` (from 1, as the 2D view's caption counts) and pauses.
void setClipFrame(AppState& s, int frame);

// [SECTION] Video (ui/app/video.h, docs/VIEWER.md "Video")
// Opens a video in Mode::Clip (closing the video and clip shown before): its frames show in
// the 2D view. Error (std::invalid_argument with the file and reason) when it cannot be read.
void openVideo(AppState& s, const std::filesystem::path& path);
// Reads a keyframe file (core/tracking/keyframes.h) into the open video's keyframes (one
// edit: undo takes it back). Throws when no video is open or the file is bad.
void loadKeyframes(AppState& s, const std::filesystem::path& path);
void saveKeyframes(AppState& s, const std::filesystem::path& path);
// The open video's keyframes into `dir` (made when missing) as <video name>_keyframes.json,
// the name saveTrack gives them beside a track.
void saveKeyframesInto(AppState& s, const std::filesystem::path& dir);
// The open video's last track into `dir` (video/track_files.h: OpenPose JSON, the 2D CSV, the
// confidences) with the keyframes it was tracked from beside them (DIR/<video>_keyframes.json).
// Throws when there is no track or a file cannot be written.
void saveTrack(AppState& s, const std::filesystem::path& dir);
// The open video's next keyframe after the frame shown (delta > 0) or the one before it
// (delta < 0); -1 when there is none that way.
int neighbouringKeyframe(const AppState& s, int delta);
// The tracked frame that is no keyframe where the track's mean confidence over the joints is
// lowest: where to look first for joints that strayed (-1 when there is no track, or every
// tracked frame is a keyframe).
int leastSureTrackedFrame(const AppState& s);
// The frame to mark next, no keyframe: the one that, marked, leaves the least of the joints'
// motion between each tracked frame and its nearest keyframe (framesToMarkNext,
// core/tracking/track_confidence.h); -1 when there is no track or nothing moved.
int nextFrameToMark(const AppState& s);
// Where the viewer offers to save the open video's keyframes and track: <video name>_track.
std::filesystem::path defaultTrackFolder(const AppState& s);
// The video's 2D view magnified `zoom` times (clamped to 1-16; 1 shows the whole picture) with
// the video pixel `centrePx` (x right, y down; kept on the picture) at its middle.
void setVideoZoom(AppState& s, double zoom, const Eigen::Vector2d& centrePx);
// The keypoint clip's 2D view magnified `zoom` times (clamped to 1-16; 1 shows the region the
// walker crosses) with the image pixel `centrePx` (x right, y down) at its middle.
void setClipZoom(AppState& s, double zoom, const Eigen::Vector2d& centrePx);
// The frame shown (0-based, clamped to the video); pauses a tracked clip's playback there.
void setVideoFrame(AppState& s, int frame);
// Guided marking on the frame shown: clicks place the joint asked for, then the next.
void startMarking(AppState& s);
void stopMarking(AppState& s);
void skipMarkedJoint(AppState& s);  // the joint asked for is not visible: ask for the next
// Places (or moves) a joint on the frame shown, in video pixels (x right, y down). A frame
// that is no keyframe yet becomes one, starting from the track's confident joints there.
// `newEdit` false: part of the edit before (a drag), not a step of its own for undo.
void markJoint(AppState& s, Joint joint, double xPx, double yPx, bool newEdit = true);
// A joint dragged (markJoint) and let go: on a tracked video, while not marking, the track is
// redone from the keyframes as they now are (issue 14: "drag a joint on any frame, it becomes a
// keyframe and the track is redone around it"); on a detected one, the detections are fitted
// again with the keyframes as corrections (issue 52). True when tracking or the fit started.
bool letGoOfJoint(AppState& s);
// Marks the frame shown with a pose estimator's detections on that frame (a keypoint file or
// folder, core/keypoints: OpenPose, AlphaPose, MMPose, CSV; the file's first frame is the
// video's first): the joints it found, replacing what was marked there, as one edit. Throws,
// naming the file, when it does not read or has no joint on that frame.
void markFromKeypoints(AppState& s, const std::filesystem::path& keypoints);
void removeKeyframe(AppState& s, int frame);
void undoKeyframes(AppState& s);
void redoKeyframes(AppState& s);
// The frames to track, inclusive (0-based; last -1: the video's end).
void setTrackRange(AppState& s, int first, int last);
// Which tracker the next track uses (optical flow, or Zou et al.'s appearance tracker).
void setTracker(AppState& s, TrackerKind tracker);
// Whether the next optical-flow track flattens a fixed camera's still background first
// (video/static_background.h).
void setFlattenBackground(AppState& s, bool flatten);
// The next flow track holds the shoulders and hips to the trunk (TrackerOptions::holdTheTrunk).
void setHoldTheTrunk(AppState& s, bool hold);
// Rounds of the model loop the next flow track runs (0-10; std::invalid_argument outside).
void setModelLoopRounds(AppState& s, int rounds);
// The model a clip is fitted with, and the model loop guides a track with (throws when none).
std::shared_ptr<const EigenwalkerModel> modelForTracking(AppState& s);
// Tracks the range from the keyframes on a worker; when done the track is fitted as a clip.
void startTracking(AppState& s);
void cancelTracking(AppState& s);
void closeVideo(AppState& s);
// The video frame the 2D view shows: the fitted clip's playback frame (its track's or its
// detections'), else the scrubbed one.
int shownVideoFrame(const AppState& s);
// The clip shown is the fit of the open video's last track.
bool showsTrackFit(const AppState& s);
// The clip shown is the fit of the open video's last detection.
bool showsDetectionFit(const AppState& s);
// Either: the open video's footage goes under the clip's fit.
bool showsVideoFit(const AppState& s);
// The video frames [first, last] the fitted clip covers (showsVideoFit), else nullopt.
std::optional<std::pair<int, int>> videoFitFrames(const AppState& s);

// [SECTION] Detecting the walker (ui/app/detection.h, docs/VIEWER.md "Detecting the walker")
// Finds the people in the open video with the built-in detector on a worker, through the
// detection cache; the 2D view draws each frame's people as they are found. When done, the
// walker's keypoints are fitted as a keypoint clip with the video (the fit over its footage);
// a video with nobody in it is reported. Throws std::invalid_argument when no video is open, a
// detection or a track is running, or the models are missing (missingPoseModelAdvice()).
void startDetection(AppState& s);
void cancelDetection(AppState& s);
// Which BlazePose landmark model the next detection uses (lite, full, heavy).
void setDetectorModel(AppState& s, PoseModelSize model);
// The last detection's keypoints fitted again as the clip (after a track took its place), the
// video's keyframes as corrections of them (ClipSettings::corrections).
void fitDetections(AppState& s);
// The open video's keyframes are corrections of its detections (issue 52: "marking and
// tracking become correction"): people were detected and no track replaced them. Then each
// edit of the keyframes outside guided marking (a joint let go, undo, redo, a keyframe
// removed or read, marking done) fits the detections again with them.
bool correctsDetections(const AppState& s);
// The open video's people found on `frame`: the running detection's, else the last one's.
std::vector<KeypointDetection> detectionsOn(const AppState& s, int frame);
// Whether a video opened alone (no keyframe file with it) is handed to the detector.
void setDetectWhenVideoOpens(AppState& s, bool detect);
// One frame on (delta > 0) or back, of what the views show: the video's own frames while its
// joints are marked or before it is tracked, the clip's frames (round its ends, as playback
// loops), else 1/60 s of the synthesised walker's cycle. Pauses a clip or video.
void stepFrame(AppState& s, int delta);
// True while the transport plays and steps the open video's own frames: its joints are being
// marked, or it has no track yet.
bool stepsVideoFrames(const AppState& s);
// Playback moves on by `seconds` × its speed: the video's own frames at its frame rate
// (stepsVideoFrames; round its end, as a walker's cycle loops), else the walker's cycle.
void advancePlayback(AppState& s, double seconds);
// The time one stepFrame moves, in seconds.
double frameStepS(const AppState& s);

// Number of coefficient sliders in the current mode (0 when nothing is loaded).
int coefficientCount(const AppState& s);
// The stride frequency driving playback (selected walker, or the population mean).
double playbackStrideHz(const AppState& s);

}  // namespace ew::ui::actions
