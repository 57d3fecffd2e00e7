#pragma once

#include <array>
// Everything the viewer knows, in one place: the document, the view state, the derived
// caches, the background jobs, the log, and one struct per panel (each panel's own
// state lives in its struct, never in function-local statics).

#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/analysis.h"
#include "ui/app/audience.h"
#include "ui/app/async_cache.h"
#include "ui/app/background_job.h"
#include "ui/app/clip.h"
#include "ui/app/data_summary.h"
#include "ui/app/derived.h"
#include "ui/app/document.h"
#include "ui/app/export.h"
#include "ui/app/loading.h"
#include "ui/app/log.h"
#include "ui/app/notices.h"
#include "ui/app/quiz.h"
#include "ui/app/stage.h"
#include "ui/app/undo.h"
#include "ui/app/video.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/coefficients_panel.h"
#include "ui/panels/controls_panel.h"
#include "ui/panels/data_panel.h"
#include "ui/panels/drawer_panel.h"
#include "ui/panels/export_panel.h"
#include "ui/panels/gait_panel.h"
#include "ui/panels/header_panel.h"
#include "ui/panels/help_panel.h"
#include "ui/panels/input_view_panel.h"
#include "ui/panels/joint_errors_panel.h"
#include "ui/panels/log_panel.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/notice_panel.h"
#include "ui/panels/playback_panel.h"
#include "ui/panels/presentation_bar.h"
#include "ui/panels/profile_panel.h"
#include "ui/panels/quiz_panel.h"
#include "ui/panels/reconstruction_view_panel.h"
#include "ui/panels/subjects_panel.h"
#include "ui/panels/tour_panel.h"

struct ImFont;

namespace ew::ui {

class Backdrop;
class Renderer;

struct Jobs {
  // Slow derived work, kept by the inputs it was computed from (ui/app/async_cache.h).
  AsyncCache<AnalysisKey, AnalysisResult> analysis{6};  // the analysis panel's curves
  AsyncCache<std::uint64_t, DataSummary> summary{1};    // the Data window's table, by generation

  bool busy() const { return analysis.running() || summary.running(); }
};

struct Fonts {
  ImFont* body = nullptr;
  ImFont* large = nullptr;   // metric values
  ImFont* small = nullptr;   // view annotations
};

// Presentation mode's text, this much larger than the workspace's, for a room to read.
inline constexpr float kPresentationTextScale = 1.4f;

// What the last frame laid out and which panels it drew (export_state reports it, so that
// tests see what is on screen without reading pixels).
struct FrameRecord {
  Layout layout;
  std::vector<std::string> drawn;  // "header", "input", "presentation_bar", …
  // Annotations the views drew and what they keep clear of: "input.walker" (the walker's
  // extent over the cycle), "input.legend", "input.caption", "reconstruction.…".
  std::vector<std::pair<std::string, PanelRect>> overlays;
  // Windows whose content is wider than they are (text or widgets cut at the edge), by how
  // many pixels; none in a layout that holds.
  std::vector<std::pair<std::string, float>> overflow;
  void overlay(std::string name, const PanelRect& r) { overlays.emplace_back(std::move(name), r); }
};

struct Panels {
  HeaderPanel header;
  SubjectsPanel subjects;
  ControlsPanel controls;
  PlaybackPanel playback;
  InputViewPanel input;
  ReconstructionViewPanel reconstruction;
  CoefficientsPanel coefficients;
  MetricsPanel metrics;
  JointErrorsPanel jointErrors;
  ProfilePanel profile;
  LogPanel log;
  NoticePanel notice;
  ExportPanel exports;
  AnalysisPanel analysis;
  GaitPanel gait;
  TourPanel tour;
  DataPanel data;
  HelpPanel help;
  DrawerPanel drawer;
  PresentationBar presentationBar;
  QuizPanel quiz;
};

struct AppState {
  // A background job running or an open waiting for one: loading, models, a clip's fit, a
  // track, a detection, the analysis, the data table.
  bool jobsBusy() const {
    return loading.busy() || clip.fits.running() || video.track.running() ||
           video.detect.running() || jobs.busy();
  }
  // That, an export, or video frames being read (scripts wait for it).
  bool busy() const {
    return jobsBusy() || exports.busy() ||
           (video.session && video.session->frames && video.session->frames->pending());
  }

  Document doc;
  ViewState view;
  ParameterHistory history;  // undo / redo of the parameters (ui/app/undo.h)
  Derived derived;
  // One struct per feature that has grown one (docs/ARCHITECTURE.md, "The viewer").
  LoadingFeature loading;  // opening data: the load, the models, the open waiting (loading.h)
  ClipFeature clip;        // the keypoint clip: its settings, its fits, its zoom (clip.h)
  VideoFeature video;      // the video open, its track and detection, the detector's choices
  Notices notices;         // what went wrong: the banner, the last error, the failures (notices.h)
  StageFeature stage;      // the classroom displays and the turning stage (stage.h)
  QuizFeature quiz;        // "which way is it walking?" (quiz.h)
  AudienceFeature audience;  // the second window, for the room (audience.h)
  Jobs jobs;               // the analysis's and the Data table's slow derived work
  Exports exports;
  Log log;
  Fonts fonts;
  Fonts presentationFonts;  // the same, kPresentationTextScale larger
  Panels panels;
  FrameRecord lastFrame;
  // The share of the window's pixels each of the last frames repainted (oldest first; 1 = all,
  // ui/render/compositor.h). export_state reports them: during playback only the views and
  // the playback row change, and a test checks that only they are repainted.
  static constexpr std::size_t kRepaintHistoryFrames = 120;
  std::deque<double> repaintedShares;
  // The pointer a script drives (its `mouse` action); a scripted run has no other.
  struct ScriptedPointer {
    bool present = false;          // over the window at (x, y), window pixels
    float x = 0.0f, y = 0.0f;
    std::array<bool, 3> down{};    // left, right, middle
    float wheel = 0.0f;            // notches, given to the next frame only
  } pointer;
  std::vector<std::filesystem::path> recentPaths;  // opened successfully, newest first (≤ 10)
  bool quitRequested = false;
  std::uint64_t frame = 0;
};

// What a panel needs besides the state to draw one frame.
struct FrameContext {
  Renderer& renderer;
  Backdrop& backdrop;  // what the panels draw beneath ImGui (window backgrounds, view images)
  float scale = 1.0f;   // UI scale × content scale (sizes in the panels multiply by it)
  double dtS = 0.0;
};

}  // namespace ew::ui
