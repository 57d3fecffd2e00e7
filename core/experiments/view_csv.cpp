#include "core/experiments/view_csv.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/io/atomic_write.h"
#include "core/io/reader_limits.h"

namespace ew {
namespace {

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
    while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
    cells.push_back(cell);
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double cellValue(const std::string& cell, const std::string& name, int lineNo) {
  if (cell.empty() || cell == "nan" || cell == "NaN") return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size()) throwMalformed(name, "line " + std::to_string(lineNo), "'" + cell + "' is not a number");
  return v;
}

bool plausibleRate(double rateHz) {
  return std::isfinite(rateHz) && rateHz >= kMinFrameRateHz && rateHz <= kMaxFrameRateHz;
}

std::string rateRange() {
  std::ostringstream s;
  s << kMinFrameRateHz << "-" << kMaxFrameRateHz << " Hz";
  return s.str();
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string viewCsvHeader() {
  std::string h = "frame,time_s";
  for (const auto& j : kJointNames) h += "," + std::string(j) + "_u," + std::string(j) + "_v";
  return h;
}

bool looksLikeViewCsv(std::string_view text) {
  std::istringstream in{std::string(text.substr(0, 4096))};
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    return line.rfind("frame,time_s,head_u", 0) == 0;
  }
  return false;
}

ViewSequence parseViewCsv(std::string_view text, const std::string& name) {
  std::istringstream in{std::string(text)};
  std::string line;
  int lineNo = 0;
  bool header = false;
  double rateHz = 0.0;
  int rateLine = 0;
  std::vector<double> times;
  std::vector<int> rowLines;
  std::vector<std::vector<double>> rows;
  const std::string expected = viewCsvHeader();
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line[0] == '#') {
      const auto at = line.find("rate_hz=");
      if (at != std::string::npos) {
        rateHz = cellValue(line.substr(at + 8), name, lineNo);
        rateLine = lineNo;
      }
      continue;
    }
    if (!header) {
      if (line != expected) throwMalformed(name, "line " + std::to_string(lineNo), "expected the 2D header '" + expected.substr(0, 40) + "…' (docs/EXPERIMENTS.md)");
      header = true;
      continue;
    }
    const auto cells = splitCells(line);
    if (cells.size() != 2 + kDims2) {
      throwMalformed(name, "line " + std::to_string(lineNo),
                     "expected " + std::to_string(2 + kDims2) + " cells, got " + std::to_string(cells.size()));
    }
    times.push_back(cellValue(cells[1], name, lineNo));
    rowLines.push_back(lineNo);
    std::vector<double> row;
    for (int c = 0; c < kDims2; ++c) row.push_back(cellValue(cells[static_cast<size_t>(2 + c)], name, lineNo));
    rows.push_back(std::move(row));
  }
  if (!header) throwMalformed(name, "line 1", "no 2D header (frame,time_s,head_u,head_v,…)");
  if (rows.size() < 2) throwBadData(name, "", "fewer than 2 frames");
  if (rateLine > 0 && !plausibleRate(rateHz)) {
    throwMalformed(name, "line " + std::to_string(rateLine),
                   "rate_hz=" + number(rateHz) + " is outside the plausible " + rateRange());
  }
  if (rateLine == 0) {
    // The rate comes from the time column: every time must be there (a NaN would also
    // break the ordering nth_element needs).
    for (size_t i = 0; i < times.size(); ++i) {
      if (!std::isfinite(times[i]))
        throwBadData(name, "line " + std::to_string(rowLines[i]),
                     "time_s is missing; fill the time column or add '# rate_hz=R'");
    }
    std::vector<double> dt;
    for (size_t i = 1; i < times.size(); ++i) dt.push_back(times[i] - times[i - 1]);
    std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
    const double median = dt[dt.size() / 2];
    if (!(median > 0)) throwBadData(name, "time_s", "time does not increase; add '# rate_hz=R'");
    rateHz = 1.0 / median;
    if (!plausibleRate(rateHz)) {
      throwBadData(name, "time_s",
                   "the times give a frame rate of " + number(rateHz) +
                       " Hz, outside the plausible " + rateRange() +
                       " (times in milliseconds?); add '# rate_hz=R'");
    }
  }
  ViewSequence s{Eigen::MatrixXd(static_cast<Eigen::Index>(rows.size()), kDims2), rateHz};
  for (size_t i = 0; i < rows.size(); ++i) {
    for (int c = 0; c < kDims2; ++c) s.framesMm(static_cast<Eigen::Index>(i), c) = rows[i][static_cast<size_t>(c)];
  }
  return s;
}

ViewSequence readViewCsv(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, file.string(), "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseViewCsv(text.str(), file.string());
}

void writeViewCsv(const std::filesystem::path& file, const ViewSequence& s,
                  const std::vector<std::string>& commentLines) {
  if (s.framesMm.cols() != kDims2 || !(s.rateHz > 0) || !std::isfinite(s.rateHz)) {
    throw Error(ErrorKind::BadArgument, file.string(), "", "a 2D sequence needs T × 30 frames and a positive rate");
  }
  writeFileAtomically(file, [&](std::ostream& out) {
    for (const auto& c : commentLines) out << "# " << c << '\n';
    out << "# rate_hz=" << s.rateHz << '\n' << viewCsvHeader() << '\n';
    out.precision(10);
    for (Eigen::Index i = 0; i < s.framesMm.rows(); ++i) {
      out << i << ',' << static_cast<double>(i) / s.rateHz;
      for (int c = 0; c < kDims2; ++c) {
        const double v = s.framesMm(i, c);
        out << ',';
        if (std::isfinite(v)) out << v;
      }
      out << '\n';
    }
  });
}

}  // namespace ew
