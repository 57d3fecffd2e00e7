#include "ui/app/audience.h"

namespace ew::ui {

const char* audienceViewsName(AudienceViews v) {
  switch (v) {
    case AudienceViews::Input: return "input";
    case AudienceViews::Reconstruction: return "reconstruction";
    case AudienceViews::Both: break;
  }
  return "both";
}

const char* audienceThemeName(AudienceTheme t) { return t == AudienceTheme::Dark ? "dark" : "projector"; }

}  // namespace ew::ui
