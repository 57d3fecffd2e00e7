#pragma once
// Exports (docs/VIEWER.md "Export"): PNG screenshots of the window or one view, a video of
// both views side by side rendered offscreen at exact gait phases, the reconstructed
// walker as 15-joint CSV and BVH, and the current leave-one-out model. Every file is
// written atomically (a temporary sibling, then a rename): a failed export never leaves
// a half-written target. The request / progress state lives in AppState::exports; the
// operations are in ui/app/actions.h.

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace ew::ui {

struct AppState;
class Renderer;

enum class CaptureView { Window, Input, Reconstruction };

// A PNG written from the next frames' framebuffer (after the UI settles).
struct PngRequest {
  std::filesystem::path path;
  CaptureView view = CaptureView::Window;
  int settleFrames = 2;
};

struct VideoSettings {
  std::filesystem::path path;  // .avi (MJPG) or .mp4 (mp4v, when OpenCV can write it)
  double cycles = 2.0;         // gait cycles of the displayed walker
  double fps = 30.0;
  int width = 1280, height = 720;  // the two views side by side, each width / 2 wide
  bool captions = true;            // each view's title, subtitle, metrics and legend burnt in
};

// Frames of a video: round(cycles · fps / strideHz), at least 1. Frame i shows the gait
// phase frac(i · strideHz / fps) (frame 0 at phase 0).
int videoFrameCount(double cycles, double fps, double strideHz);

// One video export in progress: the writer, the two offscreen targets, the frame counter.
class VideoExport {
 public:
  // Validates the settings and opens the writer on a temporary sibling of the path;
  // throws std::runtime_error (a clear message) when it cannot, e.g. no mp4v encoder.
  VideoExport(const VideoSettings& settings, double strideHz);
  ~VideoExport();  // an unfinished export removes its temporary file
  VideoExport(const VideoExport&) = delete;
  VideoExport& operator=(const VideoExport&) = delete;

  // Renders and encodes frames until budgetMs have passed or the last frame is written,
  // then renames the file into place. Returns true when finished. Throws on failure.
  bool step(const AppState& s, Renderer& renderer, double budgetMs);

  int frameCount() const;
  int framesDone() const;
  float fraction() const;
  const VideoSettings& settings() const;
  double seconds() const;  // wall time spent rendering and encoding so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct Exports {
  std::optional<PngRequest> png;
  std::unique_ptr<VideoExport> video;
  int failures = 0;        // failed PNG / video exports (scripts check it)
  std::string lastError;   // the last export error, shown in the header until dismissed
  bool busy() const { return png.has_value() || video != nullptr; }
};

// The displayed walker in the time domain: the reconstruction (edits included) in
// reconstruct mode, the synthesised walker in explore mode. T × 45 (METHOD §1 order, mm).
struct WalkerMotion {
  Eigen::MatrixXd framesX45;
  double rateHz = 120.0;
  double cycles = 0.0;
  std::string description;  // for the file's comment / the log
};

// Over `cycles` gait cycles; without it, over the held-out walker's trial duration
// (the cycles its fit covered, at least 1) in reconstruct mode, 4 cycles in explore mode.
// Throws std::invalid_argument when nothing is displayed yet.
WalkerMotion displayedWalkerMotion(const AppState& s, std::optional<double> cycles, double rateHz = 120.0);

}  // namespace ew::ui
