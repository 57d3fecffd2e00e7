#pragma once
// Our own 15-joint CSV format (documented in docs/FORMATS.md):
//   frame,time_s,head_x,head_y,head_z,sternum_x,…,l_ankle_z
// one row per frame, millimetres, METHOD §1 joint order and names, canonical axes of
// METHOD §2 when written by eigenwalker (x right, y forward, z up). Empty cell or "nan"
// = missing sample. Lines starting with '#' are comments; a comment
// "# rate_hz=120" or "# units=m" overrides what the time column implies / mm.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

RawTrial readJointCsv(const std::filesystem::path& file, const LoadOptions& options = {});
RawTrial parseJointCsv(std::string_view text, const std::string& name,
                       const LoadOptions& options = {});

// True when the first non-comment line is a 15-joint CSV header (3D).
bool looksLikeJointCsv(std::string_view text);

// Writes frames (T x 45, mm) at rateHz, atomically. Throws Error(BadArgument) on a
// shape mismatch and Error(Io) on a write failure.
void writeJointCsv(const std::filesystem::path& file, const Eigen::MatrixXd& framesX45,
                   double rateHz, const std::vector<std::string>& commentLines = {});

// The CSV header line (without newline) for 3D (xyz) joint columns.
std::string jointCsvHeader();

}  // namespace ew
