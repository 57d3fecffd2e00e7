#pragma once
// TRC marker files (OpenSim / Motion Analysis): a tab-separated header
// (PathFileType…, then DataRate CameraRate NumFrames NumMarkers Units … keys and values),
// the marker-name row (Frame# Time M1 _ _ M2 …), the X1 Y1 Z1 row, then data rows.
// Tolerant of missing header keys: the rate falls back to the Time column, the marker
// count to the name row, the unit to mm (with a warning). Empty cells are missing (NaN).
// A NumFrames that is not the number of data rows is refused (Error(Malformed) naming the
// header's line: "cut short?" when the rows are fewer), as the QTM reader refuses NO_OF_FRAMES.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

RawTrial readTrc(const std::filesystem::path& file, const LoadOptions& options = {});
RawTrial parseTrc(std::string_view text, const std::string& name, const LoadOptions& options = {});

}  // namespace ew
