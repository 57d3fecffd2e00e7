// Teaching: theme, presentation mode, the guided tour, floating panels.
#include "ui/app/teaching_actions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"
#include "ui/app/script.h"
#include "ui/app/theme.h"
#include "ui/app/tour.h"

namespace ew::ui::actions {

// [SECTION] Teaching

void setTheme(AppState& s, const std::string& name) { s.view.theme = themeFromName(name); }

void setPresentation(AppState& s, bool on) {
  if (s.view.presentation != on) s.log.info(on ? "Presentation mode (F5 or Esc to leave)" : "Presentation mode ended");
  s.view.presentation = on;
}

namespace {

void applyTourStep(AppState& s) {
  const auto& steps = tourSteps();
  const auto& step = steps[static_cast<std::size_t>(s.panels.tour.step)];
  const auto script =
      parseScript(nlohmann::json::parse(step.actionsJson), std::string("tour step ") + step.title);
  // A step's action the data cannot do (no semantic speed axis in a population that has no
  // steerable one) is a warning: the tour goes on with the rest of the step.
  for (const auto& a : script) {
    try {
      applyAction(s, a);
    } catch (const std::exception& e) {
      s.log.warning(std::string("tour step ") + step.title + ": " + a.name + ": " + e.what());
    }
  }
  s.log.info(std::string("Tour ") + std::to_string(s.panels.tour.step + 1) + "/" +
             std::to_string(steps.size()) + ": " + step.title);
}

}  // namespace

void tourStart(AppState& s) {
  requireLoaded(s);
  s.panels.tour.active = true;
  s.panels.tour.step = 0;
  applyTourStep(s);
}

void tourNext(AppState& s) {
  if (!s.panels.tour.active) throw std::invalid_argument("the tour has not started");
  if (s.panels.tour.step + 1 >= static_cast<int>(tourSteps().size())) {
    tourEnd(s);
    return;
  }
  ++s.panels.tour.step;
  applyTourStep(s);
}

void tourBack(AppState& s) {
  if (!s.panels.tour.active) throw std::invalid_argument("the tour has not started");
  if (s.panels.tour.step == 0) return;
  --s.panels.tour.step;
  applyTourStep(s);
}

void tourEnd(AppState& s) {
  if (s.panels.tour.active) s.log.info("Tour ended");
  s.panels.tour.active = false;
  s.panels.tour.step = 0;
  s.view.overlays.pointLights = false;
  s.panels.analysis.open = false;
}

void showPanel(AppState& s, const std::string& name, bool shown) {
  if (name == "export") {
    s.panels.exports.open = shown;
  } else if (name == "analysis") {
    s.panels.analysis.open = shown;
  } else if (name == "gait") {
    s.panels.gait.open = shown;
  } else if (name == "help") {
    s.panels.help.open = shown;
  } else if (name == "data") {
    s.panels.data.open = shown;
  } else if (name == "notice_details") {
    if (shown && !s.panels.notice.visible(s))
      throw std::invalid_argument("no notice to show the details of");
    s.panels.notice.detailsOpen = shown;
  } else if (name == "quiz") {
    s.quiz.open = shown;
  } else if (name == "model") {
    s.panels.header.modelMenuOpen = shown;
  } else {
    throw std::invalid_argument("unknown panel \"" + name +
                                "\" (known: export, analysis, gait, help, data, notice_details, model, quiz)");
  }
}

}  // namespace ew::ui::actions
