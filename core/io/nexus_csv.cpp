#include "core/io/nexus_csv.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>

#include "core/common/errors.h"
#include "core/io/marker_cells.h"
#include "core/io/reader_limits.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

// The sections Nexus writes (its "Export ASCII" options), any of which may come first.
constexpr std::array<std::string_view, 6> kSectionNames = {"trajectories", "devices", "model outputs",
                                                           "joints",       "segments", "events"};

// The first field of a line, whatever the delimiter.
std::string firstField(std::string_view line) {
  const size_t end = line.find_first_of(",\t");
  return toLower(trim(withoutBom(line.substr(0, end))));
}

bool namesSection(std::string_view line) {
  const std::string first = firstField(line);
  return std::find(kSectionNames.begin(), kSectionNames.end(), first) != kSectionNames.end();
}

// A row that ends a section: nothing but delimiters and blanks (the next section's name ends
// it too, should the blank line be missing).
bool blankRow(std::string_view line) {
  return line.find_first_not_of(",\t \r") == std::string_view::npos;
}

struct MarkerColumns {
  std::string label;
  std::array<size_t, 3> xyz{};  // X, Y and Z, wherever the components row puts them
  std::string unit;
};

// Each named quantity's X, Y and Z columns, found in the components row between its name and
// the next one (an export with velocities puts X' beside X).
std::vector<MarkerColumns> markerColumns(const TextLine& namesLine, const TextLine& componentsLine,
                                         const TextLine& unitsLine, char delimiter,
                                         const std::string& name) {
  const auto names = splitFields(namesLine.text, delimiter);
  const auto components = splitFields(componentsLine.text, delimiter);
  const auto units = splitFields(unitsLine.text, delimiter);
  if (components.size() < 2 || toLower(components[0]) != "frame") {
    throwMalformed(name, linePosition(componentsLine.number),
                   "expected the components row 'Frame,Sub Frame,X,Y,Z,…' under the marker names");
  }
  std::vector<MarkerColumns> markers;
  std::set<std::string> seen;
  for (size_t c = 2; c < names.size(); ++c) {
    if (names[c].empty()) continue;
    MarkerColumns m;
    m.label = std::string(names[c]);
    if (!seen.insert(m.label).second)
      throwMalformed(name, linePosition(namesLine.number, static_cast<int>(c + 1)),
                     "marker " + shownWord(names[c]) + " named twice");
    size_t end = c + 1;
    while (end < names.size() && names[end].empty()) ++end;
    end = std::max(end, std::min(components.size(), c + 3));
    for (size_t axis = 0; axis < 3; ++axis) {
      const std::string wanted(1, "xyz"[axis]);
      size_t k = c;
      while (k < std::min(end, components.size()) && toLower(components[k]) != wanted) ++k;
      if (k >= std::min(end, components.size()))
        throwMalformed(name, linePosition(componentsLine.number, static_cast<int>(c + 1)),
                       "marker " + shownWord(names[c]) + " has no " + std::string(1, "XYZ"[axis]) +
                           " column");
      m.xyz[axis] = k;
    }
    m.unit = m.xyz[0] < units.size() ? std::string(units[m.xyz[0]]) : "";
    markers.push_back(std::move(m));
  }
  if (markers.empty())
    throwBadData(name, linePosition(namesLine.number), "the Trajectories section names no marker");
  return markers;
}

// The one length unit the markers are in (Nexus: mm); the user's wins.
std::string markerUnit(const std::vector<MarkerColumns>& markers, const TextLine& unitsLine,
                       const LoadOptions& options, const std::string& name) {
  if (options.unitsOverride) return *options.unitsOverride;
  const std::string unit = markers.front().unit.empty() ? "mm" : markers.front().unit;
  for (const auto& m : markers)
    if (!m.unit.empty() && m.unit != unit)
      throwMalformed(name, linePosition(unitsLine.number),
                     "markers in " + shownWord(unit) + " and in " + shownWord(m.unit) +
                         ": give the unit with --units");
  return unit;
}

double sectionRate(const TextLine& rateLine, const LoadOptions& options, const std::string& name) {
  if (options.rateHzOverride) return checkedRateOverrideHz(*options.rateHzOverride, name);
  double rate = 0;
  const auto fields = splitFields(rateLine.text, rateLine.text.find('\t') != std::string_view::npos ? '\t' : ',');
  if (fields.empty() || !parseFinite(fields[0], rate))
    throwMalformed(name, linePosition(rateLine.number),
                   "expected the Trajectories section's rate (Hz) under its name");
  return checkedFileRateHz(rate, name, "the Trajectories section's rate");
}

}  // namespace

bool looksLikeNexusCsv(std::string_view text) {
  for (const auto& line : splitLines(text.substr(0, 4096))) {
    if (trim(line.text).empty()) continue;
    return namesSection(line.text);
  }
  return false;
}

RawTrial parseNexusCsv(std::string_view text, const std::string& name, const LoadOptions& options) {
  const auto lines = splitLines(text);
  size_t at = 0;
  while (at < lines.size() && firstField(lines[at].text) != "trajectories") ++at;
  if (at == lines.size())
    throwBadData(name, "",
                 "a Vicon Nexus export without a Trajectories section: export the markers' "
                 "trajectories (Nexus: Export ASCII with Trajectories ticked), or the C3D");
  if (at + 4 >= lines.size())
    throwMalformed(name, linePosition(lines.back().number),
                   "the file ends inside the Trajectories section's header");
  const TextLine& componentsLine = lines[at + 3];
  const char delimiter = componentsLine.text.find('\t') != std::string_view::npos ? '\t' : ',';
  const auto markers = markerColumns(lines[at + 2], componentsLine, lines[at + 4], delimiter, name);
  RawTrial raw;
  raw.file = name;
  raw.format = "Nexus CSV";
  raw.kind = PointKind::Markers;
  raw.rateHz = sectionRate(lines[at + 1], options, name);
  raw.units = markerUnit(markers, lines[at + 4], options, name);
  const double scale = unitToMm(raw.units, name);
  for (const auto& m : markers) raw.labels.push_back(m.label);
  if (std::any_of(lines.begin(), lines.end(), [](const TextLine& l) { return firstField(l.text) == "events"; }))
    raw.warnings.push_back("the export's Events section is not read: the gait events come from the "
                           "kinematics (the trial's C3D carries the lab's events)");

  size_t end = at + 5;
  while (end < lines.size() && !blankRow(lines[end].text) && !namesSection(lines[end].text)) ++end;
  const auto frames = static_cast<Eigen::Index>(end - (at + 5));
  if (frames == 0) throwBadData(name, linePosition(componentsLine.number), "the Trajectories section has no frames");
  checkPointFrames(static_cast<double>(frames), static_cast<double>(markers.size()), kMaxPointFrames, name,
                   "Trajectories");
  const size_t columns = splitFields(componentsLine.text, delimiter).size();
  raw.positionsMm.setConstant(frames, 3 * static_cast<Eigen::Index>(markers.size()), std::nan(""));
  std::optional<long> previous;
  for (Eigen::Index r = 0; r < frames; ++r) {
    const TextLine& line = lines[at + 5 + static_cast<size_t>(r)];
    const auto fields = splitFields(line.text, delimiter);
    if (fields.size() > columns)
      throwMalformed(name, linePosition(line.number),
                     std::to_string(fields.size()) + " fields, the header has " + std::to_string(columns));
    const long frame = consecutiveFrameNumber(fields[0], previous ? &*previous : nullptr, name, line.number);
    if (!previous) raw.firstFrame = frame;
    previous = frame;
    for (size_t m = 0; m < markers.size(); ++m)
      if (const auto p = markerCells(fields, markers[m].xyz, false, name, line.number))
        raw.positionsMm.block<1, 3>(r, static_cast<Eigen::Index>(3 * m)) = p->transpose() * scale;
  }
  return raw;
}

}  // namespace ew
