#include "core/io/bvh_reader.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <set>
#include <vector>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/reader_limits.h"
#include "core/io/rotation_arrays.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

// [SECTION] Limits
// A malformed file must fail fast and cheaply, never allocate by an unchecked count.
constexpr int kMaxPoints = 4096;          // joints + End Sites (real skeletons: 20-300)
constexpr int kMaxDepth = 256;            // nesting of JOINT blocks

// [SECTION] Words with line numbers

struct Word {
  std::string_view text;
  int line = 0;
};

bool sameWord(std::string_view a, std::string_view b) { return toLower(a) == toLower(b); }

// Walks the hierarchy word by word while remembering lines, so the motion block after it
// can be read line by line and names may contain spaces (rest of the line).
class WordCursor {
 public:
  WordCursor(const std::vector<TextLine>& lines, const std::string& file)
      : lines_(lines), file_(file) {}

  Word next(std::string_view expecting) {
    fill();
    if (pos_ >= words_.size()) {
      throwMalformed(file_, linePosition(lastLine()),
                     "file ends where " + std::string(expecting) + " was expected");
    }
    return words_[pos_++];
  }

  bool atEnd() {
    fill();
    return pos_ >= words_.size();
  }

  Word peek() {
    fill();
    return pos_ < words_.size() ? words_[pos_] : Word{};
  }

  // The words left on the current line (consumed).
  std::vector<Word> restOfLine() {
    std::vector<Word> rest(words_.begin() + static_cast<std::ptrdiff_t>(pos_), words_.end());
    pos_ = words_.size();
    return rest;
  }

  size_t nextLineIndex() const { return lineIndex_; }
  int lastLine() const { return lines_.empty() ? 1 : lines_.back().number; }

 private:
  void fill() {
    while (pos_ >= words_.size() && lineIndex_ < lines_.size()) {
      const TextLine& line = lines_[lineIndex_++];
      words_.clear();
      for (auto w : splitWords(line.text)) words_.push_back({w, line.number});
      pos_ = 0;
    }
  }

  const std::vector<TextLine>& lines_;
  const std::string& file_;
  std::vector<Word> words_;
  size_t pos_ = 0;
  size_t lineIndex_ = 0;
};

bool parseCount(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && ptr == s.data() + s.size() && out >= 0;
}

// [SECTION] Hierarchy

enum class Channel { XPos, YPos, ZPos, XRot, YRot, ZRot };

std::optional<Channel> channelFromName(std::string_view name) {
  const auto n = toLower(name);
  if (n == "xposition") return Channel::XPos;
  if (n == "yposition") return Channel::YPos;
  if (n == "zposition") return Channel::ZPos;
  if (n == "xrotation") return Channel::XRot;
  if (n == "yrotation") return Channel::YRot;
  if (n == "zrotation") return Channel::ZRot;
  return std::nullopt;
}

bool isRotation(Channel c) { return c == Channel::XRot || c == Channel::YRot || c == Channel::ZRot; }

struct BvhJoint {
  std::string name;
  int parent = -1;  // index into the joint list; parents come before children
  bool endSite = false;
  int line = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::vector<Channel> channels;
  int firstChannel = 0;  // column of channels[0] in a motion row
};

struct BvhSkeleton {
  std::vector<BvhJoint> joints;
  int channelCount = 0;
};

class HierarchyParser {
 public:
  HierarchyParser(WordCursor& in, const std::string& file) : in_(in), file_(file) {}

  BvhSkeleton parse() {
    if (in_.atEnd()) throwMalformed(file_, "line 1", "empty file: no BVH HIERARCHY");
    Word first = in_.next("HIERARCHY");
    if (!sameWord(first.text, "HIERARCHY")) {
      throwMalformed(file_, linePosition(first.line),
                     "not a BVH file: expected HIERARCHY, found " + shownWord(first.text));
    }
    Word root = in_.next("ROOT");
    if (!sameWord(root.text, "ROOT")) {
      throwMalformed(file_, linePosition(root.line),
                     "expected ROOT, found " + shownWord(root.text));
    }
    parseJoint(root, -1, 0);
    if (!in_.atEnd() && sameWord(in_.peek().text, "ROOT")) {
      throw Error(ErrorKind::Unsupported, file_, linePosition(in_.peek().line),
                  "a second ROOT: BVH files with several skeletons are not supported");
    }
    return std::move(skeleton_);
  }

 private:
  void parseJoint(const Word& keyword, int parent, int depth) {
    if (depth > kMaxDepth) {
      throwMalformed(file_, linePosition(keyword.line),
                     "joints nested deeper than " + std::to_string(kMaxDepth) + " levels");
    }
    const int self = addPoint(keyword, parent, false, nameAfter(keyword));
    if (!braceOpened_) expect("{", "'{' after the joint name");
    bool hasOffset = false, hasChannels = false;
    while (true) {
      Word w = in_.next("'}' closing joint " + shownWord(skeleton_.joints[self].name));
      if (w.text == "}") break;
      if (sameWord(w.text, "OFFSET")) {
        if (hasOffset) throwMalformed(file_, linePosition(w.line), "a second OFFSET");
        skeleton_.joints[self].offset = readVector();
        hasOffset = true;
      } else if (sameWord(w.text, "CHANNELS")) {
        if (hasChannels) throwMalformed(file_, linePosition(w.line), "a second CHANNELS");
        readChannels(self);
        hasChannels = true;
      } else if (sameWord(w.text, "JOINT")) {
        parseJoint(w, self, depth + 1);
      } else if (sameWord(w.text, "End")) {
        parseEndSite(w, self);
      } else if (sameWord(w.text, "ROOT")) {
        throw Error(ErrorKind::Unsupported, file_, linePosition(w.line),
                    "a second ROOT: BVH files with several skeletons are not supported");
      } else {
        throwMalformed(file_, linePosition(w.line),
                       "unexpected " + shownWord(w.text) + " in joint " +
                           shownWord(skeleton_.joints[self].name) +
                           " (expected OFFSET, CHANNELS, JOINT, End Site or '}')");
      }
    }
    if (!hasOffset) {
      throwMalformed(file_, linePosition(skeleton_.joints[self].line),
                     "joint " + shownWord(skeleton_.joints[self].name) + " has no OFFSET");
    }
  }

  void parseEndSite(const Word& keyword, int parent) {
    Word site = in_.next("'Site' after 'End'");
    if (!sameWord(site.text, "Site")) {
      throwMalformed(file_, linePosition(site.line),
                     "expected 'Site' after 'End', found " + shownWord(site.text));
    }
    // Anything else on the line is an (ignored) name, or the opening brace.
    auto rest = in_.restOfLine();
    const bool braced = !rest.empty() && rest.back().text == "{";
    const int self = addPoint(keyword, parent, true, skeleton_.joints[parent].name + "_End");
    if (!braced) expect("{", "'{' after End Site");
    Word w = in_.next("OFFSET in End Site");
    if (!sameWord(w.text, "OFFSET")) {
      throwMalformed(file_, linePosition(w.line),
                     "expected OFFSET in End Site, found " + shownWord(w.text));
    }
    skeleton_.joints[self].offset = readVector();
    expect("}", "'}' closing End Site");
  }

  // The joint's name is the rest of its line (names may contain spaces); a trailing '{'
  // opens the block.
  std::string nameAfter(const Word& keyword) {
    auto rest = in_.restOfLine();
    braceOpened_ = !rest.empty() && rest.back().text == "{";
    if (braceOpened_) rest.pop_back();
    if (rest.empty()) throwMalformed(file_, linePosition(keyword.line), "joint without a name");
    std::string name;
    for (const auto& w : rest) name += (name.empty() ? "" : " ") + std::string(w.text);
    return name;
  }

  int addPoint(const Word& keyword, int parent, bool endSite, std::string name) {
    if (static_cast<int>(skeleton_.joints.size()) >= kMaxPoints) {
      throwMalformed(file_, linePosition(keyword.line),
                     "more than " + std::to_string(kMaxPoints) + " joints");
    }
    // Labels must be unique for the joint mapping: "#2" etc. on repeats.
    std::string unique = name;
    for (int k = 2; names_.count(unique) != 0; ++k) unique = name + "#" + std::to_string(k);
    names_.insert(unique);
    BvhJoint joint;
    joint.name = unique;
    joint.parent = parent;
    joint.endSite = endSite;
    joint.line = keyword.line;
    skeleton_.joints.push_back(std::move(joint));
    return static_cast<int>(skeleton_.joints.size()) - 1;
  }

  Eigen::Vector3d readVector() {
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) {
      Word w = in_.next("an OFFSET coordinate");
      if (!parseFinite(w.text, v[k])) {
        throwMalformed(file_, linePosition(w.line), "bad OFFSET coordinate " + shownWord(w.text));
      }
    }
    return v;
  }

  void readChannels(int self) {
    Word countWord = in_.next("the CHANNELS count");
    long long count = 0;
    if (!parseCount(countWord.text, count) || count > 6) {
      throwMalformed(file_, linePosition(countWord.line),
                     "CHANNELS count " + shownWord(countWord.text) + " is not 0-6");
    }
    auto& joint = skeleton_.joints[self];
    joint.firstChannel = skeleton_.channelCount;
    for (long long k = 0; k < count; ++k) {
      Word w = in_.next("a channel name");
      auto channel = channelFromName(w.text);
      if (!channel) {
        throwMalformed(file_, linePosition(w.line), "unknown channel " + shownWord(w.text));
      }
      if (std::find(joint.channels.begin(), joint.channels.end(), *channel) !=
          joint.channels.end()) {
        throwMalformed(file_, linePosition(w.line), "channel " + shownWord(w.text) + " repeated");
      }
      joint.channels.push_back(*channel);
    }
    skeleton_.channelCount += static_cast<int>(count);
  }

  void expect(std::string_view token, std::string_view what) {
    Word w = in_.next(what);
    if (w.text != token) {
      throwMalformed(file_, linePosition(w.line),
                     "expected " + std::string(what) + ", found " + shownWord(w.text));
    }
  }

  WordCursor& in_;
  const std::string& file_;
  BvhSkeleton skeleton_;
  std::set<std::string> names_;
  bool braceOpened_ = false;
};

// [SECTION] Motion block

struct Motion {
  long long frames = 0;
  double frameTimeS = 0.0;
  std::vector<double> values;  // frames x channelCount, row-major
};

// "Frames: 317" / "Frame Time: .0083333": key and value around the ':' (spaces free).
bool splitHeader(std::string_view line, std::string& key, std::string_view& value) {
  const size_t colon = line.find(':');
  if (colon == std::string_view::npos) return false;
  key.clear();
  for (auto w : splitWords(line.substr(0, colon))) key += (key.empty() ? "" : " ") + toLower(w);
  value = trim(line.substr(colon + 1));
  return true;
}

size_t skipBlank(const std::vector<TextLine>& lines, size_t i) {
  while (i < lines.size() && trim(lines[i].text).empty()) ++i;
  return i;
}

std::string_view headerValue(const std::vector<TextLine>& lines, size_t& i,
                             const std::string& wantKey, const std::string& file) {
  i = skipBlank(lines, i);
  if (i >= lines.size()) {
    const int last = lines.empty() ? 1 : lines.back().number;
    throwMalformed(file, linePosition(last), "file ends before the '" + wantKey + ":' line");
  }
  std::string key;
  std::string_view value;
  if (!splitHeader(lines[i].text, key, value) || key != toLower(wantKey)) {
    throwMalformed(file, linePosition(lines[i].number),
                   "expected '" + wantKey + ": <value>', found " + shownWord(trim(lines[i].text)));
  }
  return value;
}

Motion readMotion(const std::vector<TextLine>& lines, size_t i, int channels,
                  std::string_view text, const std::string& file, std::vector<std::string>& warnings) {
  Motion m;
  std::string_view framesText = headerValue(lines, i, "Frames", file);
  const int framesLine = lines[i].number;
  if (!parseCount(framesText, m.frames) || m.frames == 0) {
    throwMalformed(file, linePosition(framesLine),
                   "Frames: " + shownWord(framesText) + " is not a positive whole number");
  }
  ++i;
  std::string_view timeText = headerValue(lines, i, "Frame Time", file);
  if (!parseFinite(timeText, m.frameTimeS) || m.frameTimeS <= 0.0) {
    throwMalformed(file, linePosition(lines[i].number),
                   "Frame Time: " + shownWord(timeText) + " is not a positive number of seconds");
  }
  ++i;
  // Every value needs at least one digit and one separator: bound the count by the text
  // left before allocating anything for it.
  const size_t bytesLeft =
      i < lines.size() ? text.size() - static_cast<size_t>(lines[i].text.data() - text.data()) : 0;
  const double maxFrames = (static_cast<double>(bytesLeft) + 2.0) / (2.0 * channels);
  if (static_cast<double>(m.frames) > maxFrames) {
    throwMalformed(file, linePosition(framesLine),
                   "Frames: " + std::to_string(m.frames) + " but the rest of the file holds at most " +
                       std::to_string(static_cast<long long>(maxFrames)) + " rows of " +
                       std::to_string(channels) + " channels");
  }
  m.values.assign(static_cast<size_t>(m.frames) * static_cast<size_t>(channels), 0.0);
  long long row = 0;
  long long extraRows = 0;
  for (; i < lines.size(); ++i) {
    auto words = splitWords(lines[i].text);
    if (words.empty()) continue;
    if (row == m.frames) {
      ++extraRows;
      continue;
    }
    if (static_cast<int>(words.size()) != channels) {
      throwMalformed(file, linePosition(lines[i].number),
                     "frame " + std::to_string(row + 1) + " has " + std::to_string(words.size()) +
                         " values, the hierarchy has " + std::to_string(channels) + " channels");
    }
    double* out = &m.values[static_cast<size_t>(row) * static_cast<size_t>(channels)];
    for (size_t k = 0; k < words.size(); ++k) {
      if (!parseFinite(words[k], out[k])) {
        throwMalformed(file, linePosition(lines[i].number, static_cast<int>(k + 1)),
                       "not a finite number: " + shownWord(words[k]));
      }
    }
    ++row;
  }
  if (row < m.frames) {
    const int last = lines.empty() ? 1 : lines.back().number;
    throwMalformed(file, linePosition(last),
                   "file ends after " + std::to_string(row) + " of the " +
                       std::to_string(m.frames) + " frames announced (truncated?)");
  }
  if (extraRows > 0) {
    warnings.push_back(std::to_string(extraRows) + " rows after the " + std::to_string(m.frames) +
                       " announced frames were ignored");
  }
  return m;
}

// [SECTION] Forward kinematics
int rotationAxis(Channel c) { return c == Channel::XRot ? 0 : c == Channel::YRot ? 1 : 2; }

// Global positions of every point for one motion row (nullptr: the rest pose, offsets
// only). `out` receives x,y,z per point in file units; `rotation` is scratch, one per joint.
void forwardKinematics(const BvhSkeleton& sk, const double* row, std::vector<Mat3>& rotation,
                       double* out) {
  const size_t n = sk.joints.size();
  rotation.resize(n);
  for (size_t j = 0; j < n; ++j) {
    const BvhJoint& joint = sk.joints[j];
    std::array<double, 3> t{joint.offset.x(), joint.offset.y(), joint.offset.z()};
    Mat3& r = rotation[j];
    r = joint.parent < 0 ? kIdentity3 : rotation[static_cast<size_t>(joint.parent)];
    const Mat3& parentR = r;  // read before the joint's own rotations are applied below
    double* o = out + 3 * j;
    if (row != nullptr) {
      for (size_t k = 0; k < joint.channels.size(); ++k) {
        const Channel c = joint.channels[k];
        if (!isRotation(c)) t[static_cast<size_t>(c) - static_cast<size_t>(Channel::XPos)] =
            row[joint.firstChannel + static_cast<int>(k)];
      }
    }
    if (joint.parent < 0) {
      o[0] = t[0], o[1] = t[1], o[2] = t[2];
    } else {
      const double* p = out + 3 * static_cast<size_t>(joint.parent);
      for (size_t a = 0; a < 3; ++a) {
        o[a] = p[a] + parentR[3 * a] * t[0] + parentR[3 * a + 1] * t[1] + parentR[3 * a + 2] * t[2];
      }
    }
    if (row == nullptr) continue;
    for (size_t k = 0; k < joint.channels.size(); ++k) {
      const Channel c = joint.channels[k];
      if (isRotation(c))
        postRotate(r, rotationAxis(c),
                   row[joint.firstChannel + static_cast<int>(k)] * std::numbers::pi / 180.0);
    }
  }
}

// [SECTION] CMU T-pose frame and units

double wrappedDegrees(double d) { return std::remainder(d, 360.0); }

// Hahne's CMU conversion puts a synthetic T-pose first: the root position copied from
// frame 2, (nearly) all rotations 0, and a jump to frame 2 far larger than any later step.
bool isSyntheticTPose(const BvhSkeleton& sk, const Motion& m, std::string& why) {
  if (m.frames < 3 || sk.joints.empty()) return false;
  const auto c = static_cast<size_t>(sk.channelCount);
  const double* f0 = m.values.data();
  const double* f1 = f0 + c;
  const double* f2 = f1 + c;
  const BvhJoint& root = sk.joints[0];
  int rootPositions = 0, rotations = 0, zeros = 0;
  double jump01 = 0.0, jump12 = 0.0;
  for (size_t k = 0; k < root.channels.size(); ++k) {
    if (isRotation(root.channels[k])) continue;
    const auto col = static_cast<size_t>(root.firstChannel) + k;
    if (std::abs(f0[col] - f1[col]) > 1e-6 * (1.0 + std::abs(f1[col]))) return false;
    ++rootPositions;
  }
  if (rootPositions == 0) return false;
  for (const BvhJoint& joint : sk.joints) {
    for (size_t k = 0; k < joint.channels.size(); ++k) {
      if (!isRotation(joint.channels[k])) continue;
      const auto col = static_cast<size_t>(joint.firstChannel) + k;
      ++rotations;
      if (f0[col] == 0.0) ++zeros;
      jump01 = std::max(jump01, std::abs(wrappedDegrees(f1[col] - f0[col])));
      jump12 = std::max(jump12, std::abs(wrappedDegrees(f2[col] - f1[col])));
    }
  }
  const double zeroShare = rotations > 0 ? static_cast<double>(zeros) / rotations : 0.0;
  if (zeroShare < 0.75 || jump01 < 5.0 || jump01 < 3.0 * jump12) return false;
  why = "root position equals frame 2, " + std::to_string(static_cast<int>(100 * zeroShare)) +
        " % of rotations are 0, and the step to frame 2 is " +
        std::to_string(static_cast<int>(jump01)) + " deg against " +
        std::to_string(static_cast<int>(std::ceil(jump12))) + " deg between frames 2 and 3";
  return true;
}

// Height of the root above the lowest point in the rest pose, +Y up. A skeleton whose
// rest pose is not standing along +Y (lying, Z-up) falls back to half its largest extent.
double restHipHeight(const BvhSkeleton& sk) {
  std::vector<double> rest(3 * sk.joints.size());
  std::vector<Mat3> scratch;
  forwardKinematics(sk, nullptr, scratch, rest.data());
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> p(
      rest.data(), static_cast<Eigen::Index>(sk.joints.size()), 3);
  const double hip = p(0, 1) - p.col(1).minCoeff();
  const double extent = (p.colwise().maxCoeff() - p.colwise().minCoeff()).maxCoeff();
  return hip >= 0.25 * extent ? hip : 0.5 * extent;
}

}  // namespace

BvhUnitGuess guessBvhLengthUnit(double hipHeightUnits) {
  const double h = hipHeightUnits;
  // Adult hip height 0.5-1.2 m in each unit; between the bands, the nearest unit.
  if (h < 3.0) return {"m", h >= 0.4 && h <= 1.3};
  if (h < 28.0) return {"cmu", h >= 8.0 && h <= 23.0};
  if (h < 300.0) return {"cm", h >= 40.0 && h <= 130.0};
  return {"mm", h >= 400.0 && h <= 1300.0};
}

RawTrial parseBvh(std::string_view text, const std::string& name, const LoadOptions& options) {
  const auto lines = splitLines(text);
  WordCursor cursor(lines, name);
  BvhSkeleton sk = HierarchyParser(cursor, name).parse();

  if (cursor.atEnd()) {
    throwMalformed(name, linePosition(cursor.lastLine()), "no MOTION block after the hierarchy");
  }
  Word motionWord = cursor.next("MOTION");
  if (!sameWord(motionWord.text, "MOTION")) {
    throwMalformed(name, linePosition(motionWord.line),
                   "expected MOTION after the hierarchy, found " + shownWord(motionWord.text));
  }
  if (!cursor.restOfLine().empty()) {
    throwMalformed(name, linePosition(motionWord.line), "text after MOTION on its line");
  }
  if (sk.channelCount == 0) {
    throwMalformed(name, linePosition(motionWord.line), "the hierarchy has no channels");
  }

  RawTrial out;
  out.file = name;
  out.format = "BVH";
  out.kind = PointKind::SkeletonJoints;
  out.upAxis = SignedAxis{1, 1};
  Motion motion = readMotion(lines, cursor.nextLineIndex(), sk.channelCount, text, name,
                             out.warnings);
  const auto points = static_cast<long long>(sk.joints.size());
  checkPointFrames(static_cast<double>(motion.frames), static_cast<double>(points),
                   skeletonPointFrameAllowance(text.size()), name, "MOTION");

  out.rateHz = options.rateHzOverride ? checkedRateOverrideHz(*options.rateHzOverride, name)
                                      : checkedFileRateHz(1.0 / motion.frameTimeS, name, "Frame Time");

  long long firstRow = 0;
  std::string why;
  if (isSyntheticTPose(sk, motion, why)) {
    firstRow = 1;
    out.firstFrame = 2;
    out.warnings.push_back("dropped frame 1, the CMU conversion's synthetic T-pose (" + why + ")");
  }

  double mmPerUnit = 1.0;
  if (options.unitsOverride) {
    out.units = *options.unitsOverride;
    mmPerUnit = unitToMm(out.units, name);
  } else {
    const double hip = restHipHeight(sk);
    const BvhUnitGuess guess = guessBvhLengthUnit(hip);
    out.units = guess.unit;
    mmPerUnit = unitToMm(guess.unit, name);
    char hipText[32];
    std::snprintf(hipText, sizeof hipText, "%.3g", hip);
    out.warnings.push_back(std::string("BVH states no length unit: assumed '") + guess.unit +
                           "' from the rest-pose hip height of " + hipText + " units" +
                           (guess.plausible ? "" : " (implausible for an adult in any unit)") +
                           "; set the units override if this is wrong");
  }

  for (const auto& joint : sk.joints) out.labels.push_back(joint.name);
  const auto frames = static_cast<Eigen::Index>(motion.frames - firstRow);
  // One row at a time into the result: the positions exist once in memory, not twice.
  out.positionsMm.resize(frames, 3 * points);
  Eigen::RowVectorXd framePoints(3 * points);
  std::vector<Mat3> scratch;
  for (Eigen::Index f = 0; f < frames; ++f) {
    const double* row =
        &motion.values[static_cast<size_t>(f + firstRow) * static_cast<size_t>(sk.channelCount)];
    forwardKinematics(sk, row, scratch, framePoints.data());
    out.positionsMm.row(f) = framePoints * mmPerUnit;
  }
  return out;
}

RawTrial readBvh(const std::filesystem::path& file, const LoadOptions& options) {
  return parseBvh(readFileText(file), file.string(), options);
}

}  // namespace ew
