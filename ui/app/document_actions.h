#pragma once
// Document edits and view state (document_actions.cpp): the walker, the parameters, the explorer,
// playback, overlays, the camera.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <string>
#include <vector>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

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

// Number of coefficient sliders in the current mode (0 when nothing is loaded).
int coefficientCount(const AppState& s);
// The stride frequency driving playback (selected walker, or the population mean).
double playbackStrideHz(const AppState& s);

}  // namespace ew::ui::actions
