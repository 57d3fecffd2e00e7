// CSV keypoint files: MediaPipe Pose exports (one row per frame, coordinates as fractions of
// the image) and DeepLabCut analyses (three or four header rows, one row per frame).
// Declared in keypoint_frames.h.

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/io/file_bytes.h"
#include "core/io/reader_limits.h"
#include "core/io/text_table.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// [SECTION] Shared ---------------------------------------------------------------------------

bool isBlankOrComment(std::string_view line) {
  line = trim(line);
  return line.empty() || line.front() == '#';
}

// The lines after the header rows that carry data (blank and '#' lines skipped).
std::vector<TextLine> contentLines(const std::vector<TextLine>& lines, std::size_t from) {
  std::vector<TextLine> out;
  for (std::size_t i = from; i < lines.size(); ++i) {
    if (!isBlankOrComment(lines[i].text)) out.push_back(lines[i]);
  }
  return out;
}

// A row's cells; a row with another field count than the header is malformed, since the
// columns would shift.
std::vector<std::string_view> rowCells(const TextLine& line, std::size_t expected, const std::string& file) {
  auto cells = splitFields(line.text, ',');
  if (cells.size() != expected)
    throwMalformed(file, linePosition(line.number),
              std::string(cells.size() < expected ? "short row: " : "") + std::to_string(cells.size()) +
                  " fields where the header has " + std::to_string(expected));
  return cells;
}

// A cell as a number; empty or nan is NaN (an absent point). Anything else that is not a
// finite number (text, inf) is malformed.
double cellNumber(const std::vector<std::string_view>& cells, std::size_t column, const TextLine& line,
                  const std::string& file) {
  double v = kNaN;
  if (!parseDouble(cells[column], v, true))
    throwMalformed(file, linePosition(line.number, static_cast<int>(column) + 1),
              "'" + std::string(cells[column]) + "' is not a finite number");
  return v;
}

// Existing readers' convention: a point without coordinates or with confidence 0 is absent.
void setPoint(Eigen::MatrixX3d& points, Eigen::Index i, double x, double y, double confidence) {
  if (std::isnan(x) || std::isnan(y) || !(confidence > 0.0)) {
    points.row(i) << kNaN, kNaN, 0.0;
  } else {
    points.row(i) << x, y, confidence;
  }
}

bool anyPointSeen(const Eigen::MatrixX3d& points) { return (points.col(2).array() > 0.0).any(); }

void addFrame(KeypointFrames& out, const TextLine& line) {
  if (out.frameCount() >= kMaxKeypointFrames)
    throwMalformed(out.file, linePosition(line.number), "more than " + std::to_string(kMaxKeypointFrames) + " frames");
  out.frames.emplace_back();
}

void requireSomebody(const KeypointFrames& out) {
  if (out.frames.empty()) throw Error(ErrorKind::BadData, out.file, "", "no frames");
  const bool anybody = std::any_of(out.frames.begin(), out.frames.end(), [](const auto& f) { return !f.empty(); });
  if (!anybody)
    throw Error(ErrorKind::BadData, out.file, "",
                "no point seen in any of the " + std::to_string(out.frames.size()) + " frames");
}

// [SECTION] MediaPipe Pose -------------------------------------------------------------------

struct MediaPipeColumns {
  std::vector<std::array<int, 3>> landmarks;  // per landmark: x, y, visibility column (-1: none)
  int time = -1;
  double timeToSeconds = 1.0;
  int frame = -1;
  std::size_t count = 0;
};

int positiveSide(std::string_view digits) {
  int v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  const bool ok = ec == std::errc() && end == digits.data() + digits.size();
  return ok && v > 0 && v <= kMaxKeypointImageSidePx ? v : 0;
}

// "# image_size=1920x1080" (also "image_size: 1920 x 1080"); nullopt for other comments.
std::optional<KeypointImageSize> imageSizeComment(const TextLine& line, const std::string& file) {
  std::string body = toLower(trim(trim(line.text).substr(1)));
  if (!body.starts_with("image_size")) return std::nullopt;
  body.erase(std::remove(body.begin(), body.end(), ' '), body.end());
  const std::size_t sep = body.find_first_of("=:"), x = body.find('x', sep == std::string::npos ? 0 : sep);
  KeypointImageSize size;
  if (sep != std::string::npos && x != std::string::npos) {
    size.width = positiveSide(std::string_view(body).substr(sep + 1, x - sep - 1));
    size.height = positiveSide(std::string_view(body).substr(x + 1));
  }
  if (size.width == 0 || size.height == 0)
    throwMalformed(file, linePosition(line.number),
              "image_size must be WIDTHxHEIGHT in pixels (1 to " + std::to_string(kMaxKeypointImageSidePx) +
                  "), e.g. 1920x1080");
  return size;
}

MediaPipeColumns mediaPipeColumns(const TextLine& header, const std::string& file) {
  const auto names = splitFields(header.text, ',');
  std::map<std::string, int> at;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!at.emplace(toLower(names[i]), static_cast<int>(i)).second)
      throwMalformed(file, linePosition(header.number, static_cast<int>(i) + 1),
                "column '" + std::string(names[i]) + "' appears twice");
  }
  const auto column = [&](const std::string& name) { return at.contains(name) ? at.at(name) : -1; };
  MediaPipeColumns c;
  c.count = names.size();
  std::vector<std::string> missing;
  for (const auto& landmark : keypointLayoutNamed("MediaPipe-33").points) {
    c.landmarks.push_back({column(landmark + "_x"), column(landmark + "_y"), column(landmark + "_visibility")});
    if (c.landmarks.back()[0] < 0 || c.landmarks.back()[1] < 0) missing.push_back(landmark + "_x/_y");
  }
  if (!missing.empty())
    throwMalformed(file, linePosition(header.number), "MediaPipe landmark columns missing: " + listForMessage(missing, 8));
  c.frame = column("frame");
  for (const auto& [name, scale] : {std::pair{"time_s", 1.0}, std::pair{"timestamp", 1.0}, std::pair{"timestamp_ms", 1e-3}}) {
    if (c.time < 0 && column(name) >= 0) c.time = column(name), c.timeToSeconds = scale;
  }
  return c;
}

KeypointImageSize checkedImageSize(const KeypointImageSize& size, const std::string& file) {
  const auto ok = [](int side) { return side > 0 && side <= kMaxKeypointImageSidePx; };
  if (!ok(size.width) || !ok(size.height))
    throw Error(ErrorKind::BadArgument, file, "image size",
                std::to_string(size.width) + "x" + std::to_string(size.height) + " is not an image size in pixels");
  return size;
}

void addMediaPipeRow(KeypointFrames& out, const TextLine& line, const MediaPipeColumns& c, const KeypointImageSize& size,
                     std::vector<double>& times) {
  const auto cells = rowCells(line, c.count, out.file);
  addFrame(out, line);
  if (c.frame >= 0) cellNumber(cells, static_cast<std::size_t>(c.frame), line, out.file);  // checked only: rows are frames
  if (c.time >= 0) times.push_back(cellNumber(cells, static_cast<std::size_t>(c.time), line, out.file) * c.timeToSeconds);
  Eigen::MatrixX3d points(static_cast<Eigen::Index>(c.landmarks.size()), 3);
  for (std::size_t i = 0; i < c.landmarks.size(); ++i) {
    const auto& [xCol, yCol, visCol] = c.landmarks[i];
    const double x = cellNumber(cells, static_cast<std::size_t>(xCol), line, out.file);
    const double y = cellNumber(cells, static_cast<std::size_t>(yCol), line, out.file);
    const double visibility = visCol >= 0 ? cellNumber(cells, static_cast<std::size_t>(visCol), line, out.file) : 1.0;
    setPoint(points, static_cast<Eigen::Index>(i), x * size.width, y * size.height, visibility);
  }
  if (anyPointSeen(points)) out.frames.back().push_back(KeypointDetection{std::move(points), -1});
}

// 1 / median step: robust to a dropped or repeated frame. An empty time cell leaves a NaN,
// which the steps skip.
std::optional<double> rateFromTimes(const std::vector<double>& times, const std::string& file) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < times.size(); ++i) {
    if (std::isfinite(times[i] - times[i - 1])) steps.push_back(times[i] - times[i - 1]);
  }
  if (steps.empty()) return std::nullopt;
  std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
  const double step = steps[steps.size() / 2];
  if (!(step > 0.0)) throwMalformed(file, "time column", "the times do not increase: no frame rate");
  return checkedFileRateHz(1.0 / step, file, "time column");
}

// MediaPipe's columns: a landmark's _visibility (no joint CSV has one), or the _x of two of
// its landmarks (a joint CSV with one misnamed "nose" column keeps its own header error). Not
// every landmark: a file cut down to a few is still MediaPipe's, answered with the columns it
// lacks, not read as a 15-joint CSV of the wrong width (issue 53: "nose_x, nose_y, nose_z,
// nose_visibility" holding a NaN).
bool namesMediaPipeLandmarks(const std::vector<std::string_view>& fields) {
  std::set<std::string> names;
  for (std::string_view f : fields) names.insert(toLower(f));
  int withX = 0;
  for (const std::string& landmark : keypointLayoutNamed("MediaPipe-33").points) {
    if (names.contains(landmark + "_visibility")) return true;
    withX += names.contains(landmark + "_x");
  }
  return withX >= 2;
}

// [SECTION] DeepLabCut -----------------------------------------------------------------------

struct DlcHeader {
  std::vector<std::string> pointNames;           // the first individual's body parts
  std::vector<std::vector<std::size_t>> xColumn;  // per individual, per point: its x column
  std::size_t count = 0;                          // fields per row
  std::size_t rows = 0;                           // header rows (3, or 4 with individuals)
  std::vector<std::string> warnings;
};

struct DlcGroup {
  std::string individual;
  std::vector<std::string> parts;
  std::vector<std::size_t> xColumn;
};

// Each header name spans its x, y, likelihood columns.
std::string tripleName(const std::vector<std::string_view>& cells, std::size_t x, const TextLine& line,
                       const std::string& file, const char* what) {
  if (cells[x] != cells[x + 1] || cells[x] != cells[x + 2])
    throwMalformed(file, linePosition(line.number, static_cast<int>(x) + 1),
              std::string("each ") + what + " names three columns (x, y, likelihood)");
  return std::string(cells[x]);
}

// The header rows' cells: scorer, individuals (multi-animal projects), bodyparts, coords.
std::vector<std::vector<std::string_view>> dlcHeaderRows(const std::vector<TextLine>& lines, const std::string& file) {
  std::vector<std::string> expected = {"scorer", "bodyparts", "coords"};
  if (lines.size() > 1 && toLower(splitFields(lines[1].text, ',')[0]) == "individuals")
    expected.insert(expected.begin() + 1, "individuals");
  if (lines.size() < expected.size())
    throwMalformed(file, "", "the DeepLabCut header (scorer, bodyparts, coords rows) is incomplete");
  std::vector<std::vector<std::string_view>> rows;
  for (std::size_t r = 0; r < expected.size(); ++r) {
    rows.push_back(splitFields(lines[r].text, ','));
    if (toLower(rows[r][0]) != expected[r])
      throwMalformed(file, linePosition(lines[r].number), "a DeepLabCut header row here starts with '" + expected[r] + "'");
    if (rows[r].size() != rows[0].size())
      throwMalformed(file, linePosition(lines[r].number), std::to_string(rows[r].size()) +
                                                         " fields where the scorer row has " + std::to_string(rows[0].size()));
  }
  if (rows[0].size() < 4 || (rows[0].size() - 1) % 3 != 0)
    throwMalformed(file, linePosition(lines[0].number), "after the first column DeepLabCut writes x, y, likelihood triples");
  return rows;
}

// The column triples grouped by individual (one unnamed group for single-animal files).
std::vector<DlcGroup> dlcGroups(const std::vector<std::vector<std::string_view>>& rows,
                                const std::vector<TextLine>& lines, const std::string& file) {
  const bool multi = rows.size() == 4;
  const std::size_t partsRow = rows.size() - 2, coordsRow = rows.size() - 1;
  std::vector<DlcGroup> groups;
  for (std::size_t x = 1; x + 2 < rows[0].size(); x += 3) {
    const auto& coords = rows[coordsRow];
    if (toLower(coords[x]) != "x" || toLower(coords[x + 1]) != "y" || toLower(coords[x + 2]) != "likelihood")
      throwMalformed(file, linePosition(lines[coordsRow].number, static_cast<int>(x) + 1),
                "DeepLabCut coords repeat x, y, likelihood");
    const std::string individual = multi ? tripleName(rows[1], x, lines[1], file, "individual") : "";
    if (groups.empty() || groups.back().individual != individual) {
      for (const auto& g : groups) {
        if (g.individual == individual)
          throwMalformed(file, linePosition(lines[1].number, static_cast<int>(x) + 1),
                    "the columns of individual '" + individual + "' are not together");
      }
      groups.push_back(DlcGroup{individual, {}, {}});
    }
    groups.back().parts.push_back(tripleName(rows[partsRow], x, lines[partsRow], file, "body part"));
    groups.back().xColumn.push_back(x);
  }
  return groups;
}

void checkPointNames(const std::vector<std::string>& names, const TextLine& line, const std::string& file) {
  if (names.size() > static_cast<std::size_t>(kMaxKeypointsPerPerson))
    throwMalformed(file, linePosition(line.number), std::to_string(names.size()) + " body parts, more than " +
                                                   std::to_string(kMaxKeypointsPerPerson));
  for (std::size_t i = 0; i < names.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (toLower(names[k]) == toLower(names[i]))
        throwMalformed(file, linePosition(line.number), "body part '" + names[i] + "' appears twice");
    }
  }
}

DlcHeader dlcHeader(const std::vector<TextLine>& lines, const std::string& file) {
  const auto rows = dlcHeaderRows(lines, file);
  const auto groups = dlcGroups(rows, lines, file);
  const TextLine& partsLine = lines[rows.size() - 2];
  DlcHeader h;
  h.count = rows[0].size();
  h.rows = rows.size();
  h.pointNames = groups.front().parts;
  checkPointNames(h.pointNames, partsLine, file);
  for (const auto& g : groups) {
    if (g.parts == h.pointNames) {
      h.xColumn.push_back(g.xColumn);
    } else if (toLower(g.individual) == "single") {  // multi-animal "unique bodyparts": nobody's
      h.warnings.push_back("DeepLabCut unique body parts not used (no individual's): " + listForMessage(g.parts, 10));
    } else {
      throwMalformed(file, linePosition(partsLine.number),
                "individual '" + g.individual + "' has body parts " + listForMessage(g.parts, 10) + " where '" +
                    groups.front().individual + "' has " + listForMessage(h.pointNames, 10));
    }
  }
  if (h.xColumn.size() > static_cast<std::size_t>(kMaxPeoplePerFrame))
    throwMalformed(file, linePosition(lines[1].number), "more than " + std::to_string(kMaxPeoplePerFrame) + " individuals");
  return h;
}

void addDlcRow(KeypointFrames& out, const TextLine& line, const DlcHeader& h) {
  const auto cells = rowCells(line, h.count, out.file);
  addFrame(out, line);
  double frameIndex = kNaN;
  if (!parseDouble(cells[0], frameIndex, false) || std::isnan(frameIndex))
    throwMalformed(out.file, linePosition(line.number, 1), "frame index '" + std::string(cells[0]) + "' is not a number");
  for (std::size_t k = 0; k < h.xColumn.size(); ++k) {
    Eigen::MatrixX3d points(static_cast<Eigen::Index>(h.pointNames.size()), 3);
    for (std::size_t i = 0; i < h.pointNames.size(); ++i) {
      const std::size_t x = h.xColumn[k][i];
      setPoint(points, static_cast<Eigen::Index>(i), cellNumber(cells, x, line, out.file),
               cellNumber(cells, x + 1, line, out.file), cellNumber(cells, x + 2, line, out.file));
    }
    if (anyPointSeen(points)) out.frames.back().push_back(KeypointDetection{std::move(points), static_cast<int>(k)});
  }
}

}  // namespace

// [SECTION] Public API -----------------------------------------------------------------------

KeypointCsvKind keypointCsvKind(std::string_view text) {
  text = withoutBom(text);
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (isBlankOrComment(line)) continue;
    const auto fields = splitFields(line, ',');
    if (toLower(fields[0]) == "scorer") return KeypointCsvKind::DeepLabCut;
    return namesMediaPipeLandmarks(fields) ? KeypointCsvKind::MediaPipe : KeypointCsvKind::NotKeypoints;
  }
  return KeypointCsvKind::NotKeypoints;
}

KeypointCsvKind sniffKeypointCsv(const fs::path& path) { return keypointCsvKind(readFileStart(path)); }

KeypointFrames readKeypointCsv(const fs::path& path, std::optional<KeypointImageSize> imageSize,
                               std::optional<KeypointImageSize> videoSize) {
  const std::string text = readFileText(path);
  switch (keypointCsvKind(text)) {
    case KeypointCsvKind::MediaPipe:
      return parseMediaPipeCsv(text, path.string(), imageSize, videoSize);
    case KeypointCsvKind::DeepLabCut:
      return parseDeepLabCutCsv(text, path.string());
    case KeypointCsvKind::NotKeypoints:
      break;
  }
  throwMalformed(path.string(), "",
            "not a keypoint CSV we read: expected DeepLabCut (a first row 'scorer,…') or MediaPipe Pose "
            "(a header with nose_x, nose_y, …)");
}

KeypointFrames parseMediaPipeCsv(const std::string& text, const std::string& name,
                                 std::optional<KeypointImageSize> imageSize,
                                 std::optional<KeypointImageSize> videoSize) {
  const auto lines = splitLines(withoutBom(text));
  std::size_t header = 0;
  std::optional<KeypointImageSize> stated;
  for (; header < lines.size() && isBlankOrComment(lines[header].text); ++header) {
    if (!trim(lines[header].text).empty()) {
      if (auto size = imageSizeComment(lines[header], name)) stated = size;
    }
  }
  if (header == lines.size()) throwMalformed(name, "", "no header row");
  const MediaPipeColumns columns = mediaPipeColumns(lines[header], name);
  if (!imageSize && !stated && !videoSize)
    throw Error(ErrorKind::BadArgument, name, "",
                "MediaPipe x, y are " + std::string(kNeedsImageSize) + ": give the image size in pixels (a line "
                "'# image_size=1920x1080' before the header, or the image size option), or put the video "
                "beside the file");
  const KeypointImageSize size = imageSize ? checkedImageSize(*imageSize, name)
                                 : stated  ? *stated
                                           : checkedImageSize(*videoSize, name);
  KeypointFrames out;
  out.file = name;
  out.format = "MediaPipe CSV";
  out.pointCount = static_cast<int>(columns.landmarks.size());
  out.layoutHint = "MediaPipe-33";
  out.imageSize = stated;  // what the file says; a size given or the video's is the caller's
  std::vector<double> times;
  for (const auto& line : contentLines(lines, header + 1)) addMediaPipeRow(out, line, columns, size, times);
  requireSomebody(out);
  out.rateHz = rateFromTimes(times, name);
  return out;
}

KeypointFrames parseDeepLabCutCsv(const std::string& text, const std::string& name) {
  const auto lines = contentLines(splitLines(withoutBom(text)), 0);
  if (lines.empty()) throwMalformed(name, "", "empty file");
  const DlcHeader header = dlcHeader(lines, name);
  KeypointFrames out;
  out.file = name;
  out.format = "DeepLabCut CSV";
  out.pointCount = static_cast<int>(header.pointNames.size());
  out.pointNames = header.pointNames;
  out.warnings = header.warnings;
  for (std::size_t i = header.rows; i < lines.size(); ++i) addDlcRow(out, lines[i], header);
  requireSomebody(out);
  return out;
}

}  // namespace ew
