#pragma once
// The analysis panel's curves (analysis_actions.cpp), computed through jobs.analysis.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <memory>
#include <string>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

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

}  // namespace ew::ui::actions
