#pragma once
// Gait report window (issue 17): the selected walker's gait measures — cadence, stride,
// steps, width, speed, stance, swing, double support, flexion ranges — for its motion capture
// (its own Fourier fit) and its reconstruction by the current engine (or, in explore mode, the
// synthesised walker), beside the loaded population's mean ± SD; and the hip, knee, shoulder
// and elbow flexion over the gait cycle with the population's band. Exports CSV, JSON, and the
// reconstruction as TRC + MOT for OpenSim. The numbers: ui/app/gait_report.h.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "ui/app/gait_report.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct GaitPanel {
  bool open = false;
  bool leftSide = false;  // the curves of the left side instead of the right
  std::array<char, 512> basePath{"gait_report"};
  std::string status;

  // Cached: the band per population generation and model held, the summaries per walker shown.
  std::tuple<std::uint64_t, int, const void*, std::string> bandKey;
  std::shared_ptr<const GaitBand> band;
  Eigen::VectorXd mocapW;
  GaitSummary mocap;
  // The reconstruction's column, or one per engine in compare mode.
  struct Column {
    std::string name;   // the export's column: "reconstruction", or the engine's name
    std::string label;  // the table's header
    int engine = -1;    // kEngineKinds index in compare mode (its colour); -1: the amber
    Eigen::VectorXd w;
    GaitSummary summary;
  };
  std::vector<Column> columns;
  // The column of the engine the viewer has selected (the first when none is it).
  const GaitSummary& recon() const;
  std::vector<GaitColumn> exportColumns() const;
  void updateBand(const AppState& s);

  void draw(AppState& s, const FrameContext& ctx);
  // Brings the caches up to date with what the viewer shows (also used by the scripts).
  void update(AppState& s);
};

}  // namespace ew::ui
