#include "core/io/joint_csv.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/common/errors.h"
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/reader_limits.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

constexpr std::string_view kAxes = "xyz";

std::vector<std::string> expectedColumns() {
  std::vector<std::string> cols = {"frame", "time_s"};
  for (auto name : kJointNames) {
    for (char axis : kAxes) cols.push_back(std::string(name) + "_" + axis);
  }
  return cols;
}

struct CsvDirectives {
  std::optional<double> rateHz;
  std::optional<std::string> units;
};

// "# rate_hz=120" and "# units=m" comment lines.
void readDirective(std::string_view comment, CsvDirectives& directives) {
  comment = trim(comment.substr(1));
  auto eq = comment.find('=');
  if (eq == std::string_view::npos) return;
  auto key = toLower(trim(comment.substr(0, eq)));
  auto value = trim(comment.substr(eq + 1));
  double number = 0;
  if (key == "rate_hz" && parseDouble(value, number, false)) directives.rateHz = number;
  if (key == "units") directives.units = std::string(value);
}

void checkHeader(const TextLine& line, const std::string& name) {
  auto fields = splitFields(line.text, ',');
  auto expected = expectedColumns();
  if (fields.size() != expected.size()) {
    throwMalformed(name, linePosition(line.number),
                   "header has " + std::to_string(fields.size()) + " columns, expected " +
                       std::to_string(expected.size()) + " (frame,time_s,head_x,…,l_ankle_z)");
  }
  for (size_t i = 0; i < expected.size(); ++i) {
    if (toLower(fields[i]) != expected[i]) {
      throwMalformed(name, linePosition(line.number, static_cast<int>(i + 1)),
                     "column '" + std::string(fields[i]) + "', expected '" + expected[i] + "'");
    }
  }
}

// Frame rate from the time column: the median step is robust to a dropped frame.
double rateFromTimes(const std::vector<double>& times, const std::string& name) {
  std::vector<double> steps;
  for (size_t i = 1; i < times.size(); ++i) steps.push_back(times[i] - times[i - 1]);
  if (steps.empty()) throwBadData(name, "", "one frame only: cannot tell the frame rate");
  std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
  double step = steps[steps.size() / 2];
  if (!(step > 0)) throwMalformed(name, "column time_s", "time does not increase");
  return 1.0 / step;
}

}  // namespace

std::string jointCsvHeader() {
  std::string header;
  for (const auto& col : expectedColumns()) header += (header.empty() ? "" : ",") + col;
  return header;
}

bool looksLikeJointCsv(std::string_view text) {
  for (const auto& line : splitLines(text.substr(0, 8192))) {
    auto t = trim(line.text);
    if (t.empty() || t.front() == '#') continue;
    return toLower(t).rfind("frame,time_s,head_x", 0) == 0;
  }
  return false;
}

RawTrial parseJointCsv(std::string_view text, const std::string& name, const LoadOptions& options) {
  auto lines = splitLines(text);
  CsvDirectives directives;
  size_t i = 0;
  for (; i < lines.size(); ++i) {
    auto t = trim(lines[i].text);
    if (t.empty()) continue;
    if (t.front() != '#') break;
    readDirective(t, directives);
  }
  if (i == lines.size()) throwMalformed(name, "", "empty file: no header line");
  checkHeader(lines[i], name);
  const size_t columns = expectedColumns().size();
  // Every line after the header may be a frame: bound them before storing any.
  checkPointFrames(static_cast<double>(lines.size() - i - 1), kJointCount, kMaxPointFrames, name, "");
  std::vector<double> values;
  std::vector<double> times;
  for (++i; i < lines.size(); ++i) {
    auto t = trim(lines[i].text);
    if (t.empty() || t.front() == '#') continue;
    auto fields = splitFields(t, ',');
    if (fields.size() != columns) {
      throwMalformed(name, linePosition(lines[i].number),
                     std::to_string(fields.size()) + " fields, expected " + std::to_string(columns));
    }
    for (size_t c = 0; c < columns; ++c) {
      double v = 0;
      if (!parseDouble(fields[c], v, c >= 2)) {
        throwMalformed(name, linePosition(lines[i].number, static_cast<int>(c + 1)),
                       "not a number: '" + std::string(fields[c].substr(0, 40)) + "'");
      }
      if (c == 1) times.push_back(v);
      if (c >= 2) values.push_back(v);
    }
  }
  RawTrial raw;
  raw.file = name;
  raw.format = "CSV";
  raw.kind = PointKind::CanonicalJoints;
  raw.labels.assign(kJointNames.begin(), kJointNames.end());
  raw.upAxis = SignedAxis{2, 1};
  const auto frames = static_cast<Eigen::Index>(times.size());
  if (frames == 0) throwBadData(name, "", "no data rows after the header");
  if (options.rateHzOverride) {
    raw.rateHz = checkedRateOverrideHz(*options.rateHzOverride, name);
  } else if (directives.rateHz) {
    raw.rateHz = checkedFileRateHz(*directives.rateHz, name, "# rate_hz");
  } else {
    raw.rateHz = checkedFileRateHz(rateFromTimes(times, name), name, "column time_s");
  }
  raw.units = options.unitsOverride.value_or(directives.units.value_or("mm"));
  const double scale = unitToMm(raw.units, name);
  raw.positionsMm = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
                        values.data(), frames, kDims3) * scale;
  return raw;
}

RawTrial readJointCsv(const std::filesystem::path& file, const LoadOptions& options) {
  return parseJointCsv(readFileText(file), file.string(), options);
}

void writeJointCsv(const std::filesystem::path& file, const Eigen::MatrixXd& framesX45,
                   double rateHz, const std::vector<std::string>& commentLines) {
  if (framesX45.cols() != kDims3) {
    throw Error(ErrorKind::BadArgument, file.string(), "",
                "expected 45 columns, got " + std::to_string(framesX45.cols()));
  }
  if (!(rateHz > 0)) throw Error(ErrorKind::BadArgument, file.string(), "", "frame rate must be > 0");
  writeFileAtomically(file, [&](std::ostream& out) {
    for (const auto& c : commentLines) out << "# " << c << "\n";
    out << "# rate_hz=" << std::setprecision(17) << rateHz << "\n";
    out << jointCsvHeader() << "\n";
    out << std::setprecision(10);
    for (Eigen::Index r = 0; r < framesX45.rows(); ++r) {
      out << r << ',' << static_cast<double>(r) / rateHz;
      for (Eigen::Index c = 0; c < kDims3; ++c) {
        double v = framesX45(r, c);
        out << ',';
        if (std::isfinite(v)) out << v;
      }
      out << '\n';
    }
  });
}

}  // namespace ew
