#pragma once
// Qualisys Track Manager's TSV export of 3D marker trajectories (`.tsv`). A header of
// tab-separated key and values, then one row a frame:
//   NO_OF_FRAMES    720
//   NO_OF_MARKERS   2
//   FREQUENCY       120
//   DATA_INCLUDED   3D
//   MARKER_NAMES    LASI  RASI
//   TRAJECTORY_TYPES  Measured  Measured           (newer QTM)
//   Frame  Time  LASI X  LASI Y  LASI Z  …         (when frame and time are exported)
//   1  0.00000  123.456  …
// Millimetres (QTM's unit; --units overrides). A marker QTM did not see is written as empty
// cells or as 0, 0, 0: both are gaps. Other header keys (cameras, analog, time stamp,
// description) are read past; EVENT lines are not read (a warning says so). A file of 6D
// rigid bodies, velocities or other data than 3D positions is refused, naming what it holds.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

RawTrial readQtmTsv(const std::filesystem::path& file, const LoadOptions& options = {});
RawTrial parseQtmTsv(std::string_view text, const std::string& name, const LoadOptions& options = {});

}  // namespace ew
