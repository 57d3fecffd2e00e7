#include "core/camera/calibration_file.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "core/camera/focal_length.h"
#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/text_table.h"
#include "core/keypoints/keypoint_frames.h"

namespace ew {

namespace {

// Bounds: a calibration file holds a few cameras, each a few lines.
constexpr std::size_t kMaxCameras = 64;
constexpr std::size_t kMaxNumbersPerValue = 64;
constexpr int kMaxArrayDepth = 4;

[[noreturn]] void malformed(const std::string& file, int line, const std::string& problem) {
  throw Error(ErrorKind::Malformed, file, linePosition(line), problem);
}

// A value's text without a trailing comment (a '#' outside a string).
std::string_view withoutComment(std::string_view s) {
  bool inString = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '"') inString = !inString;
    if (s[i] == '#' && !inString) return s.substr(0, i);
  }
  return s;
}

// The numbers of a value: a number or nested arrays of numbers, flattened, with the shape
// of the outer array (rows) kept as the count of numbers per row.
struct Numbers {
  std::vector<double> values;
  std::vector<std::size_t> rowSizes;  // for an array of arrays
};

Numbers parseNumbers(std::string_view v, const std::string& file, int line, std::string_view key) {
  Numbers n;
  int depth = 0;
  std::size_t rowStart = 0;
  for (std::size_t i = 0; i < v.size();) {
    const char c = v[i];
    if (c == '[') {
      if (++depth > kMaxArrayDepth) malformed(file, line, std::string(key) + ": arrays nested too deep");
      if (depth == 2) rowStart = n.values.size();
      ++i;
    } else if (c == ']') {
      if (depth == 2) n.rowSizes.push_back(n.values.size() - rowStart);
      if (--depth < 0) malformed(file, line, std::string(key) + ": unbalanced ']'");
      ++i;
    } else if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else {
      double x = 0.0;
      const char* end = v.data() + v.size();
      const char* first = v.data() + i + (c == '+' ? 1 : 0);
      const auto [ptr, ec] = std::from_chars(first, end, x);
      if (ec != std::errc() || ptr == first)
        malformed(file, line, std::string(key) + ": '" + std::string(v.substr(i, 12)) + "' is not a number");
      if (!std::isfinite(x)) malformed(file, line, std::string(key) + ": a number is not finite");
      if (n.values.size() >= kMaxNumbersPerValue) malformed(file, line, std::string(key) + ": too many numbers");
      n.values.push_back(x);
      i = static_cast<std::size_t>(ptr - v.data());
    }
  }
  if (depth != 0) malformed(file, line, std::string(key) + ": unbalanced '['");
  return n;
}

bool isString(std::string_view v) { return !v.empty() && v.front() == '"'; }
bool isStringOrBool(std::string_view v) { return isString(v) || v == "true" || v == "false"; }

// A string value ends with the quote it opened with: `name = "abc` must not become camera "ab".
void checkTerminated(std::string_view value, const std::string& file, int line, const std::string& key) {
  if (isString(value) && (value.size() < 2 || value.back() != '"'))
    malformed(file, line, key + ": the string has no closing '\"'");
}

struct Table {
  std::string name;
  int line = 0;
  std::map<std::string, std::pair<std::string, int>, std::less<>> values;  // key → (value text, line)
};

std::vector<Table> parseTables(std::string_view text, const std::string& file) {
  std::vector<Table> tables;
  // A UTF-8 byte-order mark (Windows editors write one) is no part of the first line.
  for (const TextLine& line : splitLines(withoutBom(text))) {
    const std::string_view raw = trim(withoutComment(line.text));
    const int number = line.number;
    if (raw.empty()) continue;
    if (raw.front() == '[') {
      if (raw.size() < 3 || raw.back() != ']') malformed(file, number, "a table header is [name]");
      if (tables.size() >= kMaxCameras + 1) malformed(file, number, "more than 64 tables");
      tables.push_back({std::string(trim(raw.substr(1, raw.size() - 2))), number, {}});
      continue;
    }
    const std::size_t eq = raw.find('=');
    if (eq == std::string_view::npos) malformed(file, number, "expected key = value");
    if (tables.empty()) malformed(file, number, "a value before any [table]");
    const std::string key(trim(raw.substr(0, eq)));
    const std::string_view value = trim(raw.substr(eq + 1));
    if (key.empty() || value.empty()) malformed(file, number, "expected key = value");
    checkTerminated(value, file, number, key);
    tables.back().values[key] = {std::string(value), number};
  }
  return tables;
}

// A key's numbers; nullopt when absent.
std::optional<Numbers> numbers(const Table& t, std::string_view key, const std::string& file) {
  const auto it = t.values.find(key);
  if (it == t.values.end()) return std::nullopt;
  if (isStringOrBool(it->second.first)) malformed(file, it->second.second, std::string(key) + ": expected numbers");
  return parseNumbers(it->second.first, file, it->second.second, key);
}

// `rotation` and `translation`: three numbers each, both or neither.
void readExtrinsics(const Table& t, const std::string& file, CalibratedCamera& c) {
  const auto r = numbers(t, "rotation", file);
  const auto tr = numbers(t, "translation", file);
  if (!r && !tr) return;
  const char* key = !r ? "translation" : "rotation";
  const int line = t.values.find(key)->second.second;
  if (!r || !tr) malformed(file, line, "[" + t.name + "] " + key + " without its " + (r ? "translation" : "rotation"));
  for (const auto& [name, values] : {std::pair{"rotation", &r->values}, std::pair{"translation", &tr->values}})
    if (values->size() != 3)
      malformed(file, t.values.find(name)->second.second, "[" + t.name + "] " + name + ": expected 3 numbers");
  for (int i = 0; i < 3; ++i) {
    c.rotation[static_cast<std::size_t>(i)] = r->values[static_cast<std::size_t>(i)];
    c.translationMm[static_cast<std::size_t>(i)] = 1000.0 * tr->values[static_cast<std::size_t>(i)];
  }
  c.hasExtrinsics = true;
}

CalibratedCamera cameraOf(const Table& t, const std::string& file) {
  CalibratedCamera c;
  c.name = c.table = t.name;
  if (const auto name = t.values.find("name"); name != t.values.end()) {
    const std::string& value = name->second.first;  // quoted and terminated (parseTables)
    if (!isString(value)) malformed(file, name->second.second, "[" + t.name + "] name: expected a \"quoted\" name");
    c.name = value.substr(1, value.size() - 2);
  }
  const Numbers m = *numbers(t, "matrix", file);
  const int line = t.values.find("matrix")->second.second;
  if (m.values.size() != 9 || m.rowSizes != std::vector<std::size_t>{3, 3, 3})
    malformed(file, line, "[" + t.name + "] matrix: expected 3 rows of 3 numbers");
  c.fxPx = m.values[0], c.cxPx = m.values[2], c.fyPx = m.values[4], c.cyPx = m.values[5];
  for (const double f : {c.fxPx, c.fyPx})
    if (const std::string problem = focalLengthProblem(f); !problem.empty())
      malformed(file, line, "[" + t.name + "] matrix: " + problem);
  if (const auto size = numbers(t, "size", file)) {
    const int sizeLine = t.values.find("size")->second.second;
    // Bounded as an image size option is: the callers take the sides as int pixels.
    const auto side = [](double v) { return v >= 1.0 && v <= kMaxKeypointImageSidePx; };
    if (size->values.size() != 2 || !side(size->values[0]) || !side(size->values[1]))
      malformed(file, sizeLine, "[" + t.name + "] size: expected [width, height] in pixels (1-" +
                                    std::to_string(kMaxKeypointImageSidePx) + " each)");
    c.widthPx = size->values[0], c.heightPx = size->values[1];
  }
  if (const auto d = numbers(t, "distortions", file)) {
    for (std::size_t i = 0; i < std::min<std::size_t>(4, d->values.size()); ++i) c.distortions[i] = d->values[i];
  }
  readExtrinsics(t, file, c);
  return c;
}

}  // namespace

std::vector<CalibratedCamera> parseCalibrationToml(std::string_view text, const std::string& file) {
  std::vector<CalibratedCamera> cameras;
  for (const Table& t : parseTables(text, file)) {
    if (t.name == "metadata" || !t.values.contains("matrix")) continue;
    cameras.push_back(cameraOf(t, file));
  }
  if (cameras.empty()) throw Error(ErrorKind::BadData, file, "", "no camera table (one with a matrix) in the file");
  return cameras;
}

CalibratedCamera readCalibratedCamera(const std::filesystem::path& file, const std::optional<std::string>& name) {
  const std::vector<CalibratedCamera> cameras = parseCalibrationToml(readFileText(file), file.string());
  std::vector<std::string> names;
  for (const auto& c : cameras) {
    if (name && (c.name == *name || c.table == *name)) return c;
    names.push_back(c.name);
  }
  if (!name && cameras.size() == 1) return cameras.front();
  throw Error(ErrorKind::BadArgument, file.string(), "--camera-name",
              (name ? "no camera \"" + *name + "\" in the file" : std::string("the file holds several cameras")) +
                  "; give --camera-name, one of: " + listForMessage(names, 8));
}

}  // namespace ew
