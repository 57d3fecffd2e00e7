#include "core/io/c3d_writer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <set>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/gait/canonical_frame.h"
#include "core/gait/gait_events.h"
#include "core/io/atomic_write.h"
#include "core/io/c3d_reader.h"
#include "core/io/reader_limits.h"

namespace ew {
namespace {

// [SECTION] Little-endian words (processor type 84: Intel) -----------------------------

constexpr int kIntelProcessor = 84;
constexpr std::uint8_t kWrittenC3dKey = 0x50;
constexpr unsigned kFourCharEventKey = 12345;  // header word 150
constexpr long kMaxHeaderFrame = 65535;        // header words 4 and 5 are 16 bits
// A record's offset to the next one is a signed 16-bit word in the guide.
constexpr std::size_t kMaxRecordBytes = 32767;
constexpr std::size_t kMaxParameterBlocks = 255;  // the parameter section's block count is a byte

void putU8(std::string& out, unsigned v) { out.push_back(static_cast<char>(v & 0xFFu)); }

void putU16(std::string& out, unsigned v) {
  putU8(out, v);
  putU8(out, v >> 8);
}

void putF32(std::string& out, float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  putU16(out, bits & 0xFFFFu);
  putU16(out, bits >> 16);
}

void setU16(std::string& out, std::size_t at, unsigned v) {
  out[at] = static_cast<char>(v & 0xFFu);
  out[at + 1] = static_cast<char>((v >> 8) & 0xFFu);
}

void setF32(std::string& out, std::size_t at, float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  setU16(out, at, bits & 0xFFFFu);
  setU16(out, at + 2, bits >> 16);
}

// [SECTION] Parameter records -----------------------------------------------------------

// Builds the parameter section's records (C3D guide, "Parameter section"): a group is
// (name length, −id, name, offset to the next record, description); a parameter is (name
// length, group id, name, offset, type, dimension count, dimensions, values, description).
// The offset counts from its own first byte. The last record's offset is 0: the end.
class ParameterRecords {
 public:
  explicit ParameterRecords(const std::string& file) : file_(file) {}

  void group(int id, const std::string& name, const std::string& description) {
    currentGroup_ = id;
    currentGroupName_ = name;
    currentName_.clear();
    std::string body;
    putText(body, description);
    record(-id, name, body);
  }

  void int16(const std::string& name, unsigned value) { int16s(name, {value}, {}); }

  void int16s(const std::string& name, const std::vector<unsigned>& values,
              const std::vector<std::size_t>& dims) {
    std::string body = typeAndDims(name, 2, dims);
    for (unsigned v : values) putU16(body, v);
    parameter(name, body);
  }

  void float32(const std::string& name, float value) { floats(name, {value}, {}); }

  void floats(const std::string& name, const std::vector<float>& values,
              const std::vector<std::size_t>& dims) {
    std::string body = typeAndDims(name, 4, dims);
    for (float v : values) putF32(body, v);
    parameter(name, body);
  }

  void bytes(const std::string& name, const std::vector<unsigned>& values) {
    std::string body = typeAndDims(name, 1, {values.size()});
    for (unsigned v : values) putU8(body, v);
    parameter(name, body);
  }

  // One string: dimensions [length].
  void text(const std::string& name, const std::string& value) {
    std::string body = typeAndDims(name, -1, {std::max<std::size_t>(value.size(), 1)});
    body += value.empty() ? std::string(" ") : value;
    parameter(name, body);
  }

  // n strings padded with spaces to the longest: dimensions [width, n].
  void texts(const std::string& name, const std::vector<std::string>& values) {
    std::size_t width = 1;
    for (const auto& v : values) width = std::max(width, v.size());
    std::string body = typeAndDims(name, -1, {width, values.size()});
    for (const auto& v : values) body += v + std::string(width - v.size(), ' ');
    parameter(name, body);
  }

  // The records, the last one's offset set to 0.
  std::string finish() {
    if (lastOffsetAt_) setU16(records_, *lastOffsetAt_, 0);
    return records_;
  }

 private:
  std::string typeAndDims(const std::string& name, int type, const std::vector<std::size_t>& dims) {
    currentName_ = name;
    std::string body;
    putU8(body, static_cast<unsigned>(static_cast<std::uint8_t>(static_cast<std::int8_t>(type))));
    putU8(body, static_cast<unsigned>(dims.size()));
    for (std::size_t d : dims) {
      if (d > 255) tooLarge("a dimension of " + std::to_string(d) + " (C3D's limit is 255)");
      putU8(body, static_cast<unsigned>(d));
    }
    return body;
  }

  void parameter(const std::string& name, std::string body) {
    putText(body, "");  // no description
    record(currentGroup_, name, body);
  }

  static void putText(std::string& out, const std::string& text) {
    putU8(out, static_cast<unsigned>(text.size()));
    out += text;
  }

  void record(int id, const std::string& name, const std::string& body) {
    const std::size_t offset = 2 + body.size();
    if (offset > kMaxRecordBytes)
      tooLarge(std::to_string(offset) + " bytes (C3D's offset word reaches " +
               std::to_string(kMaxRecordBytes) + ")");
    putU8(records_, static_cast<unsigned>(name.size()));
    putU8(records_, static_cast<unsigned>(static_cast<std::uint8_t>(static_cast<std::int8_t>(id))));
    records_ += name;
    lastOffsetAt_ = records_.size();
    putU16(records_, static_cast<unsigned>(offset));
    records_ += body;
  }

  [[noreturn]] void tooLarge(const std::string& what) const {
    const std::string where = currentName_.empty() ? "group " + currentGroupName_
                                                   : "parameter " + currentGroupName_ + ":" + currentName_;
    throw Error(ErrorKind::BadArgument, file_, where, "holds " + what);
  }

  const std::string& file_;
  std::string records_;
  int currentGroup_ = 0;
  std::string currentGroupName_, currentName_;
  std::optional<std::size_t> lastOffsetAt_;
};

// [SECTION] Checks ---------------------------------------------------------------------

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& position,
                         const std::string& problem) {
  throw Error(ErrorKind::BadArgument, file.string(), position, problem);
}

bool printableAscii(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
}

// Free text (descriptions, notes) may be UTF-8, as the guide allows; no control characters.
bool freeText(const std::string& s) {
  return std::none_of(s.begin(), s.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7F;
  });
}

// A text C3D pads with spaces and readers trim: it must come back as it went in. Labels are
// names readers match: printable ASCII; descriptions (mayBeEmpty) may be UTF-8.
void checkText(const std::filesystem::path& file, const std::string& position,
               const std::string& what, const std::string& s, bool isLabel) {
  if (s.empty() && isLabel) refuse(file, position, what + " is empty");
  if (s.size() > kC3dMaxTextChars)
    refuse(file, position,
           what + " has " + std::to_string(s.size()) + " characters; C3D holds at most " +
               std::to_string(kC3dMaxTextChars) + " (a parameter dimension is one byte)");
  if (isLabel ? !printableAscii(s) : !freeText(s))
    refuse(file, position,
           what + (isLabel ? " has a character that is not printable ASCII"
                           : " has a control character"));
  if (!s.empty() && (s.front() == ' ' || s.back() == ' '))
    refuse(file, position,
           what + " '" + s + "' begins or ends with a space, which C3D's space-padded text loses");
}

long checkPoints(const std::filesystem::path& file, const C3dContent& c) {
  if (c.points.empty()) refuse(file, "", "no points to write");
  if (c.points.size() > kC3dMaxPoints)
    refuse(file, "POINT:LABELS",
           std::to_string(c.points.size()) + " points; C3D's POINT:LABELS names at most " +
               std::to_string(kC3dMaxPoints));
  const Eigen::Index frames = c.points.front().positionsMm.rows();
  if (frames < 1) refuse(file, "", "no frames to write");
  if (frames > kC3dMaxFrames)
    refuse(file, "POINT:FRAMES",
           std::to_string(frames) + " frames; C3D's float frame count holds at most " +
               std::to_string(kC3dMaxFrames) + " exactly");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const C3dPointTrajectory& p = c.points[i];
    const std::string where = "point " + std::to_string(i + 1);
    checkText(file, where, "the label", p.label, true);
    checkText(file, where, "the description", p.description, false);
    if (!seen.insert(p.label).second) refuse(file, where, "the label '" + p.label + "' is used twice");
    if (p.positionsMm.rows() != frames)
      refuse(file, where + " (" + p.label + ")",
             std::to_string(p.positionsMm.rows()) + " frames where point 1 has " +
                 std::to_string(frames));
    for (Eigen::Index r = 0; r < frames; ++r)
      for (int a = 0; a < 3; ++a) {
        const double v = p.positionsMm(r, a);
        if (std::isfinite(v) && std::abs(v) > std::numeric_limits<float>::max())
          refuse(file, where + " (" + p.label + "), frame " + std::to_string(r + 1),
                 "coordinate " + std::to_string(v) + " mm is beyond a 32-bit float");
      }
  }
  return static_cast<long>(frames);
}

void checkContent(const std::filesystem::path& file, const C3dContent& c) {
  if (!std::isfinite(c.rateHz) || c.rateHz < kMinFrameRateHz || c.rateHz > kMaxFrameRateHz)
    refuse(file, "POINT:RATE",
           "frame rate " + std::to_string(c.rateHz) + " Hz is not one a capture has (" +
               std::to_string(static_cast<int>(kMinFrameRateHz)) + "–" +
               std::to_string(static_cast<int>(kMaxFrameRateHz)) + " Hz)");
  if (c.events.size() > kC3dMaxEvents)
    refuse(file, "EVENT:TIMES",
           std::to_string(c.events.size()) + " events; C3D's EVENT:TIMES holds at most " +
               std::to_string(kC3dMaxEvents));
  for (std::size_t i = 0; i < c.events.size(); ++i) {
    const GaitEvent& e = c.events[i];
    const std::string where = "event " + std::to_string(i + 1);
    if (!std::isfinite(e.timeS) || e.timeS < 0)
      refuse(file, where, "time " + std::to_string(e.timeS) + " s is not a time from the first frame");
    if (!e.label.empty()) checkText(file, where, "the label", e.label, true);
  }
  checkText(file, "EVENT:DESCRIPTIONS", "the event description", c.eventDescription, false);
  for (const auto* axis : {&c.xScreen, &c.yScreen}) {
    const std::string& s = *axis;
    if (s.size() != 2 || (s[0] != '+' && s[0] != '-') || s[1] < 'X' || s[1] > 'Z')
      refuse(file, "POINT:X_SCREEN", "screen axis '" + s + "' is not +X, -Y, …");
  }
  if (c.xScreen[1] == c.yScreen[1])
    refuse(file, "POINT:Y_SCREEN", "X_SCREEN and Y_SCREEN name the same axis " + c.xScreen);
  for (const auto& line : c.notes)
    if (!freeText(line)) refuse(file, "MANUFACTURER:NOTES", "a note has a control character");
}

// [SECTION] Parameters ------------------------------------------------------------------

std::string eventLabel(const GaitEvent& e) {
  if (!e.label.empty()) return e.label;
  if (e.type == GaitEventType::FootStrike) return "Foot Strike";
  if (e.type == GaitEventType::FootOff) return "Foot Off";
  return "Event";
}

unsigned eventIcon(const GaitEvent& e) {
  if (e.type == GaitEventType::FootStrike) return 1;
  if (e.type == GaitEventType::FootOff) return 2;
  return 0;
}

// Lines cut to C3D's 255 bytes, never inside a UTF-8 character; at most 255 of them.
std::vector<std::string> noteLines(const std::vector<std::string>& notes) {
  auto continuation = [](char c) { return (static_cast<unsigned char>(c) & 0xC0u) == 0x80u; };
  std::vector<std::string> lines;
  for (const auto& note : notes) {
    std::size_t at = 0;
    do {
      std::size_t end = std::min(note.size(), at + kC3dMaxTextChars);
      while (end < note.size() && end > at + 1 && continuation(note[end])) --end;
      lines.push_back(note.substr(at, end - at));
      at = end;
    } while (at < note.size());
  }
  if (lines.size() > 255) lines.resize(255);
  return lines;
}

// Two 16-bit words, low first (the guide's TRIAL fields; it writes the high word's weight
// as 65535, a slip for the 65536 of a 32-bit number, which Vicon's files and our reader use).
std::vector<unsigned> twoWords(long v) {
  const auto u = static_cast<std::uint32_t>(v);
  return {u & 0xFFFFu, u >> 16};
}

std::string parameterRecords(const std::filesystem::path& file, const C3dContent& c, long frames,
                             unsigned dataBlock) {
  const std::string name = file.string();
  ParameterRecords p(name);
  const bool longTrial = frames > kMaxHeaderFrame;
  const auto rate = static_cast<float>(c.rateHz);
  p.group(1, "POINT", "3D point parameters");
  p.int16("USED", static_cast<unsigned>(c.points.size()));
  p.float32("SCALE", -1.0f);
  p.float32("RATE", rate);
  if (longTrial) p.float32("FRAMES", static_cast<float>(frames));
  else p.int16("FRAMES", static_cast<unsigned>(frames));
  if (longTrial) p.float32("LONG_FRAMES", static_cast<float>(frames));
  p.int16("DATA_START", dataBlock);
  p.text("UNITS", "mm");
  std::vector<std::string> labels, descriptions;
  for (const auto& point : c.points) {
    labels.push_back(point.label);
    descriptions.push_back(point.description);
  }
  p.texts("LABELS", labels);
  p.texts("DESCRIPTIONS", descriptions);
  p.text("X_SCREEN", c.xScreen);
  p.text("Y_SCREEN", c.yScreen);
  p.group(2, "ANALOG", "analog data parameters");
  p.int16("USED", 0);
  p.float32("RATE", rate);
  p.group(3, "TRIAL", "the frame range as 32-bit numbers");
  p.int16s("ACTUAL_START_FIELD", twoWords(1), {2});
  p.int16s("ACTUAL_END_FIELD", twoWords(frames), {2});
  p.float32("CAMERA_RATE", rate);
  p.group(4, "EVENT", "gait events");
  p.int16("USED", static_cast<unsigned>(c.events.size()));
  if (!c.events.empty()) {
    std::vector<std::string> contexts, eventLabels, eventDescriptions;
    std::vector<float> times;
    std::vector<unsigned> icons, flags;
    for (const auto& e : c.events) {
      contexts.push_back(e.side == Side::Right ? "Right" : "Left");
      eventLabels.push_back(eventLabel(e));
      eventDescriptions.push_back(c.eventDescription);
      const double minutes = std::floor(e.timeS / 60.0);
      times.push_back(static_cast<float>(minutes));
      times.push_back(static_cast<float>(e.timeS - 60.0 * minutes));
      icons.push_back(eventIcon(e));
      flags.push_back(0);
    }
    p.texts("CONTEXTS", contexts);
    p.texts("LABELS", eventLabels);
    p.texts("DESCRIPTIONS", eventDescriptions);
    p.floats("TIMES", times, {2, c.events.size()});
    p.int16s("ICON_IDS", icons, {c.events.size()});
    p.bytes("GENERIC_FLAGS", flags);
  }
  p.group(5, "MANUFACTURER", "the program that wrote the file");
  p.text("COMPANY", "Eigenwalker");
  p.text("SOFTWARE", "eigenwalker (core/io/c3d_writer)");
  if (!c.notes.empty()) p.texts("NOTES", noteLines(c.notes));
  return p.finish();
}

// The parameter section: its 4-byte header (two reserved bytes as Vicon writes them, the
// block count, the processor type) and the records, padded to whole blocks.
std::string parameterSection(const std::filesystem::path& file, const C3dContent& c, long frames) {
  // The data block depends on the section's size, whose records hold it in a fixed-size
  // word: build once to measure, then again with the right block.
  std::string records = parameterRecords(file, c, frames, 0);
  const std::size_t blocks = (4 + records.size() + kC3dBlockBytes - 1) / kC3dBlockBytes;
  if (blocks > kMaxParameterBlocks)
    refuse(file, "parameter section",
           std::to_string(blocks) + " blocks of parameters; C3D's block count reaches " +
               std::to_string(kMaxParameterBlocks));
  records = parameterRecords(file, c, frames, static_cast<unsigned>(2 + blocks));
  std::string section;
  putU8(section, 1);
  putU8(section, kWrittenC3dKey);
  putU8(section, static_cast<unsigned>(blocks));
  putU8(section, kIntelProcessor);
  section += records;
  section.resize(blocks * kC3dBlockBytes, '\0');
  return section;
}

// [SECTION] Header and data -------------------------------------------------------------

// The 512-byte header (words are 1-based in the guide; byte = 2 × (word − 1)).
std::string headerBlock(const C3dContent& c, long frames, std::size_t parameterBlocks) {
  std::string h(kC3dBlockBytes, '\0');
  h[0] = 2;  // parameters start in block 2
  h[1] = static_cast<char>(kWrittenC3dKey);
  setU16(h, 2, static_cast<unsigned>(c.points.size()));                     // word 2
  setU16(h, 4, 0);                                                          // word 3: analog values a frame
  setU16(h, 6, 1);                                                          // word 4: first frame
  setU16(h, 8, static_cast<unsigned>(std::min(frames, kMaxHeaderFrame)));  // word 5: last frame
  setU16(h, 10, 0);                                                         // word 6: interpolation gap
  setF32(h, 12, -1.0f);                                                     // words 7-8: scale, REAL
  setU16(h, 16, static_cast<unsigned>(2 + parameterBlocks));                // word 9: data block
  setU16(h, 18, 0);                                                         // word 10: analog samples a frame
  setF32(h, 20, static_cast<float>(c.rateHz));                              // words 11-12
  setU16(h, 2 * (150 - 1), kFourCharEventKey);                              // 4-char event labels
  setU16(h, 2 * (151 - 1), 0);                                              // header events: none
  return h;
}

void writeFrames(std::ostream& out, const C3dContent& c, long frames) {
  std::string row;
  row.reserve(16 * c.points.size());
  for (long f = 0; f < frames; ++f) {
    row.clear();
    for (const auto& p : c.points) {
      const Eigen::RowVector3d v = p.positionsMm.row(f);
      const bool valid = v.allFinite();
      for (int a = 0; a < 3; ++a) putF32(row, valid ? static_cast<float>(v[a]) : 0.0f);
      putF32(row, valid ? 0.0f : -1.0f);
    }
    out.write(row.data(), static_cast<std::streamsize>(row.size()));
  }
}

// [SECTION] The walker's axes and events ----------------------------------------------

std::string axisName(int axis, int sign) {
  return std::string(sign < 0 ? "-" : "+") + static_cast<char>('X' + axis);
}

struct WalkerAxes {
  std::string forward = "+Y", up = "+Z";
  Eigen::MatrixXd canonical;  // the frames turned to z up, facing +y (empty: not finite)
  Eigen::MatrixXd canonicalFeet;  // the feet turned with them (empty without feet)
};

// Up is the body's (head over ankles), forward the horizontal axis closest to the facing
// direction; both default to the canonical frame's when a sample is missing. The feet
// (T × 12, or empty) are turned with the joints.
WalkerAxes walkerAxes(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, const Eigen::MatrixXd& feetX12) {
  WalkerAxes axes;
  if (framesX45.rows() == 0 || !framesX45.allFinite()) return axes;
  const bool feet = feetX12.rows() == framesX45.rows() && feetX12.cols() == kFootDims3;
  Eigen::MatrixXd m(framesX45.rows(), kDims3 + (feet ? kFootDims3 : 0));
  if (feet)
    m << framesX45, feetX12;
  else
    m = framesX45;
  const SignedAxis up = detectUpAxis(m);
  const Eigen::Matrix3d toZUp = rotationToZUp(up);
  rotateFrames(m, toZUp);
  const Eigen::Vector2d facing = facingDirection(m);
  rotateFacingToY(m);
  if (feet) axes.canonicalFeet = m.rightCols(kFootDims3);
  axes.canonical = m.leftCols(kDims3);
  axes.up = axisName(up.axis, up.sign);
  if (facing.isZero()) return axes;
  const Eigen::Vector3d forward = toZUp.transpose() * Eigen::Vector3d(facing.x(), facing.y(), 0.0);
  Eigen::Index axis = 0;
  Eigen::Vector3d score = forward.cwiseAbs();
  score[up.axis] = -1.0;
  score.maxCoeff(&axis);
  axes.forward = axisName(static_cast<int>(axis), forward[axis] >= 0 ? 1 : -1);
  return axes;
}

std::vector<GaitEvent> eventList(const GaitEventSet& set) {
  std::vector<GaitEvent> events;
  for (Side side : {Side::Right, Side::Left}) {
    const FootEvents& foot = set.of(side);
    for (double t : foot.strikesS) events.push_back({side, GaitEventType::FootStrike, t, "Foot Strike"});
    for (double t : foot.offsS) events.push_back({side, GaitEventType::FootOff, t, "Foot Off"});
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const GaitEvent& a, const GaitEvent& b) { return a.timeS < b.timeS; });
  return events;
}

}  // namespace

// [SECTION] Public entry points --------------------------------------------------------

void writeC3d(const std::filesystem::path& file, const C3dContent& content) {
  checkContent(file, content);
  const long frames = checkPoints(file, content);
  const std::string parameters = parameterSection(file, content, frames);
  const std::string header = headerBlock(content, frames, parameters.size() / kC3dBlockBytes);
  writeFileAtomically(file, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(parameters.data(), static_cast<std::streamsize>(parameters.size()));
    writeFrames(out, content, frames);
    // The data section ends on a block boundary, as the guide's files do.
    const std::size_t dataBytes = static_cast<std::size_t>(frames) * 16 * content.points.size();
    const std::size_t pad = (kC3dBlockBytes - dataBytes % kC3dBlockBytes) % kC3dBlockBytes;
    out.write(std::string(pad, '\0').data(), static_cast<std::streamsize>(pad));
  });
}

std::vector<C3dPointTrajectory> jointPointTrajectories(
    const Eigen::Ref<const Eigen::MatrixXd>& framesX45, const std::string& description) {
  if (framesX45.cols() != kDims3)
    throw Error(ErrorKind::BadArgument, "", "",
                "a walker has 45 columns (15 joints), not " + std::to_string(framesX45.cols()));
  std::vector<C3dPointTrajectory> points;
  for (int j = 0; j < kJointCount; ++j)
    points.push_back({std::string(kJointNames[static_cast<std::size_t>(j)]), description,
                      framesX45.middleCols<3>(3 * j)});
  return points;
}

void writeWalkerC3d(const std::filesystem::path& file,
                    const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                    const std::vector<std::string>& notes,
                    const std::vector<C3dPointTrajectory>& extraPoints) {
  writeWalkerWithFeetC3d(file, framesX45, Eigen::MatrixXd(), rateHz, notes, extraPoints);
}

std::vector<C3dPointTrajectory> footPointTrajectories(const Eigen::MatrixXd& feetX12,
                                                      const std::string& description) {
  std::vector<C3dPointTrajectory> points;
  if (feetX12.cols() != kFootDims3) return points;
  for (int p = 0; p < kFootPointCount; ++p) {
    if (!feetX12.middleCols<3>(3 * p).array().isFinite().any()) continue;
    points.push_back({std::string(kFootPointNames[static_cast<std::size_t>(p)]), description,
                      feetX12.middleCols<3>(3 * p)});
  }
  return points;
}

void writeWalkerWithFeetC3d(const std::filesystem::path& file,
                            const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                            const Eigen::MatrixXd& feetX12, double rateHz,
                            const std::vector<std::string>& notes,
                            const std::vector<C3dPointTrajectory>& extraPoints, bool feetInSagittalPlanes) {
  if (framesX45.cols() != kDims3)
    refuse(file, "", "expected 45 columns, got " + std::to_string(framesX45.cols()));
  const bool feet = feetX12.rows() == framesX45.rows() && feetX12.cols() == kFootDims3;
  C3dContent c;
  c.rateHz = rateHz;
  c.points = jointPointTrajectories(framesX45, "eigenwalker joint centre");
  if (feet) {
    const auto feetPoints = footPointTrajectories(
        feetX12, feetInSagittalPlanes ? std::string(kSagittalFootDescription) : std::string("the input's heel or toe point"));
    c.points.insert(c.points.end(), feetPoints.begin(), feetPoints.end());
  }
  c.points.insert(c.points.end(), extraPoints.begin(), extraPoints.end());
  c.notes = notes;
  const WalkerAxes axes = walkerAxes(framesX45, feet ? feetX12 : Eigen::MatrixXd());
  c.xScreen = axes.forward;
  c.yScreen = axes.up;
  if (axes.canonical.rows() > 0 && std::isfinite(rateHz) && rateHz > 0) {
    const GaitEventSet events = gaitEventsFromFeet(axes.canonical, axes.canonicalFeet, rateHz);
    c.events = eventList(events);
    c.eventDescription = events.method == "kinematics"
                             ? "from the ankle's lead on the pelvis (Zeni et al. 2008; docs/GAIT.md)"
                             : "from the heel's and the toe's lead on the pelvis (Zeni et al. 2008; docs/GAIT.md)";
  } else {
    c.notes.push_back("no gait events: a joint sample is missing");
  }
  if (c.events.size() > kC3dMaxEvents) {
    c.notes.push_back(std::to_string(c.events.size() - kC3dMaxEvents) + " gait events after " +
                      std::to_string(c.events[kC3dMaxEvents - 1].timeS) +
                      " s not written: C3D's EVENT:TIMES holds " + std::to_string(kC3dMaxEvents));
    c.events.resize(kC3dMaxEvents);
  }
  writeC3d(file, c);
}

}  // namespace ew
