#include "core/io/text_table.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "core/common/errors.h"

namespace ew {

std::vector<TextLine> splitLines(std::string_view text) {
  std::vector<TextLine> lines;
  size_t start = 0;
  int number = 1;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (end == text.size() && line.empty()) break;  // no phantom last line after final LF
    lines.push_back({number++, line});
    start = end + 1;
  }
  return lines;
}

namespace {
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
}  // namespace

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  words.reserve(8);
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::string shownWord(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) == 127) c = '?';
  }
  if (s.size() > 40) out += "...";
  return "'" + out + "'";
}

bool parseFinite(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string toLower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string_view> splitFields(std::string_view line, char delimiter) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  while (true) {
    size_t end = line.find(delimiter, start);
    std::string_view field = trim(line.substr(start, end == std::string_view::npos
                                                         ? std::string_view::npos
                                                         : end - start));
    if (field.size() >= 2 && field.front() == '"' && field.back() == '"') {
      field = field.substr(1, field.size() - 2);
    }
    fields.push_back(field);
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return fields;
}

std::vector<std::string_view> splitTabs(std::string_view line) {
  if (line.find('\t') != std::string_view::npos) return splitFields(line, '\t');
  std::vector<std::string_view> fields;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && line[i] == ' ') ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool parseDouble(std::string_view field, double& out, bool allowEmpty) {
  field = trim(field);
  if (field.empty()) {
    out = std::numeric_limits<double>::quiet_NaN();
    return allowEmpty;
  }
  std::string lower = toLower(field);
  if (lower == "nan" || lower == "-nan") {
    out = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (field.front() == '+') field.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), out);
  if (ec != std::errc() || ptr != field.data() + field.size()) return false;
  return std::isfinite(out);
}

std::string linePosition(int line, int column) {
  std::string s = "line " + std::to_string(line);
  if (column > 0) s += ", column " + std::to_string(column);
  return s;
}

std::string_view withoutBom(std::string_view s) {
  return s.rfind("\xEF\xBB\xBF", 0) == 0 ? s.substr(3) : s;
}

long consecutiveFrameNumber(std::string_view field, const long* previous, const std::string& file, int line) {
  double frame = 0;
  if (!parseFinite(field, frame) || frame != std::floor(frame) || std::abs(frame) > 1e9)
    throwMalformed(file, linePosition(line, 1), "frame number " + shownWord(field) + " is not a whole number");
  const auto number = static_cast<long>(frame);
  if (previous && number != *previous + 1)
    throwMalformed(file, linePosition(line, 1),
                   "frame " + std::to_string(number) + " after frame " + std::to_string(*previous) +
                       ": the rows must be consecutive frames");
  return number;
}

}  // namespace ew
