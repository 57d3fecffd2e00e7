#include "core/tracking/keyframes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"

namespace ew {
namespace {

using nlohmann::json;
constexpr const char* kFormatName = "eigenwalker-keyframes";
constexpr int kFormatVersion = 1;

double coordinate(const json& value, const std::string& name, const std::string& where) {
  if (!value.is_number()) throwMalformed(name, where, "a coordinate is not a number");
  const double v = value.get<double>();
  if (!std::isfinite(v)) throwMalformed(name, where, "a coordinate is not finite");
  return v;
}

Keyframe parseKeyframe(const json& entry, const std::string& name, std::size_t position) {
  const std::string where = "keyframe " + std::to_string(position);
  if (!entry.is_object()) throwMalformed(name, where, "is not an object");
  const auto frame = entry.find("frame");
  if (frame == entry.end() || !frame->is_number_integer())
    throwMalformed(name, where, "has no integer \"frame\"");
  const auto frameNumber = frame->get<long long>();
  if (frameNumber < 0 || frameNumber > std::numeric_limits<int>::max())
    throwMalformed(name, where, "frame " + std::to_string(frameNumber) + " is out of range");
  Keyframe k;
  k.frame = static_cast<int>(frameNumber);
  k.jointsPx = Eigen::RowVectorXd::Constant(kDims2, std::numeric_limits<double>::quiet_NaN());
  const auto joints = entry.find("joints");
  if (joints == entry.end() || !joints->is_object())
    throwMalformed(name, where, "has no \"joints\" object");
  for (const auto& [jointText, value] : joints->items()) {
    const auto joint = jointFromName(jointText);
    if (!joint)
      throwMalformed(name, where,
                     "unknown joint \"" + jointText + "\" (docs/METHOD.md §1 names: head, sternum, …)");
    if (value.is_null()) continue;
    if (!value.is_array() || value.size() != 2)
      throwMalformed(name, where + " " + jointText, "is not an [x, y] pair");
    k.jointsPx(2 * index(*joint)) = coordinate(value[0], name, where + " " + jointText);
    k.jointsPx(2 * index(*joint) + 1) = coordinate(value[1], name, where + " " + jointText);
  }
  return k;
}

void sortByFrame(std::vector<Keyframe>& keyframes) {
  std::sort(keyframes.begin(), keyframes.end(),
            [](const Keyframe& a, const Keyframe& b) { return a.frame < b.frame; });
}

bool hasAJoint(const Keyframe& k) { return !k.jointsPx.array().isNaN().all(); }

// "812.5", "-10", "1e+300": six significant digits at most, for an error message.
std::string shortNumber(double v) {
  std::ostringstream out;
  out << std::setprecision(6) << v;
  return out.str();
}

}  // namespace

Keyframes parseKeyframes(const std::string& text, const std::string& name) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throwMalformed(name, "byte " + std::to_string(e.byte), "not JSON");
  } catch (const json::exception& e) {  // valid JSON the reader cannot hold: a number past 1e308
    throwMalformed(name, "", std::string("not JSON a reader can hold: ") + e.what());
  }
  const auto format = root.is_object() ? root.find("format") : root.end();
  if (format == root.end() || !format->is_string() || format->get<std::string>() != kFormatName)
    throwMalformed(
        name, "", std::string("not a keyframe file (\"format\": \"") + kFormatName + "\" missing)");
  if (!root.contains("version") || !root["version"].is_number_integer() ||
      root["version"].get<long long>() != kFormatVersion)
    throwMalformed(name, "", "keyframe file version is not 1");
  const auto list = root.find("keyframes");
  if (list == root.end() || !list->is_array())
    throwMalformed(name, "", "has no \"keyframes\" list");
  if (list->size() > static_cast<std::size_t>(kMaxKeyframes))
    throwMalformed(name, "", "more than " + std::to_string(kMaxKeyframes) + " keyframes");
  Keyframes out;
  if (const auto video = root.find("video"); video != root.end() && video->is_string())
    out.video = video->get<std::string>();
  std::set<int> seen;
  for (std::size_t i = 0; i < list->size(); ++i) {
    Keyframe k = parseKeyframe((*list)[i], name, i);
    if (!seen.insert(k.frame).second)
      throwMalformed(name, "keyframe " + std::to_string(i),
                     "frame " + std::to_string(k.frame) + " is marked twice");
    out.keyframes.push_back(std::move(k));
  }
  sortByFrame(out.keyframes);
  if (std::none_of(out.keyframes.begin(), out.keyframes.end(), hasAJoint))
    throwBadData(name, "", "no keyframe has a marked joint");
  return out;
}

void checkMarksWithin(const Keyframes& keyframes, int widthPx, int heightPx, const std::string& file) {
  const double marginX = kMarkMarginShare * widthPx, marginY = kMarkMarginShare * heightPx;
  const auto within = [](double v, double size, double margin) { return v >= -margin && v <= size + margin; };
  for (const Keyframe& k : keyframes.keyframes) {
    for (int j = 0; j < kJointCount; ++j) {
      const double x = k.jointsPx(2 * j), y = k.jointsPx(2 * j + 1);
      if (std::isnan(x) || std::isnan(y) || (within(x, widthPx, marginX) && within(y, heightPx, marginY)))
        continue;
      throwBadData(file, "keyframe on frame " + std::to_string(k.frame) + " " + std::string(kJointNames[j]),
                   "marked at (" + shortNumber(x) + ", " + shortNumber(y) + "), far outside the " +
                       std::to_string(widthPx) + "x" + std::to_string(heightPx) +
                       " picture (not marked on this video?)");
    }
  }
}

void checkKeyframesWithin(const Keyframes& keyframes, int frameCount, const std::string& file) {
  for (const Keyframe& k : keyframes.keyframes)
    if (k.frame >= frameCount)
      throwBadData(file, "keyframe on frame " + std::to_string(k.frame),
                   "the video has " + std::to_string(frameCount) + " frames (0-" + std::to_string(frameCount - 1) +
                       "): not marked on this video?");
}

bool isKeyframeFile(const std::filesystem::path& path) {
  if (path.extension() != ".json") return false;
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head.find("\"eigenwalker-keyframes\"") != std::string::npos;
}

Keyframes readKeyframes(const std::filesystem::path& file) {
  return parseKeyframes(readFileText(file), file.string());
}

std::string formatKeyframes(const Keyframes& keyframes) {
  json list = json::array();
  for (const Keyframe& k : keyframes.keyframes) {
    json joints = json::object();
    for (int j = 0; j < kJointCount; ++j) {
      const double x = k.jointsPx(2 * j), y = k.jointsPx(2 * j + 1);
      joints[std::string(kJointNames[j])] =
          std::isnan(x) || std::isnan(y) ? json(nullptr) : json::array({x, y});
    }
    list.push_back({{"frame", k.frame}, {"joints", joints}});
  }
  const json root = {{"format", kFormatName},
                     {"version", kFormatVersion},
                     {"video", keyframes.video},
                     {"keyframes", list}};
  return root.dump(1) + "\n";
}

void writeKeyframes(const std::filesystem::path& file, const Keyframes& keyframes) {
  const std::string text = formatKeyframes(keyframes);
  writeFileAtomically(file, [&](std::ostream& out) { out << text; });
}

Keyframes keyframesFromTrack(const Eigen::Ref<const Eigen::MatrixXd>& jointsPx,
                             const std::vector<int>& frames, const std::string& video) {
  if (jointsPx.cols() != kDims2)
    throw Error(ErrorKind::BadArgument, video, "", "a 2D track has 30 columns");
  Keyframes out;
  out.video = video;
  for (const int f : std::set<int>(frames.begin(), frames.end())) {  // in order, each once
    if (f < 0 || f >= jointsPx.rows())
      throw Error(ErrorKind::BadArgument, video, "frame " + std::to_string(f),
                  "outside the track's frames 0-" + std::to_string(jointsPx.rows() - 1));
    Keyframe k{f, jointsPx.row(f)};
    if (!hasAJoint(k))
      throw Error(ErrorKind::BadArgument, video, "frame " + std::to_string(f),
                  "has no joint to start from");
    out.keyframes.push_back(std::move(k));
  }
  return out;
}

}  // namespace ew
