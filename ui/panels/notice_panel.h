#pragma once
// The notice row under the header: what went wrong (an open that failed — the previous data
// stays —, an open that skipped some items, a failed export or reconstruction) as a short
// reason on one line, with Details (the full message, one click away), Retry and Dismiss
// always on screen at its right end. The row has its own place in the layout
// (ui/app/layout.h), so it never covers the views or their titles, at any window size. In
// amber when an open succeeded but skipped some of the items. The same message is in the log.

#include <cstdint>
#include <optional>
#include <string>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

// What the row shows: the open notice first, then an export error, then a failed
// reconstruction.
struct NoticeView {
  enum class Kind { Open, Export, Reconstruction };
  Kind kind = Kind::Open;
  bool error = true;
  std::string title;     // "Could not open walk.csv"
  std::string detail;    // the full reason (paths shortened)
  std::string fullText;  // with full paths (the log's text)
  std::string kept;      // what the viewer still shows
  bool canRetry = false;
  std::uint64_t serial = 0;
  std::string shortTitle;  // shown where the title does not fit ("" : "Error" or "Warning")
};

// The first clause of a message, for one line: its first line, without a leading
// "file.csv: " (the title names the file), up to the first "; ", " (" or ". ".
std::string shortReason(const std::string& message);

struct NoticePanel {
  std::uint64_t frontSerial = 0;    // the notice whose details were last brought to the front
  bool detailsOpen = false;         // the details window
  std::string dismissedReconError;  // a reconstruction error the user dismissed

  std::optional<NoticeView> current(const AppState& s) const;
  bool visible(const AppState& s) const { return current(s).has_value(); }
  // `row`: the layout's notice row.
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& row);
  // The details window (Details…, or the script's show_panel ["notice_details", true]).
  void drawDetails(AppState& s, const FrameContext& ctx);

 private:
  void apply(AppState& s, const NoticeView& n, const std::string& clicked);
};

}  // namespace ew::ui
