// Errors the user sees: the log, and the banner over the views (OpenNotice).
#include "ui/app/notice_actions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"
#include "ui/app/held_model.h"

namespace ew::ui::actions {

// [SECTION] Errors the user sees

// What the user still has after a failure.
std::string keptDescription(const AppState& s) {
  if (s.doc.walkerCount() == 0)
    return "Nothing is loaded: open other data, or the synthetic default population.";
  std::string kept = "Still showing ";
  if (s.doc.population) {
    kept += s.doc.population->label + " (" + std::to_string(s.doc.population->walkerCount()) +
            " walkers";
    if (s.doc.inspected)
      kept += " + " + std::to_string(s.doc.inspected->walkerCount()) + " inspected";
  } else {
    kept +=
        std::to_string(s.doc.walkerCount()) + " inspected walker(s) (model " + heldModelName(s.doc);
  }
  if (const Walker* w = s.doc.selectedWalker()) kept += ", " + w->subject + " selected";
  return kept + "): nothing you had open has changed.";
}

// The message with each opened path shortened to its file or folder name where it names it
// (the banner's title says where it was opened from; the log keeps the full paths).
std::string shortenPaths(std::string message, const std::vector<std::filesystem::path>& paths) {
  std::vector<std::filesystem::path> sorted = paths;
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& a, const auto& b) { return a.string().size() > b.string().size(); });
  for (const auto& p : sorted) {
    const std::string full = p.string();
    const std::string name = describePaths({p});
    if (full.empty() || full == name) continue;
    for (std::size_t at = message.find(full); at != std::string::npos;
         at = message.find(full, at)) {
      const std::size_t end = at + full.size();
      const bool whole = end == message.size() ||
                         std::string_view(":/ ,\n").find(message[end]) != std::string_view::npos;
      if (!whole) {
        at = end;
        continue;
      }
      message.replace(at, full.size(), name);
      at += name.size();
    }
  }
  return message;
}

void showNotice(AppState& s, OpenNotice notice) {
  notice.serial = ++s.notices.serial;
  s.notices.banner = std::move(notice);
}

std::string describePaths(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) return "the synthetic default population";
  std::vector<std::string> names;
  for (const auto& p : paths) {
    const auto name = p.filename().empty() ? p.parent_path().filename() : p.filename();
    names.push_back(name.empty() ? p.string() : name.string());
  }
  return listForMessage(names, 3);
}

void reportError(AppState& s, const std::string& title, const std::string& detail) {
  s.notices.lastError = detail.empty() ? title : title + ": " + detail;
  s.log.error(s.notices.lastError);
  OpenNotice n;
  n.title = title;
  n.detail = detail;
  n.fullText = s.notices.lastError;
  n.kept = keptDescription(s);
  showNotice(s, std::move(n));
}

void reportNote(AppState& s, const std::string& title, const std::string& detail, const std::string& shortTitle) {
  s.log.warning(detail.empty() ? title : title + ": " + detail);
  OpenNotice n;
  n.error = false;
  n.title = title;
  n.shortTitle = shortTitle;
  n.detail = n.fullText = detail;
  showNotice(s, std::move(n));
}

void reportOpenError(AppState& s, const std::vector<std::filesystem::path>& paths,
                     const std::string& message) {
  reportError(s, "Could not open " + describePaths(paths), message);
  s.notices.banner->detail = shortenPaths(message, paths);
  s.notices.banner->retryPaths = paths;
  s.notices.banner->canRetry = true;
}

void dismissNotice(AppState& s) {
  s.notices.banner.reset();
  s.notices.lastError.clear();
}

}  // namespace ew::ui::actions
