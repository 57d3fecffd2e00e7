#pragma once
// 2D joint sequences (an image-plane view of a walker), our CSV format:
//   frame,time_s,head_u,head_v,sternum_u,…,l_ankle_v
// one row per frame, millimetres (orthographic image coordinates: u horizontal, v up),
// METHOD §1 joint order. Empty cell or "nan" = missing sample. '#' lines are comments;
// "# rate_hz=R" sets the rate, else it is 1 / median(Δtime_s). See docs/EXPERIMENTS.md.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

struct ViewSequence {
  Eigen::MatrixXd framesMm;  // T × 30, joint-major u, v
  double rateHz = 0.0;
};

std::string viewCsvHeader();

// True when the first non-comment line is a 2D header (starts "frame,time_s,head_u").
bool looksLikeViewCsv(std::string_view text);

// Throws Error(Io) if unreadable, Error(Malformed) naming the file and line for a wrong
// header, a short row, a bad number or a rate_hz outside 1-10000 Hz (core/io/reader_limits.h),
// Error(BadData) for fewer than 2 frames, or — when the rate comes from the time column —
// a missing time, a non-increasing time column or an implausible rate.
ViewSequence readViewCsv(const std::filesystem::path& file);
ViewSequence parseViewCsv(std::string_view text, const std::string& name);

// Writes atomically.
void writeViewCsv(const std::filesystem::path& file, const ViewSequence& sequence,
                  const std::vector<std::string>& commentLines = {});

}  // namespace ew
