#include "core/io/trc_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/reader_limits.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

struct TrcHeader {
  std::map<std::string, std::string> keys;  // lower-case key -> value
  int valuesLine = 0;                       // the line number of the values under DataRate, …
  size_t nameRow = 0;                       // index into lines of the "Frame#" row
};

TrcHeader readHeader(const std::vector<TextLine>& lines, const std::string& name) {
  TrcHeader header;
  for (size_t i = 0; i < lines.size() && i < 20; ++i) {
    auto fields = splitTabs(lines[i].text);
    if (fields.empty()) continue;
    auto first = toLower(fields[0]);
    if (first == "frame#" || first == "frame") {
      header.nameRow = i;
      return header;
    }
    if (first == "datarate" && i + 1 < lines.size()) {
      auto values = splitTabs(lines[i + 1].text);
      header.valuesLine = lines[i + 1].number;
      for (size_t k = 0; k < fields.size() && k < values.size(); ++k) {
        header.keys[toLower(fields[k])] = std::string(values[k]);
      }
    }
  }
  throwMalformed(name, "", "no 'Frame#' marker-name row in the first 20 lines: not a TRC file");
}

std::vector<std::string> markerNames(const TextLine& row, const std::string& name) {
  auto fields = splitFields(row.text, '\t');
  std::vector<std::string> labels;
  for (size_t k = 2; k < fields.size(); ++k) {
    if (!fields[k].empty()) labels.emplace_back(fields[k]);
  }
  if (labels.empty()) throwMalformed(name, linePosition(row.number), "no marker names");
  return labels;
}

std::string headerText(const TrcHeader& h, const std::string& key) {
  auto it = h.keys.find(key);
  return it == h.keys.end() ? std::string() : it->second.substr(0, 40);
}

double headerNumber(const TrcHeader& h, const std::string& key) {
  auto it = h.keys.find(key);
  double v = 0;
  if (it == h.keys.end() || !parseDouble(it->second, v, false)) return 0.0;
  return v;
}

// Data rows may omit trailing empty cells; any cell may be empty (a gap).
void readRows(const std::vector<TextLine>& lines, size_t first, size_t markers,
              const std::string& name, std::vector<double>& values, std::vector<double>& times) {
  const size_t columns = 2 + 3 * markers;
  for (size_t i = first; i < lines.size(); ++i) {
    if (trim(lines[i].text).empty()) continue;
    auto fields = splitFields(lines[i].text, '\t');
    if (fields.size() > columns + 1) {
      throwMalformed(name, linePosition(lines[i].number),
                     std::to_string(fields.size()) + " fields, more than the " +
                         std::to_string(columns) + " the header announces");
    }
    double t = 0;
    if (fields.size() < 2 || !parseDouble(fields[1], t, false)) {
      throwMalformed(name, linePosition(lines[i].number, 2), "missing or bad Time value");
    }
    times.push_back(t);
    for (size_t c = 2; c < columns; ++c) {
      double v = std::numeric_limits<double>::quiet_NaN();
      if (c < fields.size() && !parseDouble(fields[c], v, true)) {
        throwMalformed(name, linePosition(lines[i].number, static_cast<int>(c + 1)),
                       "not a number: '" + std::string(fields[c].substr(0, 40)) + "'");
      }
      values.push_back(v);
    }
  }
}

// NumFrames is checked, not trusted (the rows are the frames), and unlike NumMarkers a mismatch
// is refused, as the QTM reader refuses NO_OF_FRAMES': fewer rows is a file cut short (a copy or
// a write that stopped), more a header written for another take; either way one of the two lies.
void checkStatedFrames(const TrcHeader& h, size_t rows, const std::string& name) {
  const auto it = h.keys.find("numframes");
  double stated = 0;
  if (it == h.keys.end() || trim(it->second).empty() || !parseDouble(it->second, stated, false)) return;
  if (stated == static_cast<double>(rows)) return;
  throwMalformed(name, linePosition(h.valuesLine),
                 "NumFrames says " + headerText(h, "numframes") + " frames, the file holds " + std::to_string(rows) +
                     (static_cast<double>(rows) < stated ? " (cut short?)" : ""));
}

long firstFrameNumber(const std::vector<TextLine>& lines, size_t first) {
  for (size_t i = first; i < lines.size(); ++i) {
    auto fields = splitFields(lines[i].text, '\t');
    double frame = 1;
    if (fields.empty() || trim(lines[i].text).empty()) continue;
    if (parseDouble(fields[0], frame, false) && std::abs(frame) < 1e9) return static_cast<long>(frame);
    break;
  }
  return 1;
}

}  // namespace

RawTrial parseTrc(std::string_view text, const std::string& name, const LoadOptions& options) {
  auto lines = splitLines(text);
  if (lines.empty()) throwMalformed(name, "", "empty file");
  TrcHeader header = readHeader(lines, name);
  RawTrial raw;
  raw.file = name;
  raw.format = "TRC";
  raw.kind = PointKind::Markers;
  raw.labels = markerNames(lines[header.nameRow], name);
  // NumMarkers is only compared, never trusted: the name row says how many there are.
  const double announced = headerNumber(header, "nummarkers");
  if (announced != 0 && announced != static_cast<double>(raw.labels.size())) {
    raw.warnings.push_back("header says " + headerText(header, "nummarkers") +
                           " markers, name row has " + std::to_string(raw.labels.size()) +
                           ": using the name row");
  }
  const size_t dataLines = lines.size() > header.nameRow + 2 ? lines.size() - header.nameRow - 2 : 0;
  checkPointFrames(static_cast<double>(dataLines), static_cast<double>(raw.labels.size()),
                   kMaxPointFrames, name, "");
  std::vector<double> values, times;
  readRows(lines, header.nameRow + 2, raw.labels.size(), name, values, times);
  if (times.empty()) throwBadData(name, "", "no data rows");
  checkStatedFrames(header, times.size(), name);
  raw.rateHz = headerNumber(header, "datarate");
  if (options.rateHzOverride) {
    raw.rateHz = checkedRateOverrideHz(*options.rateHzOverride, name);
  } else if (header.keys.count("datarate") && raw.rateHz != 0) {
    raw.rateHz = checkedFileRateHz(raw.rateHz, name, "DataRate");
  } else if (times.size() > 1 && times[1] > times[0]) {
    raw.rateHz = checkedFileRateHz(1.0 / (times[1] - times[0]), name, "Time column");
    raw.warnings.push_back("no DataRate in header: rate taken from the Time column");
  } else {
    throwBadData(name, "", "no frame rate (DataRate missing, Time not increasing)");
  }
  auto units = header.keys.count("units") ? header.keys["units"] : std::string();
  if (units.empty() && !options.unitsOverride) raw.warnings.push_back("no Units in header: assuming mm");
  raw.units = options.unitsOverride.value_or(units.empty() ? "mm" : units);
  const double scale = unitToMm(raw.units, name);
  const auto frames = static_cast<Eigen::Index>(times.size());
  const auto cols = static_cast<Eigen::Index>(3 * raw.labels.size());
  raw.positionsMm =
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          values.data(), frames, cols) * scale;
  raw.firstFrame = firstFrameNumber(lines, header.nameRow + 2);
  // OpenSim's convention is Y up; other TRC writers differ, so the normaliser decides
  // from the data unless the labels are our own joints.
  if (std::equal(raw.labels.begin(), raw.labels.end(), kJointNames.begin(), kJointNames.end())) {
    raw.kind = PointKind::CanonicalJoints;
  }
  return raw;
}

RawTrial readTrc(const std::filesystem::path& file, const LoadOptions& options) {
  return parseTrc(readFileText(file), file.string(), options);
}

}  // namespace ew
