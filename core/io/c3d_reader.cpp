#include "core/io/c3d_reader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/reader_limits.h"

// Layout notes (C3D User Guide, c3d.org): the file is a sequence of 512-byte blocks.
// Block 1 is the header: byte 0 = first parameter block (1-based), byte 1 = 0x50.
// The parameter section starts with 4 bytes (reserved, reserved, block count,
// 83 + processor type) followed by group and parameter records chained by offsets.
// The data section holds, per frame, 4 values per point (x, y, z, residual word) then
// the frame's analog samples; values are int16 (INT, POINT:SCALE > 0) or 32-bit floats
// (REAL, POINT:SCALE < 0) in the processor's byte order and float format.

namespace ew {
namespace {

// [SECTION] Bounds-checked byte access ------------------------------------------------

enum class Processor { Intel = 84, Dec = 85, Mips = 86 };

std::string bytePosition(std::size_t at) { return "byte " + std::to_string(at); }

// Every read goes through here: an offset past the end throws Malformed with the position,
// so no code below can read outside the buffer.
class C3dBytes {
 public:
  C3dBytes(std::span<const std::uint8_t> bytes, const std::string& name)
      : bytes_(bytes), name_(name) {}

  std::size_t size() const { return bytes_.size(); }
  const std::string& name() const { return name_; }
  void setProcessor(Processor p) { processor_ = p; }
  Processor processor() const { return processor_; }

  // Throws unless [at, at + count) lies inside the file.
  // `what` is a view: this runs for every value read, so nothing is built unless it throws.
  void require(std::size_t at, std::size_t count, std::string_view what) const {
    if (at > bytes_.size() || count > bytes_.size() - at) {
      throwMalformed(name_, bytePosition(at),
                     "file ends at byte " + std::to_string(bytes_.size()) + " inside " +
                         std::string(what) +
                         " (" + std::to_string(count) + " bytes needed): truncated or corrupt");
    }
  }

  std::uint8_t u8(std::size_t at) const {
    require(at, 1, "a byte field");
    return bytes_[at];
  }
  std::int8_t i8(std::size_t at) const { return static_cast<std::int8_t>(u8(at)); }

  std::uint16_t u16(std::size_t at) const {
    require(at, 2, "a 16-bit field");
    const unsigned lo = bytes_[at], hi = bytes_[at + 1];
    // DEC and Intel store integers little-endian; MIPS/SGI big-endian.
    const unsigned v = processor_ == Processor::Mips ? (lo << 8) | hi : (hi << 8) | lo;
    return static_cast<std::uint16_t>(v);
  }
  std::int16_t i16(std::size_t at) const { return static_cast<std::int16_t>(u16(at)); }

  float f32(std::size_t at) const {
    require(at, 4, "a 32-bit float");
    const std::uint8_t* p = bytes_.data() + at;
    if (processor_ == Processor::Dec) return decodeVaxFloat(p);
    std::uint32_t bits = 0;
    if (processor_ == Processor::Mips) {
      bits = (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
             (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
    } else {
      bits = (std::uint32_t{p[3]} << 24) | (std::uint32_t{p[2]} << 16) |
             (std::uint32_t{p[1]} << 8) | std::uint32_t{p[0]};
    }
    return std::bit_cast<float>(bits);
  }

  std::string text(std::size_t at, std::size_t count) const {
    require(at, count, "a text field");
    return std::string(reinterpret_cast<const char*>(bytes_.data() + at), count);
  }

 private:
  std::span<const std::uint8_t> bytes_;
  const std::string& name_;
  Processor processor_ = Processor::Intel;
};

std::string trimLabel(const std::string& s) {
  std::size_t b = 0, e = s.size();
  auto blank = [](char c) { return c == ' ' || c == '\0' || c == '\t' || c == '\r' || c == '\n'; };
  while (b < e && blank(s[b])) ++b;
  while (e > b && blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Labels go into error messages and the UI: keep them printable.
std::string printable(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return out;
}

// [SECTION] Header --------------------------------------------------------------------

struct C3dHeader {
  std::size_t parameterBlock = 0;  // 1-based block number
  unsigned points = 0;             // word 2
  unsigned analogPerFrame = 0;     // word 3: channels x samples per point frame
  long firstFrame = 0;             // word 4
  long lastFrame = 0;              // word 5
  float scale = 0.0f;              // words 7-8
  std::size_t dataBlock = 0;       // word 9
  float rateHz = 0.0f;             // words 11-12
};

constexpr std::uint8_t kC3dKey = 0x50;

// First pass: only the bytes that do not depend on the processor type.
std::size_t parameterStart(const C3dBytes& b) {
  if (b.size() == 0) throwMalformed(b.name(), "byte 0", "file is empty: not a C3D file");
  if (b.size() < kC3dBlockBytes) {
    throwMalformed(b.name(), bytePosition(b.size()),
                   "file is " + std::to_string(b.size()) +
                       " bytes, shorter than the 512-byte C3D header: truncated or not C3D");
  }
  if (b.u8(1) != kC3dKey) {
    throwMalformed(b.name(), "byte 1",
                   "not a C3D file: the header key is " + std::to_string(b.u8(1)) +
                       ", C3D files have 80 (0x50) here");
  }
  const std::size_t block = b.u8(0);
  if (block < 2) {
    throwMalformed(b.name(), "byte 0",
                   "parameter section pointer is block " + std::to_string(block) +
                       " (must be 2 or later: block 1 is the header)");
  }
  const std::size_t start = (block - 1) * kC3dBlockBytes;
  b.require(start, 4, "the parameter section (header points to block " + std::to_string(block) +
                          ")");
  return start;
}

Processor readProcessor(const C3dBytes& b, std::size_t paramStart) {
  const int code = b.u8(paramStart + 3);
  if (code == 84) return Processor::Intel;
  if (code == 85) return Processor::Dec;
  if (code == 86) return Processor::Mips;
  throw Error(ErrorKind::Unsupported, b.name(), bytePosition(paramStart + 3),
              "unknown C3D processor type " + std::to_string(code) +
                  " (expected 84 Intel, 85 DEC or 86 MIPS/SGI)");
}

C3dHeader readHeader(const C3dBytes& b) {
  C3dHeader h;
  h.parameterBlock = b.u8(0);
  h.points = b.u16(2);
  h.analogPerFrame = b.u16(4);
  h.firstFrame = b.u16(6);
  h.lastFrame = b.u16(8);
  h.scale = b.f32(12);
  h.dataBlock = b.u16(16);
  h.rateHz = b.f32(20);
  return h;
}

// [SECTION] Parameter section ---------------------------------------------------------

struct C3dParameter {
  std::string fullName;  // "GROUP:NAME", upper case
  int type = 0;          // -1 char, 1 byte, 2 int16, 4 float
  std::vector<std::size_t> dims;
  std::size_t dataAt = 0;  // absolute byte offset of the values
  std::size_t count = 0;   // number of elements (product of dims; 1 for a scalar)
};

using C3dParameters = std::map<std::string, C3dParameter>;

// The C3D guide allows up to 7 dimensions; anything more is a corrupt record.
constexpr std::size_t kMaxParameterDims = 7;

struct RawParameter {
  int groupId = 0;
  std::string name;
  C3dParameter value;
};

// Reads one parameter's type, dimensions and data extent starting at `at` (just after
// the next-record offset word). Checks the data fits in the file before anything uses it.
C3dParameter readParameterBody(const C3dBytes& b, std::size_t at, const std::string& where) {
  C3dParameter p;
  p.type = b.i8(at);
  if (p.type != -1 && p.type != 1 && p.type != 2 && p.type != 4) {
    throwMalformed(b.name(), where + " (" + bytePosition(at) + ")",
                   "invalid data type " + std::to_string(p.type) + " (expected -1, 1, 2 or 4)");
  }
  const std::size_t nDims = b.u8(at + 1);
  if (nDims > kMaxParameterDims) {
    throwMalformed(b.name(), where + " (" + bytePosition(at + 1) + ")",
                   std::to_string(nDims) + " dimensions (the C3D limit is 7)");
  }
  b.require(at + 2, nDims, where + " dimensions");
  std::size_t elements = 1;
  for (std::size_t d = 0; d < nDims; ++d) {
    p.dims.push_back(b.u8(at + 2 + d));
    elements *= p.dims.back();  // at most 255^7 < 2^56: no overflow
  }
  p.dataAt = at + 2 + nDims;
  p.count = elements;
  const std::size_t width = static_cast<std::size_t>(std::abs(p.type));
  if (elements > (b.size() - std::min(b.size(), p.dataAt)) / width) {
    throwMalformed(b.name(), where + " (" + bytePosition(p.dataAt) + ")",
                   "dimensions ask for " + std::to_string(elements) + " values of " +
                       std::to_string(width) + " bytes, past the end of the file");
  }
  return p;
}

C3dParameters readParameters(const C3dBytes& b, std::size_t start,
                             std::vector<std::string>& warnings) {
  const std::size_t declaredBlocks = b.u8(start + 2);
  // Records must lie in the declared blocks; a zero count (seen in old writers) means
  // "until the chain ends", bounded by the file.
  std::size_t end = b.size();
  if (declaredBlocks > 0 && declaredBlocks * kC3dBlockBytes <= b.size() - start) {
    end = start + declaredBlocks * kC3dBlockBytes;
  }
  std::map<int, std::string> groups;
  std::vector<RawParameter> raw;
  std::size_t pos = start + 4;
  while (pos + 2 <= end) {
    const int nameLen = std::abs(int{b.i8(pos)});  // negative = locked
    const int id = b.i8(pos + 1);
    if (nameLen == 0 || id == 0) break;  // end of the chain
    const std::size_t offsetAt = pos + 2 + static_cast<std::size_t>(nameLen);
    b.require(pos + 2, static_cast<std::size_t>(nameLen) + 2, "a parameter record name");
    const std::string name = upper(trimLabel(b.text(pos + 2, static_cast<std::size_t>(nameLen))));
    const std::size_t offset = b.u16(offsetAt);  // forward only: no loops possible
    if (id < 0) {
      groups.emplace(-id, name);
    } else {
      RawParameter r;
      r.groupId = id;
      r.name = name;
      r.value = readParameterBody(b, offsetAt + 2,
                                  "parameter " + printable(name) + " at " + bytePosition(pos));
      raw.push_back(std::move(r));
    }
    if (offset == 0) break;
    pos = offsetAt + offset;
  }
  C3dParameters params;
  for (auto& r : raw) {
    auto g = groups.find(r.groupId);
    if (g == groups.end()) {
      warnings.push_back("parameter " + printable(r.name) + " belongs to undefined group " +
                         std::to_string(r.groupId) + ": ignored");
      continue;
    }
    r.value.fullName = g->second + ":" + r.name;
    params.emplace(r.value.fullName, std::move(r.value));  // first definition wins
  }
  return params;
}

// [SECTION] Parameter values ----------------------------------------------------------

const C3dParameter* findParameter(const C3dParameters& params, const std::string& fullName) {
  auto it = params.find(fullName);
  return it == params.end() ? nullptr : &it->second;
}

std::string parameterPosition(const C3dParameter& p) { return "parameter " + p.fullName; }

// Element i as a number; int16 is read signed (callers that want a count use
// parameterCount). Throws when the parameter is text or too short.
double parameterNumber(const C3dBytes& b, const C3dParameter& p, std::size_t i = 0) {
  if (i >= p.count || p.type == -1) {
    throwMalformed(b.name(), parameterPosition(p),
                   p.type == -1 ? "is text, a number was expected"
                                : "has " + std::to_string(p.count) + " values, value " +
                                      std::to_string(i + 1) + " was needed");
  }
  const std::size_t width = static_cast<std::size_t>(std::abs(p.type));
  const std::size_t at = p.dataAt + i * width;
  if (p.type == 1) return b.u8(at);
  if (p.type == 2) return b.i16(at);
  return b.f32(at);
}

// Counts (POINT:USED, FRAMES, DATA_START, …) are 16-bit words that writers use as
// unsigned to reach 65535; a float-typed count is accepted when it is a whole number.
long parameterCount(const C3dBytes& b, const C3dParameter& p) {
  if (p.type == 2 && p.count >= 1) return b.u16(p.dataAt);
  const double v = parameterNumber(b, p);
  if (!std::isfinite(v) || v < 0 || v > 2.0e9 || v != std::floor(v)) {
    throwMalformed(b.name(), parameterPosition(p), "not a valid count: " + std::to_string(v));
  }
  return static_cast<long>(v);
}

std::optional<long> optionalCount(const C3dBytes& b, const C3dParameters& params,
                                  const std::string& fullName) {
  const auto* p = findParameter(params, fullName);
  if (!p) return std::nullopt;
  return parameterCount(b, *p);
}

std::optional<double> optionalNumber(const C3dBytes& b, const C3dParameters& params,
                                     const std::string& fullName) {
  const auto* p = findParameter(params, fullName);
  if (!p) return std::nullopt;
  return parameterNumber(b, *p);
}

// A char parameter of dims [len] is one string; [len, n, …] is n strings of len chars.
std::vector<std::string> parameterStrings(const C3dBytes& b, const C3dParameter& p) {
  if (p.type != -1) throwMalformed(b.name(), parameterPosition(p), "is a number, text was expected");
  std::vector<std::string> out;
  if (p.dims.empty()) {
    out.push_back(trimLabel(b.text(p.dataAt, 1)));
    return out;
  }
  const std::size_t len = p.dims[0];
  const std::size_t n = len == 0 ? 0 : p.count / len;
  out.reserve(n);  // bounded: readParameterBody checked count bytes exist
  for (std::size_t k = 0; k < n; ++k) out.push_back(trimLabel(b.text(p.dataAt + k * len, len)));
  return out;
}

std::vector<std::string> optionalStrings(const C3dBytes& b, const C3dParameters& params,
                                         const std::string& fullName) {
  const auto* p = findParameter(params, fullName);
  if (!p || p->type != -1) return {};
  return parameterStrings(b, *p);
}

// [SECTION] Layout: points, frames, analog, data start --------------------------------

struct C3dLayout {
  std::size_t points = 0;
  long firstFrame = 1;
  std::size_t frames = 0;
  double scale = 0.0;  // POINT:SCALE; < 0 means REAL storage
  double rateHz = 0.0;
  std::size_t analogPerFrame = 0;  // analog values interleaved after each frame's points
  std::size_t dataStart = 0;       // absolute byte offset
  bool isFloat() const { return scale < 0; }
  std::size_t wordBytes() const { return isFloat() ? 4 : 2; }
  std::size_t frameBytes() const { return (4 * points + analogPerFrame) * wordBytes(); }
};

// Analog channels sample faster than points (force plates, EMG: up to ~100 kHz); this
// ceiling keeps the analog/point ratio arithmetic away from overflow.
constexpr double kMaxAnalogRateHz = 1.0e6;

std::size_t pointCount(const C3dBytes& b, const C3dParameters& params, const C3dHeader& h,
                       std::vector<std::string>& warnings) {
  const auto used = optionalCount(b, params, "POINT:USED");
  if (!used) return h.points;
  if (static_cast<unsigned long>(*used) != h.points) {
    warnings.push_back("POINT:USED (" + std::to_string(*used) + ") differs from the header's " +
                       std::to_string(h.points) + " points: using POINT:USED");
  }
  return static_cast<std::size_t>(*used);
}

double pointRate(const C3dBytes& b, const C3dParameters& params, const C3dHeader& h) {
  const auto* p = findParameter(params, "POINT:RATE");
  const double rate = p ? parameterNumber(b, *p) : static_cast<double>(h.rateHz);
  return checkedFileRateHz(rate, b.name(), p ? parameterPosition(*p) : "byte 20 (header frame rate)");
}

double pointScale(const C3dBytes& b, const C3dParameters& params, const C3dHeader& h) {
  const auto* p = findParameter(params, "POINT:SCALE");
  const double scale = p ? parameterNumber(b, *p) : static_cast<double>(h.scale);
  if (!std::isfinite(scale) || scale == 0.0) {
    throwMalformed(b.name(), p ? parameterPosition(*p) : "byte 12 (header scale factor)",
                   "point scale " + std::to_string(scale) + " is not usable (zero or not finite)");
  }
  return scale;
}

// Header words 4-5 hold 16-bit frame numbers; longer trials store the count in
// POINT:LONG_FRAMES (float) or TRIAL:ACTUAL_START_FIELD/END_FIELD (two words each).
std::optional<long> trialField(const C3dBytes& b, const C3dParameters& params,
                               const std::string& fullName) {
  const auto* p = findParameter(params, fullName);
  if (!p || p->type != 2 || p->count < 2) return std::nullopt;
  return long{b.u16(p->dataAt)} + 65536L * long{b.u16(p->dataAt + 2)};
}

void frameRange(const C3dBytes& b, const C3dParameters& params, const C3dHeader& h,
                C3dLayout& layout) {
  layout.firstFrame = h.firstFrame;
  long frames = h.lastFrame - h.firstFrame + 1;
  long longFrames = 0;
  if (auto v = optionalCount(b, params, "POINT:FRAMES")) longFrames = *v;
  if (const auto* p = findParameter(params, "POINT:LONG_FRAMES")) {
    longFrames = std::max(longFrames, parameterCount(b, *p));
  }
  const auto start = trialField(b, params, "TRIAL:ACTUAL_START_FIELD");
  const auto end = trialField(b, params, "TRIAL:ACTUAL_END_FIELD");
  if (start && end && *end >= *start) {
    longFrames = std::max(longFrames, *end - *start + 1);
    if (*start > 65535) layout.firstFrame = *start;
  }
  // The parameters only take over where the 16-bit header cannot say it.
  if (longFrames > 65535 || (frames < 1 && longFrames > 0)) frames = longFrames;
  if (frames < 1) {
    throwMalformed(b.name(), "byte 8 (header last frame)",
                   "last frame " + std::to_string(h.lastFrame) + " is before first frame " +
                       std::to_string(h.firstFrame) + " and no frame-count parameter says more");
  }
  layout.frames = static_cast<std::size_t>(frames);
}

std::size_t analogValuesPerFrame(const C3dBytes& b, const C3dParameters& params,
                                 const C3dHeader& h, double pointRateHz,
                                 std::vector<std::string>& warnings) {
  const auto used = optionalCount(b, params, "ANALOG:USED");
  const auto rate = optionalNumber(b, params, "ANALOG:RATE");
  if (!used || *used == 0) return h.analogPerFrame;
  if (!rate || !std::isfinite(*rate) || *rate <= 0.0 || *rate > kMaxAnalogRateHz) {
    warnings.push_back("ANALOG:RATE missing or invalid: using the header's analog count");
    return h.analogPerFrame;
  }
  const double ratio = *rate / pointRateHz;
  const double samples = std::round(ratio);
  if (samples < 1.0 || samples > 65535.0 || std::abs(ratio - samples) > 1e-3 * ratio) {
    warnings.push_back("ANALOG:RATE / POINT:RATE = " + std::to_string(ratio) +
                       " is not a whole number: using the header's analog count");
    return h.analogPerFrame;
  }
  const auto fromParams = static_cast<std::size_t>(*used) * static_cast<std::size_t>(samples);
  if (fromParams != h.analogPerFrame) {
    warnings.push_back("ANALOG:USED x samples per frame (" + std::to_string(fromParams) +
                       ") differs from the header's " + std::to_string(h.analogPerFrame) +
                       " analog values per frame: using the parameters");
  }
  return fromParams;
}

std::size_t dataStart(const C3dBytes& b, const C3dParameters& params, const C3dHeader& h,
                      std::size_t paramStart, std::vector<std::string>& warnings) {
  const auto* p = findParameter(params, "POINT:DATA_START");
  const long fromParam = p ? parameterCount(b, *p) : 0;
  long block = static_cast<long>(h.dataBlock);
  if (block == 0) block = fromParam;
  else if (p && fromParam != block) {
    warnings.push_back("POINT:DATA_START (" + std::to_string(fromParam) +
                       ") differs from the header's data block " + std::to_string(block) +
                       ": using the header");
  }
  const std::size_t start = block > 0 ? static_cast<std::size_t>(block - 1) * kC3dBlockBytes : 0;
  if (block < 2 || start == paramStart) {
    throwMalformed(b.name(), p && h.dataBlock == 0 ? parameterPosition(*p) : "byte 16",
                   "data section pointer is block " + std::to_string(block) +
                       ", which is the header or the parameter section");
  }
  return start;
}

C3dLayout readLayout(const C3dBytes& b, const C3dParameters& params, const C3dHeader& h,
                     std::size_t paramStart, std::vector<std::string>& warnings) {
  C3dLayout layout;
  layout.points = pointCount(b, params, h, warnings);
  if (layout.points == 0) {
    throw Error(ErrorKind::Unsupported, b.name(), "parameter POINT:USED",
                "the file has no 3D points (analog-only C3D)");
  }
  layout.rateHz = pointRate(b, params, h);
  layout.scale = pointScale(b, params, h);
  frameRange(b, params, h, layout);
  layout.analogPerFrame = analogValuesPerFrame(b, params, h, layout.rateHz, warnings);
  layout.dataStart = dataStart(b, params, h, paramStart, warnings);
  // The one check that bounds every allocation below: the frames must be in the file.
  const std::size_t available = b.size() - std::min(b.size(), layout.dataStart);
  if (layout.frames > available / layout.frameBytes()) {
    throwMalformed(b.name(), bytePosition(layout.dataStart),
                   "data section has " + std::to_string(available) + " bytes but " +
                       std::to_string(layout.frames) + " frames of " +
                       std::to_string(layout.points) + " points and " +
                       std::to_string(layout.analogPerFrame) + " analog values need " +
                       std::to_string(layout.frameBytes()) + " bytes each: truncated or corrupt");
  }
  return layout;
}

// [SECTION] Labels, units, up axis ----------------------------------------------------

std::vector<std::string> pointLabels(const C3dBytes& b, const C3dParameters& params,
                                     std::size_t points, std::vector<std::string>& warnings) {
  std::vector<std::string> labels = optionalStrings(b, params, "POINT:LABELS");
  for (int k = 2; labels.size() < points; ++k) {
    const auto more = optionalStrings(b, params, "POINT:LABELS" + std::to_string(k));
    if (more.empty()) break;
    labels.insert(labels.end(), more.begin(), more.end());
  }
  if (labels.size() < points) {
    warnings.push_back("POINT:LABELS names " + std::to_string(labels.size()) + " of " +
                       std::to_string(points) + " points: the rest are called P<n>");
  }
  labels.resize(points);
  for (std::size_t i = 0; i < points; ++i) {
    labels[i] = printable(labels[i]);
    if (labels[i].empty()) labels[i] = "P" + std::to_string(i + 1);
  }
  return labels;
}

// Lengths in C3D files are usually mm, sometimes m (SIMI) or cm. The table is the
// project's one (unitToMm); an override the user typed must be valid, a unit the file
// states is only a warning when we do not know it.
double lengthFactor(const C3dBytes& b, const C3dParameters& params, const LoadOptions& options,
                    RawTrial& trial) {
  if (options.unitsOverride) {
    const double factor = unitToMm(*options.unitsOverride, b.name());
    trial.units = trimLabel(*options.unitsOverride);
    return factor;
  }
  const auto units = optionalStrings(b, params, "POINT:UNITS");
  const std::string stated = units.empty() ? std::string() : printable(units[0]);
  trial.units = "mm";
  if (stated.empty()) {
    trial.warnings.push_back("POINT:UNITS missing: assuming millimetres (override the unit if "
                             "the walker looks 1000x too small or large)");
    return 1.0;
  }
  try {
    const double factor = unitToMm(stated, b.name());
    trial.units = stated;
    return factor;
  } catch (const Error&) {
    trial.warnings.push_back("POINT:UNITS '" + stated +
                             "' is not a length unit we know: assuming millimetres");
    return 1.0;
  }
}

// POINT:Y_SCREEN names the lab axis drawn upwards on screen, i.e. the vertical ("+Z").
void upAxisFromScreen(const C3dBytes& b, const C3dParameters& params, RawTrial& trial) {
  const auto y = optionalStrings(b, params, "POINT:Y_SCREEN");
  if (y.empty()) return;
  std::string s = upper(y[0]);
  int sign = 1;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    sign = s[0] == '-' ? -1 : 1;
    s = s.substr(1);
  }
  if (s.size() == 1 && s[0] >= 'X' && s[0] <= 'Z') {
    trial.upAxis = SignedAxis{s[0] - 'X', sign};
  } else {
    trial.warnings.push_back("POINT:Y_SCREEN '" + printable(y[0]) +
                             "' is not an axis: up axis left to the data");
  }
}

// [SECTION] Events ---------------------------------------------------------------------

GaitEventType eventType(const std::string& label) {
  const std::string u = upper(label);
  if (u.find("FOOT STRIKE") != std::string::npos) return GaitEventType::FootStrike;
  if (u.find("FOOT OFF") != std::string::npos) return GaitEventType::FootOff;
  return GaitEventType::Other;
}

// EVENT:TIMES is 2 x N (minutes, seconds) from the start of the capture, whose first
// frame is numbered firstFrame: t = 0 at that frame is (firstFrame - 1) / rate.
void readEvents(const C3dBytes& b, const C3dParameters& params, const C3dLayout& layout,
                RawTrial& trial) {
  const auto* times = findParameter(params, "EVENT:TIMES");
  const auto used = optionalCount(b, params, "EVENT:USED");
  if (!times || !used || *used == 0) return;
  const auto n = static_cast<std::size_t>(*used);
  if (times->count < 2 * n) {
    throwMalformed(b.name(), parameterPosition(*times),
                   "holds " + std::to_string(times->count / 2) + " times but EVENT:USED is " +
                       std::to_string(n));
  }
  const auto labels = optionalStrings(b, params, "EVENT:LABELS");
  const auto contexts = optionalStrings(b, params, "EVENT:CONTEXTS");
  const double t0 = static_cast<double>(layout.firstFrame - 1) / layout.rateHz;
  std::size_t unsided = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string context = i < contexts.size() ? upper(contexts[i]) : std::string();
    if (context != "LEFT" && context != "RIGHT") {
      ++unsided;  // "General" events carry no side; gait analysis has no use for them
      continue;
    }
    const double seconds = 60.0 * parameterNumber(b, *times, 2 * i) +
                           parameterNumber(b, *times, 2 * i + 1);
    if (!std::isfinite(seconds)) {
      throwMalformed(b.name(), parameterPosition(*times),
                     "event " + std::to_string(i + 1) + " has a time that is not a number");
    }
    GaitEvent e;
    e.side = context == "LEFT" ? Side::Left : Side::Right;
    e.label = i < labels.size() ? printable(labels[i]) : std::string();
    e.type = eventType(e.label);
    e.timeS = seconds - t0;
    trial.events.push_back(e);
  }
  if (unsided > 0) {
    trial.warnings.push_back(std::to_string(unsided) +
                             " events without a Left/Right context were ignored");
  }
  std::sort(trial.events.begin(), trial.events.end(),
            [](const GaitEvent& a, const GaitEvent& c) { return a.timeS < c.timeS; });
}

// [SECTION] Subject -------------------------------------------------------------------

// Some labs keep the subject's measures with the trial: SUBJECT:LABELS, SUBJECT:UNITS and
// SUBJECT:VALUES (the Schreiber-Moissenet files: age, gender, weight, height in m, leg
// lengths). The stature is kept when its unit is a length and its value a person's.
void readSubjectStature(const C3dBytes& b, const C3dParameters& params, RawTrial& trial) {
  const auto* values = findParameter(params, "SUBJECT:VALUES");
  if (!values || values->type == -1) return;
  const auto labels = optionalStrings(b, params, "SUBJECT:LABELS");
  const auto units = optionalStrings(b, params, "SUBJECT:UNITS");
  for (std::size_t i = 0; i < labels.size() && i < values->count; ++i) {
    const std::string label = upper(trimLabel(labels[i]));
    if (label != "HEIGHT" && label != "STATURE") continue;
    const std::string unit = i < units.size() ? upper(trimLabel(units[i])) : std::string();
    const double toMm = unit == "M" ? 1000.0 : unit == "CM" ? 10.0 : unit == "MM" ? 1.0 : 0.0;
    const double mm = parameterNumber(b, *values, i) * toMm;
    if (mm >= 300.0 && mm <= 3000.0) {
      trial.subjectStatureMm = mm;
    } else {
      trial.warnings.push_back("SUBJECT:VALUES holds a " + printable(labels[i]) + " of " +
                               std::to_string(parameterNumber(b, *values, i)) + " '" + printable(unit) +
                               "', not a person's stature in m, cm or mm: ignored");
    }
    return;
  }
}

// [SECTION] Point data -----------------------------------------------------------------

// One point sample: x, y, z in file units and whether the residual word marks it valid.
struct PointSample {
  double x = 0, y = 0, z = 0;
  bool valid = false;
};

PointSample readSample(const C3dBytes& b, const C3dLayout& layout, std::size_t at) {
  PointSample s;
  if (layout.isFloat()) {
    s.x = b.f32(at);
    s.y = b.f32(at + 4);
    s.z = b.f32(at + 8);
    const float residual = b.f32(at + 12);
    s.valid = residual >= 0.0f;  // false for negative and NaN
  } else {
    // INT: the 4th word's high byte is the camera mask, low byte the residual; a
    // negative word (-1) marks the point invalid.
    const double k = std::abs(layout.scale);
    s.x = b.i16(at) * k;
    s.y = b.i16(at + 2) * k;
    s.z = b.i16(at + 4) * k;
    s.valid = b.i16(at + 6) >= 0;
  }
  s.valid = s.valid && std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z);
  return s;
}

// Qualisys and older writers mark a gap with coordinates (0, 0, 0) and a valid residual; a
// real marker exactly at the lab origin in all three axes does not happen.
bool isZeroGap(const PointSample& s) { return s.x == 0.0 && s.y == 0.0 && s.z == 0.0;
}

void readPoints(const C3dBytes& b, const C3dLayout& layout, double toMm, RawTrial& trial) {
  const auto rows = static_cast<Eigen::Index>(layout.frames);
  const auto cols = static_cast<Eigen::Index>(3 * layout.points);
  trial.positionsMm.setConstant(rows, cols, std::numeric_limits<double>::quiet_NaN());
  const std::size_t pointBytes = 4 * layout.wordBytes();
  std::size_t invalid = 0, zeros = 0;
  for (std::size_t f = 0; f < layout.frames; ++f) {
    const std::size_t frameAt = layout.dataStart + f * layout.frameBytes();
    for (std::size_t p = 0; p < layout.points; ++p) {
      const PointSample s = readSample(b, layout, frameAt + p * pointBytes);
      if (!s.valid || isZeroGap(s)) {
        ++(s.valid ? zeros : invalid);
        continue;
      }
      const auto r = static_cast<Eigen::Index>(f);
      const auto c = static_cast<Eigen::Index>(3 * p);
      trial.positionsMm(r, c) = s.x * toMm;
      trial.positionsMm(r, c + 1) = s.y * toMm;
      trial.positionsMm(r, c + 2) = s.z * toMm;
    }
  }
  if (zeros > 0) {
    trial.warnings.push_back(std::to_string(zeros) +
                             " point samples at exactly (0, 0, 0) were taken as gaps (missing)");
  }
  if (invalid == layout.frames * layout.points) {
    trial.warnings.push_back("every point sample is marked invalid (negative residual): the "
                             "trial has no usable marker data");
  } else if (invalid > 0) {
    trial.warnings.push_back(std::to_string(invalid) + " of " +
                             std::to_string(layout.frames * layout.points) +
                             " point samples are missing (negative residual)");
  }
}

}  // namespace

// [SECTION] Public entry points --------------------------------------------------------

float decodeVaxFloat(const std::uint8_t bytes[4]) {
  // VAX F_floating: two little-endian 16-bit words; the first holds sign, 8-bit exponent
  // (bias 128) and the top 7 mantissa bits, the second the low 16 mantissa bits; the
  // value is 0.1fff… (hidden bit after the point) x 2^(exp - 128).
  const unsigned w0 = unsigned{bytes[0]} | (unsigned{bytes[1]} << 8);
  const unsigned w1 = unsigned{bytes[2]} | (unsigned{bytes[3]} << 8);
  const bool negative = (w0 & 0x8000u) != 0;
  const int exponent = static_cast<int>((w0 >> 7) & 0xFFu);
  const std::uint32_t mantissa = ((w0 & 0x7Fu) << 16) | w1;
  if (exponent == 0) return negative ? std::numeric_limits<float>::quiet_NaN() : 0.0f;
  const double fraction = 0.5 + static_cast<double>(mantissa) / 16777216.0;  // 2^24
  const double value = std::ldexp(fraction, exponent - 128);
  return static_cast<float>(negative ? -value : value);
}

RawTrial parseC3d(std::span<const std::uint8_t> bytes, const std::string& name,
                  const LoadOptions& options) {
  C3dBytes b(bytes, name);
  const std::size_t paramStart = parameterStart(b);
  b.setProcessor(readProcessor(b, paramStart));
  RawTrial trial;
  trial.file = name;
  trial.format = "C3D";
  trial.kind = PointKind::Markers;
  const C3dHeader header = readHeader(b);
  const C3dParameters params = readParameters(b, paramStart, trial.warnings);
  const C3dLayout layout = readLayout(b, params, header, paramStart, trial.warnings);
  trial.rateHz = layout.rateHz;
  if (options.rateHzOverride) trial.rateHz = checkedRateOverrideHz(*options.rateHzOverride, name);
  trial.firstFrame = layout.firstFrame;
  trial.labels = pointLabels(b, params, layout.points, trial.warnings);
  trial.descriptions = optionalStrings(b, params, "POINT:DESCRIPTIONS");
  for (auto& d : trial.descriptions) d = printable(d);
  // Our own 15 joints (core/io/c3d_writer.h writes them so, the feet's points after them when
  // known), as the TRC reader takes them.
  if (trial.labels.size() >= kJointNames.size() &&
      std::equal(kJointNames.begin(), kJointNames.end(), trial.labels.begin()))
    trial.kind = PointKind::CanonicalJoints;
  const double toMm = lengthFactor(b, params, options, trial);
  upAxisFromScreen(b, params, trial);
  readEvents(b, params, layout, trial);
  // A rate the user says is the right one re-times the frames; each event stays on its frame
  // (before, the events kept the file's seconds and fell on other frames: strides 4 times short
  // at a quarter of the rate, the cadence unchanged).
  if (options.rateHzOverride)
    for (GaitEvent& e : trial.events) e.timeS *= layout.rateHz / trial.rateHz;
  readSubjectStature(b, params, trial);
  readPoints(b, layout, toMm, trial);
  return trial;
}

RawTrial readC3d(const std::filesystem::path& file, const LoadOptions& options) {
  const auto bytes = readFileBytes(file);
  return parseC3d(bytes, file.string(), options);
}

}  // namespace ew
