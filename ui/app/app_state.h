#pragma once
// Everything the viewer knows, in one place: the document, the view state, the derived
// caches, the background jobs, the log, and one struct per panel (each panel's own
// state lives in its struct, never in function-local statics).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/analysis.h"
#include "ui/app/background_job.h"
#include "ui/app/data_summary.h"
#include "ui/app/derived.h"
#include "ui/app/document.h"
#include "ui/app/export.h"
#include "ui/app/log.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/coefficients_panel.h"
#include "ui/panels/controls_panel.h"
#include "ui/panels/data_panel.h"
#include "ui/panels/export_panel.h"
#include "ui/panels/header_panel.h"
#include "ui/panels/help_panel.h"
#include "ui/panels/input_view_panel.h"
#include "ui/panels/joint_errors_panel.h"
#include "ui/panels/log_panel.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/playback_panel.h"
#include "ui/panels/profile_panel.h"
#include "ui/panels/reconstruction_view_panel.h"
#include "ui/panels/subjects_panel.h"
#include "ui/panels/tour_panel.h"

struct ImFont;

namespace ew::ui {

class Backdrop;
class Renderer;

struct Jobs {
  BackgroundJob<std::shared_ptr<const Population>> load;
  BackgroundJob<std::shared_ptr<const ModelSet>> models;
  BackgroundJob<std::shared_ptr<const AnalysisResult>> analysis;  // the analysis panel's curves
  BackgroundJob<std::shared_ptr<const DataSummary>> summary;      // the Data window's table
  AnalysisKey analysisRunning;            // the key of the running analysis job
  std::optional<AnalysisKey> analysisFailed;  // not retried until the inputs change
  std::string analysisError;
  // An open requested while a load was running: started when it finishes.
  std::optional<std::vector<std::filesystem::path>> pendingOpen;
  std::vector<std::filesystem::path> loadingPaths;
  std::string lastError;   // shown in the header until dismissed
  int failures = 0;        // loads or model builds that failed (scripts check it)

  bool busy() const {
    return load.running() || models.running() || analysis.running() || summary.running() ||
           pendingOpen.has_value();
  }
};

struct Fonts {
  ImFont* body = nullptr;
  ImFont* large = nullptr;   // metric values
  ImFont* small = nullptr;   // view annotations
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
  ExportPanel exports;
  AnalysisPanel analysis;
  TourPanel tour;
  DataPanel data;
  HelpPanel help;
};

struct AppState {
  // Loading, model building or an export under way (scripts wait for it).
  bool busy() const { return jobs.busy() || exports.busy(); }

  Document doc;
  ViewState view;
  Derived derived;
  Jobs jobs;
  Exports exports;
  AnalysisCache analysis;
  std::shared_ptr<const DataSummary> dataSummary;  // of the current generation, once computed
  Log log;
  Fonts fonts;
  Panels panels;
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
