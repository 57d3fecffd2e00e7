#pragma once
// Exports (export_actions.cpp): PNG, video, motion, model, the state JSON, the gait report.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <optional>
#include <string>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

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

// [SECTION] Gait report (ui/app/gait_report.h, ui/panels/gait_panel.h)
// By the extension: .csv or .json the report; .trc the reconstruction walked over the floor at
// its measured speed as an OpenSim marker file, and its joint angles beside it as .mot.
// Throws ew::Error naming the file, std::invalid_argument when there is nothing to export.
void exportGaitReport(AppState& s, const std::filesystem::path& path);

}  // namespace ew::ui::actions
