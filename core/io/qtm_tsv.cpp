#include "core/io/qtm_tsv.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/marker_cells.h"
#include "core/io/reader_limits.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

// QTM's header keys: NO_OF_FRAMES, FREQUENCY, MARKER_NAMES, … (capitals, digits, underscores).
bool isHeaderKey(std::string_view field) {
  return !field.empty() && std::isupper(static_cast<unsigned char>(field.front())) &&
         std::all_of(field.begin(), field.end(), [](char c) {
           return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
         });
}

// A count a header states, as a message shows it: whole numbers in full, anything else
// (1e302, 2.5) as it reads; never cast to an integer it does not fit.
std::string statedCount(double v) {
  if (std::abs(v) < 1e15 && v == std::floor(v)) return std::to_string(static_cast<long long>(v));
  std::ostringstream out;
  out << v;
  return out.str();
}

std::vector<std::string_view> qtmFields(std::string_view line) {
  auto fields = splitFields(withoutBom(line), '\t');
  while (fields.size() > 1 && fields.back().empty()) fields.pop_back();  // a trailing tab
  return fields;
}

struct QtmHeader {
  std::optional<double> frames, markers, frequencyHz;
  std::string dataIncluded;
  std::vector<std::string> names;
  int namesLine = 0, lastLine = 0, events = 0;
  size_t dataStart = 0;  // the first line after the header
};

double qtmHeaderNumber(const std::vector<std::string_view>& fields, const TextLine& line, const std::string& name) {
  double v = 0;
  if (fields.size() < 2 || !parseFinite(fields[1], v))
    throwMalformed(name, linePosition(line.number), shownWord(fields[0]) + " is not followed by a number");
  return v;
}

QtmHeader readQtmHeader(const std::vector<TextLine>& lines, const std::string& name) {
  QtmHeader h;
  size_t i = 0;
  for (; i < lines.size(); ++i) {
    if (trim(lines[i].text).empty()) continue;
    const auto fields = qtmFields(lines[i].text);
    const std::string_view key = fields[0];
    if (!isHeaderKey(key)) break;
    h.lastLine = lines[i].number;
    if (key == "NO_OF_FRAMES") h.frames = qtmHeaderNumber(fields, lines[i], name);
    if (key == "NO_OF_MARKERS") h.markers = qtmHeaderNumber(fields, lines[i], name);
    if (key == "FREQUENCY") h.frequencyHz = qtmHeaderNumber(fields, lines[i], name);
    if (key == "DATA_INCLUDED" && fields.size() > 1) h.dataIncluded = std::string(fields[1]);
    if (key == "EVENT") ++h.events;
    if (key == "MARKER_NAMES") {
      h.namesLine = lines[i].number;
      for (size_t f = 1; f < fields.size(); ++f) {
        if (fields[f].empty() || std::find(h.names.begin(), h.names.end(), fields[f]) != h.names.end())
          throwMalformed(name, linePosition(h.namesLine, static_cast<int>(f + 1)),
                         fields[f].empty() ? "a marker without a name" : "marker " + shownWord(fields[f]) + " named twice");
        h.names.emplace_back(fields[f]);
      }
    }
  }
  h.dataStart = i;
  if (!h.dataIncluded.empty() && toLower(h.dataIncluded) != "3d")
    throwBadData(name, "", "a Qualisys export of " + shownWord(h.dataIncluded) +
                               " data, not 3D marker positions: export the 3D data (TSV) or a C3D");
  if (h.names.empty())
    throwBadData(name, "", "no MARKER_NAMES line: not a Qualisys Track Manager 3D export (.tsv)");
  if (h.markers && *h.markers != static_cast<double>(h.names.size()))
    throwMalformed(name, linePosition(h.namesLine),
                   std::to_string(h.names.size()) + " marker names, NO_OF_MARKERS says " +
                       statedCount(*h.markers));
  return h;
}

// How many columns come before the coordinates: a `Frame Time …` header row says so; without
// one the rows' width does (3 a marker, after the frame and the time when they are exported).
// A row ending in an empty cell may end in a gap or in a tab after its last value, so the
// width is read off a row that ends in a value; only when none does is a last empty cell
// taken for a trailing tab.
int qtmLeadingColumns(const std::vector<TextLine>& lines, size_t& at, size_t markers, const std::string& name) {
  while (at < lines.size() && trim(lines[at].text).empty()) ++at;
  if (at == lines.size()) throwBadData(name, "", "the header is followed by no frames");
  const auto first = qtmFields(lines[at].text);
  if (toLower(first[0]) == "frame") {
    ++at;
    return first.size() > 1 && toLower(first[1]) == "time" ? 2 : 1;
  }
  std::optional<size_t> width;
  for (size_t i = at; i < lines.size() && !width; ++i) {
    const auto raw = splitFields(lines[i].text, '\t');
    if (!trim(lines[i].text).empty() && !raw.back().empty()) width = raw.size();
  }
  if (!width) width = splitFields(lines[at].text, '\t').size() - 1;
  const size_t extra = *width >= 3 * markers ? *width - 3 * markers : 99;
  if (extra > 2)
    throwMalformed(name, linePosition(lines[at].number),
                   std::to_string(*width) + " fields for " + std::to_string(markers) +
                       " markers (3 a marker, after the frame and time when they are exported)");
  return static_cast<int>(extra);
}

}  // namespace

RawTrial parseQtmTsv(std::string_view text, const std::string& name, const LoadOptions& options) {
  const auto lines = splitLines(text);
  const QtmHeader h = readQtmHeader(lines, name);
  const size_t n = h.names.size();
  RawTrial raw;
  raw.file = name;
  raw.format = "QTM TSV";
  raw.kind = PointKind::Markers;
  raw.labels = h.names;
  if (options.rateHzOverride) {
    raw.rateHz = checkedRateOverrideHz(*options.rateHzOverride, name);
  } else if (h.frequencyHz) {
    raw.rateHz = checkedFileRateHz(*h.frequencyHz, name, "FREQUENCY");
  } else {
    throwBadData(name, "", "no FREQUENCY line: give the frame rate with --rate");
  }
  raw.units = options.unitsOverride.value_or("mm");
  const double scale = unitToMm(raw.units, name);
  if (h.events > 0)
    raw.warnings.push_back(std::to_string(h.events) +
                           " EVENT lines not read: the gait events come from the kinematics");

  size_t at = h.dataStart;
  const int leading = qtmLeadingColumns(lines, at, n, name);
  std::vector<const TextLine*> rows;
  for (; at < lines.size(); ++at)
    if (!trim(lines[at].text).empty()) rows.push_back(&lines[at]);
  if (h.frames && *h.frames != static_cast<double>(rows.size()))
    throwMalformed(name, rows.empty() ? linePosition(h.lastLine) : linePosition(rows.back()->number),
                   "NO_OF_FRAMES says " + statedCount(*h.frames) + " frames, the file holds " +
                       std::to_string(rows.size()) + (static_cast<double>(rows.size()) < *h.frames ? " (cut short?)" : ""));
  if (rows.empty()) throwBadData(name, "", "the header is followed by no frames");
  checkPointFrames(static_cast<double>(rows.size()), static_cast<double>(n), kMaxPointFrames, name, "MARKER_NAMES");

  raw.positionsMm.setConstant(static_cast<Eigen::Index>(rows.size()), 3 * static_cast<Eigen::Index>(n), std::nan(""));
  std::optional<long> previous;
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto fields = qtmFields(rows[r]->text);
    if (fields.size() > static_cast<size_t>(leading) + 3 * n)
      throwMalformed(name, linePosition(rows[r]->number),
                     std::to_string(fields.size()) + " fields, expected " + std::to_string(leading + 3 * n));
    if (leading > 0) {
      const long frame = consecutiveFrameNumber(fields[0], previous ? &*previous : nullptr, name, rows[r]->number);
      if (!previous) raw.firstFrame = frame;
      previous = frame;
    }
    for (size_t m = 0; m < n; ++m) {
      const size_t x = static_cast<size_t>(leading) + 3 * m;
      // QTM writes a marker it did not see as empty cells or as 0, 0, 0: both are gaps.
      if (const auto p = markerCells(fields, {x, x + 1, x + 2}, true, name, rows[r]->number))
        raw.positionsMm.block<1, 3>(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(3 * m)) = p->transpose() * scale;
    }
  }
  return raw;
}

RawTrial readQtmTsv(const std::filesystem::path& file, const LoadOptions& options) {
  return parseQtmTsv(readFileText(file), file.string(), options);
}

}  // namespace ew
