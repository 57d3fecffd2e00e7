#include "core/io/asf_amc_reader.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/reader_limits.h"
#include "core/io/rotation_arrays.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

// [SECTION] Limits
constexpr size_t kMaxBones = 1024;        // CMU: 30; anything far beyond is corruption
constexpr double kDefaultRateHz = 120.0;  // CMU captures at 120 Hz; AMC stores no rate

// [SECTION] Words and numbers

bool parseInteger(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
}

// A line split into words, with what an error needs to point at it.
struct Words {
  std::vector<std::string_view> w;
  int line = 0;
};

class LineReader {
 public:
  LineReader(std::string_view text, std::string file)
      : lines_(splitLines(text)), file_(std::move(file)) {}

  // The next line that is neither blank nor a '#' comment; false at the end.
  bool next(Words& out) {
    while (index_ < lines_.size()) {
      const TextLine& line = lines_[index_++];
      auto words = splitWords(line.text);
      if (words.empty() || words[0].front() == '#') continue;
      out = {std::move(words), line.number};
      return true;
    }
    return false;
  }
  void unread() { --index_; }  // only right after a successful next()
  int lastLine() const { return lines_.empty() ? 1 : lines_.back().number; }
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(int line, const std::string& problem) const {
    throwMalformed(file_, linePosition(line), problem);
  }

  double number(const Words& words, size_t k, const char* what) const {
    double v = 0.0;
    if (k >= words.w.size()) fail(words.line, std::string("missing ") + what);
    if (!parseFinite(words.w[k], v)) {
      fail(words.line, std::string("bad ") + what + ": " + shownWord(words.w[k]));
    }
    return v;
  }

 private:
  std::vector<TextLine> lines_;
  std::string file_;
  size_t index_ = 0;
};

// [SECTION] ASF skeleton

enum class Dof { RX, RY, RZ, TX, TY, TZ };

std::optional<Dof> dofFromName(std::string_view name) {
  const auto n = toLower(name);
  if (n == "rx") return Dof::RX;
  if (n == "ry") return Dof::RY;
  if (n == "rz") return Dof::RZ;
  if (n == "tx") return Dof::TX;
  if (n == "ty") return Dof::TY;
  if (n == "tz") return Dof::TZ;
  return std::nullopt;
}

bool isRotation(Dof d) { return d == Dof::RX || d == Dof::RY || d == Dof::RZ; }

// [SECTION] Rotations

// Rotations applied in the listed order (first listed first): R = R(last)…R(first),
// so they are post-multiplied last first. `axes` holds 0,1,2 for X,Y,Z.
Mat3 composeInOrder(const std::vector<int>& axes, const std::vector<double>& radians) {
  Mat3 r = kIdentity3;
  for (size_t k = axes.size(); k-- > 0;) postRotate(r, axes[k], radians[k]);
  return r;
}

struct AsfBone {
  std::string name;
  int line = 0;
  int parent = -1;  // bone index; -1 = the root
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double length = 0.0;
  Mat3 axis = kIdentity3;  // C
  std::vector<Dof> dofs;
  int firstValue = 0;  // column of dofs[0] in a frame's value row
};

struct AsfSkeleton {
  double lengthUnit = 1.0;  // `:units length`: lengths are in 1/lengthUnit inches
  double angleToRad = std::numbers::pi / 180.0;
  std::vector<Dof> rootOrder{Dof::TX, Dof::TY, Dof::TZ, Dof::RX, Dof::RY, Dof::RZ};
  Mat3 rootAxis = kIdentity3;
  Eigen::Vector3d rootPosition = Eigen::Vector3d::Zero();
  std::vector<AsfBone> bones;
  std::map<std::string, int, std::less<>> boneIndex;
  std::vector<int> order;  // bones, parents first
  int valueCount = 0;      // root order + every bone's dofs
};

// "XYZ" -> {0,1,2}; any permutation of the three axes.
std::vector<int> axisOrder(std::string_view s, const LineReader& in, int line) {
  std::vector<int> axes;
  const auto u = toLower(s);
  for (char c : u) {
    if (c < 'x' || c > 'z') in.fail(line, "bad rotation order " + shownWord(s));
    axes.push_back(c - 'x');
  }
  auto sorted = axes;
  std::sort(sorted.begin(), sorted.end());
  if (sorted != std::vector<int>{0, 1, 2}) in.fail(line, "bad rotation order " + shownWord(s));
  return axes;
}

// "axis 0 0 20 XYZ" / root "axis XYZ" + "orientation 0 0 0": C from the X,Y,Z angles.
Mat3 axisMatrix(const Eigen::Vector3d& anglesXyz, const std::vector<int>& order,
                           double angleToRad) {
  std::vector<double> radians;
  for (int a : order) radians.push_back(anglesXyz[a] * angleToRad);
  return composeInOrder(order, radians);
}

class AsfParser {
 public:
  AsfParser(std::string_view text, const std::string& file) : in_(text, file) {}

  AsfSkeleton parse() {
    Words words;
    bool sawBones = false, sawHierarchy = false;
    while (in_.next(words)) {
      const auto key = toLower(words.w[0]);
      if (key == ":units") readUnits();
      else if (key == ":root") readRoot();
      else if (key == ":bonedata") readBones(), sawBones = true;
      else if (key == ":hierarchy") readHierarchy(), sawHierarchy = true;
      else if (key.front() == ':') skipSection();  // :version, :name, :documentation, :skin
      else
        in_.fail(words.line, "unexpected " + shownWord(words.w[0]) + " outside a section");
    }
    if (!sawBones) in_.fail(in_.lastLine(), "no :bonedata section: not an ASF skeleton");
    if (!sawHierarchy) in_.fail(in_.lastLine(), "no :hierarchy section");
    orderBones();
    return std::move(sk_);
  }

 private:
  // Lines up to the next ':' keyword belong to the current section.
  bool nextInSection(Words& words) {
    if (!in_.next(words)) return false;
    if (words.w[0].front() == ':') {
      in_.unread();
      return false;
    }
    return true;
  }

  void skipSection() {
    Words words;
    while (nextInSection(words)) {
    }
  }

  void readUnits() {
    Words words;
    while (nextInSection(words)) {
      const auto key = toLower(words.w[0]);
      if (key == "length") {
        sk_.lengthUnit = in_.number(words, 1, "length unit");
        if (sk_.lengthUnit <= 0.0) in_.fail(words.line, "length unit must be positive");
      } else if (key == "angle") {
        const auto unit = words.w.size() > 1 ? toLower(words.w[1]) : std::string();
        if (unit == "deg" || unit == "degree" || unit == "degrees") {
          sk_.angleToRad = std::numbers::pi / 180.0;
        } else if (unit == "rad" || unit == "radian" || unit == "radians") {
          sk_.angleToRad = 1.0;
        } else {
          in_.fail(words.line, "angle unit must be deg or rad");
        }
      } else if (key == "mass") {
        in_.number(words, 1, "mass unit");
      } else {
        in_.fail(words.line, "unknown unit " + shownWord(words.w[0]));
      }
    }
  }

  void readRoot() {
    Words words;
    Eigen::Vector3d orientation = Eigen::Vector3d::Zero();
    std::vector<int> order{0, 1, 2};
    while (nextInSection(words)) {
      const auto key = toLower(words.w[0]);
      if (key == "order") {
        sk_.rootOrder.clear();
        for (size_t k = 1; k < words.w.size(); ++k) {
          auto dof = dofFromName(words.w[k]);
          if (!dof || std::count(sk_.rootOrder.begin(), sk_.rootOrder.end(), *dof) > 0) {
            in_.fail(words.line, "bad root order entry " + shownWord(words.w[k]));
          }
          sk_.rootOrder.push_back(*dof);
        }
      } else if (key == "axis") {
        if (words.w.size() != 2) in_.fail(words.line, "root axis needs one order, e.g. XYZ");
        order = axisOrder(words.w[1], in_, words.line);
      } else if (key == "position" || key == "orientation") {
        Eigen::Vector3d v;
        for (int k = 0; k < 3; ++k) v[k] = in_.number(words, static_cast<size_t>(k + 1), key.c_str());
        (key == "position" ? sk_.rootPosition : orientation) = v;
      } else {
        in_.fail(words.line, "unknown root field " + shownWord(words.w[0]));
      }
    }
    sk_.rootAxis = axisMatrix(orientation, order, sk_.angleToRad);
  }

  void readBones() {
    Words words;
    while (nextInSection(words)) {
      if (toLower(words.w[0]) != "begin") {
        in_.fail(words.line, "expected 'begin' of a bone, found " + shownWord(words.w[0]));
      }
      if (sk_.bones.size() >= kMaxBones) {
        in_.fail(words.line, "more than " + std::to_string(kMaxBones) + " bones");
      }
      readBone(words.line);
    }
  }

  void readBone(int beginLine) {
    AsfBone bone;
    bone.line = beginLine;
    bool hasDirection = false, hasLength = false, hasLimits = false;
    Words words;
    while (true) {
      if (!in_.next(words)) in_.fail(in_.lastLine(), "file ends inside a bone (no 'end')");
      const auto key = toLower(words.w[0]);
      if (key == "end") break;
      if (key == "id" || key == "bodymass" || key == "cofmass") {
        in_.number(words, 1, key.c_str());
      } else if (key == "name") {
        if (words.w.size() != 2) in_.fail(words.line, "a bone name is one word");
        bone.name = std::string(words.w[1]);
      } else if (key == "direction") {
        for (int k = 0; k < 3; ++k) bone.direction[k] = in_.number(words, static_cast<size_t>(k + 1), "direction");
        hasDirection = true;
      } else if (key == "length") {
        bone.length = in_.number(words, 1, "length");
        if (bone.length < 0.0) in_.fail(words.line, "negative bone length");
        hasLength = true;
      } else if (key == "axis") {
        Eigen::Vector3d angles;
        for (int k = 0; k < 3; ++k) angles[k] = in_.number(words, static_cast<size_t>(k + 1), "axis angle");
        if (words.w.size() != 5) in_.fail(words.line, "axis needs three angles and an order");
        bone.axis = axisMatrix(angles, axisOrder(words.w[4], in_, words.line), sk_.angleToRad);
      } else if (key == "dof") {
        readDofs(words, bone);
      } else if (key == "limits") {
        readLimits(words, bone.dofs.size());
        hasLimits = true;
      } else {
        in_.fail(words.line, "unknown bone field " + shownWord(words.w[0]));
      }
    }
    finishBone(std::move(bone), hasDirection, hasLength, hasLimits);
  }

  void finishBone(AsfBone bone, bool hasDirection, bool hasLength, bool hasLimits) {
    if (bone.name.empty()) in_.fail(bone.line, "bone without a name");
    if (!hasDirection || !hasLength) {
      in_.fail(bone.line, "bone " + shownWord(bone.name) + " needs a direction and a length");
    }
    if (!bone.dofs.empty() && !hasLimits) {
      in_.fail(bone.line, "bone " + shownWord(bone.name) + " has dofs but no limits");
    }
    const double norm = bone.direction.norm();
    if (norm > 0.0) bone.direction /= norm;
    else if (bone.length > 0.0)
      in_.fail(bone.line, "bone " + shownWord(bone.name) + " has a zero direction");
    if (toLower(bone.name) == "root" || sk_.boneIndex.count(bone.name) != 0) {
      in_.fail(bone.line, "bone name " + shownWord(bone.name) + " used twice");
    }
    bone.firstValue = sk_.valueCount;
    sk_.valueCount += static_cast<int>(bone.dofs.size());
    sk_.boneIndex.emplace(bone.name, static_cast<int>(sk_.bones.size()));
    sk_.bones.push_back(std::move(bone));
  }

  void readDofs(const Words& words, AsfBone& bone) {
    for (size_t k = 1; k < words.w.size(); ++k) {
      auto dof = dofFromName(words.w[k]);
      if (!dof) {
        // Acclaim also allows a length dof 'l'; CMU never uses it.
        throw Error(ErrorKind::Unsupported, in_.file(), linePosition(words.line),
                    "dof " + shownWord(words.w[k]) + " is not supported (rx ry rz only)");
      }
      if (!isRotation(*dof)) {
        throw Error(ErrorKind::Unsupported, in_.file(), linePosition(words.line),
                    "translation dof " + shownWord(words.w[k]) + " on a bone is not supported");
      }
      if (std::count(bone.dofs.begin(), bone.dofs.end(), *dof) > 0) {
        in_.fail(words.line, "dof " + shownWord(words.w[k]) + " repeated");
      }
      bone.dofs.push_back(*dof);
    }
  }

  // "limits (-160.0 20.0)" then one "(lo hi)" line per further dof; ±inf allowed.
  void readLimits(Words words, size_t dofCount) {
    for (size_t pair = 0; pair < dofCount; ++pair) {
      if (pair > 0 && !in_.next(words)) in_.fail(in_.lastLine(), "file ends inside limits");
      std::string joined;
      for (size_t k = pair == 0 ? 1 : 0; k < words.w.size(); ++k) joined += std::string(words.w[k]) + " ";
      const auto open = joined.find('('), close = joined.find(')');
      if (open == std::string::npos || close == std::string::npos || close < open) {
        in_.fail(words.line, "limits need '(low high)' for each dof");
      }
      auto values = splitWords(std::string_view(joined).substr(open + 1, close - open - 1));
      if (values.size() != 2) in_.fail(words.line, "limits need two values per dof");
      for (auto v : values) {
        double x = 0.0;
        const auto lower = toLower(v);
        if (lower != "inf" && lower != "-inf" && !parseFinite(v, x)) {
          in_.fail(words.line, "bad limit " + shownWord(v));
        }
      }
    }
  }

  void readHierarchy() {
    Words words;
    if (!nextInSection(words)) in_.fail(in_.lastLine(), "empty :hierarchy section");
    if (toLower(words.w[0]) != "begin") in_.fail(words.line, "hierarchy must start with 'begin'");
    while (true) {
      if (!in_.next(words)) in_.fail(in_.lastLine(), "file ends inside the hierarchy");
      if (toLower(words.w[0]) == "end") break;
      const bool fromRoot = toLower(words.w[0]) == "root";
      const int parent = fromRoot ? -1 : boneAt(words, 0);
      if (words.w.size() < 2) in_.fail(words.line, "hierarchy line without children");
      for (size_t k = 1; k < words.w.size(); ++k) {
        AsfBone& child = sk_.bones[static_cast<size_t>(boneAt(words, k))];
        if (child.parent != -1 || hasRootParent(child.name)) {
          in_.fail(words.line, "bone " + shownWord(child.name) + " has two parents");
        }
        child.parent = parent;
        if (fromRoot) rootChildren_.push_back(child.name);
      }
    }
  }

  bool hasRootParent(const std::string& name) const {
    return std::find(rootChildren_.begin(), rootChildren_.end(), name) != rootChildren_.end();
  }

  int boneAt(const Words& words, size_t k) const {
    auto it = sk_.boneIndex.find(words.w[k]);
    if (it == sk_.boneIndex.end()) {
      in_.fail(words.line, "hierarchy names unknown bone " + shownWord(words.w[k]));
    }
    return it->second;
  }

  // Parents before children; bones the root does not reach (a cycle, a missing line)
  // are an error rather than silently dropped.
  void orderBones() {
    std::vector<std::vector<int>> children(sk_.bones.size() + 1);
    for (size_t b = 0; b < sk_.bones.size(); ++b) {
      const int parent = sk_.bones[b].parent;
      if (parent == -1 && !hasRootParent(sk_.bones[b].name)) {
        in_.fail(sk_.bones[b].line, "bone " + shownWord(sk_.bones[b].name) +
                                        " is not connected to the root in :hierarchy");
      }
      children[static_cast<size_t>(parent + 1)].push_back(static_cast<int>(b));
    }
    std::vector<int> stack(children[0].rbegin(), children[0].rend());
    while (!stack.empty()) {
      const int b = stack.back();
      stack.pop_back();
      sk_.order.push_back(b);
      const auto& next = children[static_cast<size_t>(b + 1)];
      stack.insert(stack.end(), next.rbegin(), next.rend());
    }
    if (sk_.order.size() != sk_.bones.size()) {
      in_.fail(in_.lastLine(), "the :hierarchy has a cycle: some bones never reach the root");
    }
  }

  LineReader in_;
  AsfSkeleton sk_;
  std::vector<std::string> rootChildren_;
};

// [SECTION] AMC motion

struct AmcMotion {
  long firstFrame = 1;
  long long frames = 0;
  std::vector<double> values;  // frames x (root order + bone dofs), radians / file lengths
};

class AmcParser {
 public:
  AmcParser(std::string_view text, const std::string& file, const AsfSkeleton& sk)
      : in_(text, file),
        sk_(sk),
        rootCount_(static_cast<int>(sk.rootOrder.size())),
        allowance_(skeletonPointFrameAllowance(text.size())) {
    angleToRad_ = sk.angleToRad;
  }

  AmcMotion parse(std::vector<std::string>& warnings) {
    Words words;
    const double points = static_cast<double>(sk_.bones.size() + 1);
    const auto width = static_cast<size_t>(rootCount_ + sk_.valueCount);
    while (in_.next(words)) {
      if (words.w[0].front() == ':') {
        keyword(words, warnings);
        continue;
      }
      long long number = 0;
      if (words.w.size() == 1 && parseInteger(words.w[0], number)) {
        startFrame(words, number);
        // The dof values of a frame count like coordinates (three to a point).
        checkPointFrames(static_cast<double>(motion_.frames),
                         std::max(points, static_cast<double>(width) / 3.0), allowance_,
                         in_.file(), linePosition(words.line));
        motion_.values.resize(motion_.values.size() + width, 0.0);
        seen_.assign(sk_.bones.size() + 1, false);
        continue;
      }
      if (motion_.frames == 0) {
        in_.fail(words.line, "expected a frame number, found " + shownWord(words.w[0]));
      }
      boneValues(words);
    }
    if (motion_.frames == 0) in_.fail(in_.lastLine(), "no frames in the AMC file");
    return std::move(motion_);
  }

 private:
  void keyword(const Words& words, std::vector<std::string>& warnings) {
    if (motion_.frames > 0)
      in_.fail(words.line, "keyword " + shownWord(words.w[0]) + " after the frames");
    const auto key = toLower(words.w[0]);
    if (key == ":degrees") angleToRad_ = std::numbers::pi / 180.0;
    else if (key == ":radians") angleToRad_ = 1.0;
    else if (key != ":fully-specified")
      warnings.push_back("ignored AMC keyword " + shownWord(words.w[0]));
  }

  void startFrame(const Words& words, long long number) {
    if (motion_.frames == 0) {
      if (number < 0 || number > 1'000'000'000) in_.fail(words.line, "bad frame number");
      motion_.firstFrame = static_cast<long>(number);
    } else if (number != motion_.firstFrame + motion_.frames) {
      in_.fail(words.line, "frame " + std::to_string(number) + " where frame " +
                               std::to_string(motion_.firstFrame + motion_.frames) +
                               " was expected (frames must be consecutive)");
    }
    ++motion_.frames;
  }

  void boneValues(const Words& words) {
    const bool isRoot = toLower(words.w[0]) == "root";
    int slot = 0, first = 0, count = rootCount_;
    if (!isRoot) {
      auto it = sk_.boneIndex.find(words.w[0]);
      if (it == sk_.boneIndex.end()) {
        in_.fail(words.line,
                 "unknown bone " + shownWord(words.w[0]) + " (not in the ASF skeleton)");
      }
      const AsfBone& bone = sk_.bones[static_cast<size_t>(it->second)];
      slot = it->second + 1;
      first = rootCount_ + bone.firstValue;
      count = static_cast<int>(bone.dofs.size());
    }
    if (static_cast<int>(words.w.size()) - 1 != count) {
      in_.fail(words.line, shownWord(words.w[0]) + " has " + std::to_string(words.w.size() - 1) +
                               " values, the skeleton gives it " + std::to_string(count) + " dofs");
    }
    if (seen_[static_cast<size_t>(slot)])
      in_.fail(words.line, shownWord(words.w[0]) + " twice in one frame");
    seen_[static_cast<size_t>(slot)] = true;
    double* row = &motion_.values[motion_.values.size() - static_cast<size_t>(rootCount_ + sk_.valueCount)];
    for (int k = 0; k < count; ++k) {
      double v = in_.number(words, static_cast<size_t>(k + 1), "dof value");
      const bool rotation = isRoot ? isRotation(sk_.rootOrder[static_cast<size_t>(k)]) : true;
      row[first + k] = rotation ? v * angleToRad_ : v;
    }
  }

  LineReader in_;
  const AsfSkeleton& sk_;
  int rootCount_;
  double allowance_;  // point-frames this AMC's size allows (reader_limits.h)
  double angleToRad_;
  AmcMotion motion_;
  std::vector<bool> seen_;
};

// [SECTION] Forward kinematics

// C · R(dofs) · C⁻¹ after `m`: R applies the dofs in the listed order, i.e.
// R = R(last)…R(first), so they are post-multiplied last first.
Mat3 jointFrame(const Mat3& parent, const Mat3& c, const Mat3& cInverse,
                const std::vector<Dof>& dofs, const double* values) {
  Mat3 m = multiply(parent, c);
  for (size_t k = dofs.size(); k-- > 0;) {
    if (isRotation(dofs[k])) {
      postRotate(m, static_cast<int>(dofs[k]) - static_cast<int>(Dof::RX), values[k]);
    }
  }
  return multiply(m, cInverse);
}

struct FkSkeleton {
  Mat3 rootC, rootCInverse;
  std::vector<Mat3> c, cInverse;
  std::vector<std::array<double, 3>> bone;  // direction * length
};

FkSkeleton prepareFk(const AsfSkeleton& sk) {
  FkSkeleton fk;
  fk.rootC = sk.rootAxis;
  fk.rootCInverse = transposed(sk.rootAxis);
  for (const AsfBone& b : sk.bones) {
    fk.c.push_back(b.axis);
    fk.cInverse.push_back(transposed(b.axis));
    const Eigen::Vector3d v = b.direction * b.length;
    fk.bone.push_back({v.x(), v.y(), v.z()});
  }
  return fk;
}

// One frame: "root" then every bone's end, x,y,z in file length units.
void forwardKinematics(const AsfSkeleton& sk, const FkSkeleton& fk, const double* row,
                       std::vector<Mat3>& frame, double* out) {
  std::array<double, 3> rootPos{sk.rootPosition.x(), sk.rootPosition.y(), sk.rootPosition.z()};
  for (size_t k = 0; k < sk.rootOrder.size(); ++k) {
    const Dof d = sk.rootOrder[k];
    if (!isRotation(d)) rootPos[static_cast<size_t>(d) - static_cast<size_t>(Dof::TX)] += row[k];
  }
  const Mat3 rootM = jointFrame(kIdentity3, fk.rootC, fk.rootCInverse, sk.rootOrder, row);
  for (size_t a = 0; a < 3; ++a) out[a] = rootPos[a];
  frame.resize(sk.bones.size());
  const double* boneValues = row + sk.rootOrder.size();
  for (int index : sk.order) {
    const auto b = static_cast<size_t>(index);
    const AsfBone& bone = sk.bones[b];
    const bool fromRoot = bone.parent < 0;
    const Mat3& parentM = fromRoot ? rootM : frame[static_cast<size_t>(bone.parent)];
    const double* start = out + (fromRoot ? 0 : 3 * (static_cast<size_t>(bone.parent) + 1));
    frame[b] = jointFrame(parentM, fk.c[b], fk.cInverse[b], bone.dofs, boneValues + bone.firstValue);
    const Mat3& m = frame[b];
    const auto& v = fk.bone[b];
    double* end = out + 3 * (b + 1);
    for (size_t a = 0; a < 3; ++a) {
      end[a] = start[a] + m[3 * a] * v[0] + m[3 * a + 1] * v[1] + m[3 * a + 2] * v[2];
    }
  }
}

std::string lengthUnitName(double lengthUnit) {
  if (std::abs(lengthUnit - 0.45) < 1e-9) return "cmu";
  if (std::abs(lengthUnit - 1.0) < 1e-9) return "in";
  char text[48];
  std::snprintf(text, sizeof text, "1/%g in", lengthUnit);
  return text;
}

// .asf beside the .amc: the one whose stem prefixes the AMC's (longest), else the only one.
std::filesystem::path findAsf(const std::filesystem::path& amcFile) {
  const auto dir = amcFile.has_parent_path() ? amcFile.parent_path() : std::filesystem::path(".");
  const auto stem = amcFile.stem().string();
  std::error_code ec;
  std::vector<std::filesystem::path> asfs;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (toLower(entry.path().extension().string()) == ".asf") asfs.push_back(entry.path());
  }
  std::filesystem::path best;
  for (const auto& p : asfs) {
    const auto s = p.stem().string();
    if (stem.rfind(s, 0) == 0 && s.size() > best.stem().string().size()) best = p;
  }
  if (best.empty() && asfs.size() == 1) best = asfs.front();
  if (best.empty()) {
    throw Error(ErrorKind::Io, amcFile.string(), "",
                asfs.empty() ? "no .asf skeleton file beside it"
                             : "several .asf files beside it and none named like it");
  }
  return best;
}

}  // namespace

RawTrial parseAsfAmc(std::string_view asfText, std::string_view amcText,
                     const std::string& asfName, const std::string& amcName,
                     const LoadOptions& options) {
  const AsfSkeleton sk = AsfParser(asfText, asfName).parse();
  RawTrial out;
  out.file = amcName;
  out.format = "ASF/AMC";
  out.kind = PointKind::SkeletonJoints;
  out.upAxis = SignedAxis{1, 1};
  const AmcMotion motion = AmcParser(amcText, amcName, sk).parse(out.warnings);
  out.firstFrame = motion.firstFrame;

  if (options.rateHzOverride) {
    out.rateHz = checkedRateOverrideHz(*options.rateHzOverride, amcName);
  } else {
    out.rateHz = kDefaultRateHz;
    out.warnings.push_back("AMC stores no frame rate: assumed 120 Hz (CMU); set the rate "
                           "override if this is wrong");
  }
  double mmPerUnit = 25.4 / sk.lengthUnit;
  out.units = lengthUnitName(sk.lengthUnit);
  if (options.unitsOverride) {
    out.units = *options.unitsOverride;
    mmPerUnit = unitToMm(out.units, amcName);
  }

  out.labels.push_back("root");
  for (const auto& bone : sk.bones) out.labels.push_back(bone.name);
  const auto points = static_cast<Eigen::Index>(out.labels.size());
  const auto frames = static_cast<Eigen::Index>(motion.frames);
  const auto width = sk.rootOrder.size() + static_cast<size_t>(sk.valueCount);
  // One row at a time into the result: the positions exist once in memory, not twice.
  out.positionsMm.resize(frames, 3 * points);
  Eigen::RowVectorXd framePoints(3 * points);
  const FkSkeleton fk = prepareFk(sk);
  std::vector<Mat3> scratch;
  for (Eigen::Index f = 0; f < frames; ++f) {
    forwardKinematics(sk, fk, &motion.values[static_cast<size_t>(f) * width], scratch,
                      framePoints.data());
    out.positionsMm.row(f) = framePoints * mmPerUnit;
  }
  return out;
}

RawTrial parseAsfAmc(std::string_view asfText, std::string_view amcText, const std::string& name,
                     const LoadOptions& options) {
  return parseAsfAmc(asfText, amcText, name, name, options);
}

std::filesystem::path asfSkeletonFor(const std::filesystem::path& amcFile) {
  return findAsf(amcFile);
}

std::vector<std::filesystem::path> amcMotionsFor(const std::filesystem::path& asfFile) {
  const auto dir = asfFile.has_parent_path() ? asfFile.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (toLower(entry.path().extension().string()) != ".amc") continue;
    try {
      if (std::filesystem::equivalent(findAsf(entry.path()), asfFile, ec)) out.push_back(entry.path());
    } catch (const Error&) {
      // an .amc that pairs with no .asf here is not this skeleton's motion
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

RawTrial readAsfAmc(const std::filesystem::path& amcFile, const LoadOptions& options) {
  const auto amcText = readFileText(amcFile);
  const auto asfFile = findAsf(amcFile);
  return parseAsfAmc(readFileText(asfFile), amcText, asfFile.string(), amcFile.string(), options);
}

}  // namespace ew
