#pragma once
// Picks up a finished track (called by actions::pollJobs): a track that succeeded becomes the
// clip to fit; one that failed is reported, one cancelled is logged.

#include "ui/app/app_state.h"

namespace ew::ui {

void pollVideo(AppState& s);

}  // namespace ew::ui
