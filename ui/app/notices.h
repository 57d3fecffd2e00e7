#pragma once
// What the user is told went wrong (docs/VIEWER.md, "Opening data": the notice row): the banner
// over the views, the last error, and how many opens, model builds and fits failed. Every
// feature that can fail reports through it (ui/app/notice_actions.h); the banner is drawn by
// ui/panels/notice_panel.h. The feature's whole state is Notices (AppState::notices).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ew::ui {

// What the banner over the views says after an open went wrong (ui/panels/notice_panel.h):
// an open that failed (the previous data stays), or one that succeeded without some of the
// items the user named.
struct OpenNotice {
  bool error = true;     // false: opened, but some items were skipped
  std::string title;     // "Could not open walk.csv"
  std::string detail;    // why: the file, where in it, the problem (the opened paths shortened)
  std::string fullText;  // the same with full paths, as in the log (the banner's tooltip)
  std::string kept;      // what the viewer still shows
  std::vector<std::filesystem::path> retryPaths;  // what Retry opens
  bool canRetry = false;
  std::uint64_t serial = 0;  // a new notice comes to the front once
  std::string shortTitle;    // for a row too narrow for the title ("Doubtful camera fit")
};

struct Notices {
  std::optional<OpenNotice> banner;  // the banner over the views, until dismissed
  std::uint64_t serial = 0;          // the last banner's (each new one comes to the front once)
  std::string lastError;  // the last failed open, model build or fit ("" once dismissed or opened)
  int failures = 0;       // opens, model builds and fits that failed (scripts check it)
};

}  // namespace ew::ui
