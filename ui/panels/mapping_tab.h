#pragma once
// The Data window's "Joint mapping" tab: a file the program cannot map (or maps wrongly)
// gets a table of its labels with a joint chosen per row — absent (estimated from the model),
// the suggestion of core's labelTable, or one of the file's labels — that writes a user
// mapping file (core/mapping/mapping_file.h, docs/FORMATS.md) and opens the file with it.

#include <array>
#include <string>
#include <vector>

#include "core/common/skeleton.h"
#include "core/mapping/mapping_file.h"
#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct MappingTab {
  std::array<char, 1024> file{};     // the trial whose labels are listed
  std::array<char, 1024> outPath{};  // where the mapping is written
  std::string readFile;              // the file `table` was read from
  LabelTable table;
  // Per joint: 0 = absent, 1 = the suggestion, 2 + i = table.labels[i].
  std::array<int, kJointCount> choice{};
  std::string status;
  bool statusIsError = false;

  void draw(AppState& s, const FrameContext& ctx);
  // What the buttons do (the script action write_joint_mapping uses them too): list `path`'s
  // labels with the suggestion chosen for every joint; write the chosen mapping to outPath
  // (and open the file with it). read reports a failure in `status`; write throws.
  void read(AppState& s, const std::string& path);
  void write(AppState& s, bool openNow);

 private:
  JointMapping mapping() const;
};

}  // namespace ew::ui
