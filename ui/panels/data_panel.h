#pragma once
// File → Open and the data table: a folder browser (folders, then the files the viewer reads,
// filtered by format), recent files, and one row per trial of the opened data (like
// `eigenwalker-cli info`) with its warnings and a per-file unit / frame-rate override.
// Files and folders can also be dropped on the window (the same action as "drop").

#include <array>
#include <map>
#include <string>
#include <vector>

#include "ui/panels/mapping_tab.h"
#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

// The browser's format toggle that lists a file (.c3d, .bvh, .asf/.amc, .trc/.tsv, .csv, video,
// .json, .ewm: 0-7), or -1 for a file the viewer does not open.
int browserFormat(const std::string& fileName);

struct DataPanel {
  struct Entry {
    std::string name;
    bool folder = false;
  };
  struct OverrideEdit {
    int unit = 0;        // index into the unit list; 0 = the file's
    float rateHz = 0.0f; // 0 = the file's
  };

  bool open = false;
  std::array<char, 1024> folder{};  // the browser's folder (the working directory at first)
  std::string listedFolder;         // the folder `entries` lists
  std::vector<Entry> entries;
  std::string listError;
  std::map<std::string, bool> selected;  // file name in `folder` → ticked
  // c3d, bvh, asf/amc, trc/tsv, csv, video, json (keypoints, keyframes), ewm (models)
  std::array<bool, 8> formats{true, true, true, true, true, true, true, true};
  std::map<std::string, OverrideEdit> edits;  // by file path, until applied
  std::string status;
  MappingTab mapping;  // the "Joint mapping" tab

  void draw(AppState& s, const FrameContext& ctx);

 private:
  void refresh();
};

}  // namespace ew::ui
