#include "core/keypoints/keypoint_frames.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/io/file_bytes.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json parseJson(const std::string& text, const std::string& file) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    throwMalformed(file, "", std::string("not JSON: ") + e.what());
  }
}

double number(const json& v, const std::string& file, const std::string& where) {
  if (!v.is_number()) throwMalformed(file, where, "keypoint values must be numbers, found " + v.dump());
  const double x = v.get<double>();
  if (!std::isfinite(x)) throwMalformed(file, where, "keypoint value is not finite");
  return x;
}

// P x 3 from a flat [x, y, c, x, y, c, …] list. OpenPose writes 0, 0, 0 for a point it did
// not find: any point with confidence 0 is absent.
Eigen::MatrixX3d fromTriples(const json& flat, const std::string& file, const std::string& where) {
  if (!flat.is_array() || flat.size() % 3 != 0)
    throwMalformed(file, where, "keypoints must be a list of x, y, confidence triples");
  const auto p = static_cast<Eigen::Index>(flat.size() / 3);
  if (p > kMaxKeypointsPerPerson)
    throwMalformed(file, where, std::to_string(p) + " keypoints per person, more than " +
                               std::to_string(kMaxKeypointsPerPerson));
  Eigen::MatrixX3d out(p, 3);
  for (Eigen::Index i = 0; i < p; ++i) {
    for (int c = 0; c < 3; ++c) out(i, c) = number(flat[static_cast<std::size_t>(3 * i + c)], file, where);
    if (out(i, 2) <= 0.0) out.row(i) << kNaN, kNaN, 0.0;
  }
  return out;
}

// Every detection must have the same number of points; the first one sets it.
void addDetection(KeypointFrames& out, std::vector<KeypointDetection>& frame, KeypointDetection d,
                  const std::string& where) {
  const int p = static_cast<int>(d.points.rows());
  if (out.pointCount == 0) out.pointCount = p;
  if (p != out.pointCount)
    throwMalformed(out.file, where, std::to_string(p) + " keypoints where earlier detections had " +
                                   std::to_string(out.pointCount));
  if (static_cast<int>(frame.size()) >= kMaxPeoplePerFrame)
    throwMalformed(out.file, where, "more than " + std::to_string(kMaxPeoplePerFrame) + " people in one frame");
  frame.push_back(std::move(d));
}

void checkNotEmpty(const KeypointFrames& out) {
  if (out.frames.empty()) throw Error(ErrorKind::BadData, out.file, "", "no frames");
  const bool anybody = std::any_of(out.frames.begin(), out.frames.end(), [](const auto& f) { return !f.empty(); });
  if (!anybody) throw Error(ErrorKind::BadData, out.file, "", "no person detected in any of the " +
                                                                  std::to_string(out.frames.size()) + " frames");
}

void addFrame(KeypointFrames& out) {
  if (out.frameCount() >= kMaxKeypointFrames)
    throwMalformed(out.file, "", "more than " + std::to_string(kMaxKeypointFrames) + " frames");
  out.frames.emplace_back();
}

}  // namespace

long trailingNumber(const std::string& name) {
  const std::string stem = fs::path(name).stem().string();
  long value = -1;
  for (std::size_t i = 0; i < stem.size();) {
    if (!std::isdigit(static_cast<unsigned char>(stem[i]))) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < stem.size() && std::isdigit(static_cast<unsigned char>(stem[j]))) ++j;
    value = j - i < 15 ? std::stol(stem.substr(i, j - i)) : -1;
    i = j;
  }
  return value;
}

namespace {

// [SECTION] Frames placed by their numbers ---------------------------------------------------

void checkFrameSpan(long first, long last, const std::string& name) {
  if (last - first >= kMaxKeypointFrames)
    throwMalformed(name, "", "frames numbered " + std::to_string(first) + " to " + std::to_string(last) +
                                 ": more than " + std::to_string(kMaxKeypointFrames) + " frames");
}

// The frame numbers of per-frame files in the order given (sorted by number), when every file
// has one and no two share one; else empty (the files are then taken as consecutive frames).
std::vector<long> frameNumbersInOrder(const std::vector<std::pair<std::string, std::string>>& files,
                                      const std::string& name) {
  std::vector<long> numbers;
  for (const auto& f : files) numbers.push_back(trailingNumber(f.first));
  const bool placeable = numbers.size() > 1 && numbers.front() >= 0 &&
                         std::adjacent_find(numbers.begin(), numbers.end(),
                                            [](long a, long b) { return b <= a; }) == numbers.end();
  if (!placeable) return {};
  checkFrameSpan(numbers.front(), numbers.back(), name);
  return numbers;
}

long addEmptyFrames(KeypointFrames& out, long count) {
  for (long i = 0; i < count; ++i) addFrame(out);
  return std::max(count, 0L);
}

void warnOfMissingFrames(KeypointFrames& out, long missing, const std::string& what) {
  if (missing > 0)
    out.warnings.push_back(std::to_string(missing) + " of the " + std::to_string(out.frameCount()) +
                           " frames have no " + what + " (their numbers are missing): taken as frames with nobody");
}

// [SECTION] OpenPose ---------------------------------------------------------------------

void addOpenPoseFrame(KeypointFrames& out, const json& doc, const std::string& where) {
  if (!doc.is_object() || !doc.contains("people") || !doc["people"].is_array())
    throwMalformed(out.file, where, "an OpenPose frame must be an object with a \"people\" list");
  addFrame(out);
  for (std::size_t k = 0; k < doc["people"].size(); ++k) {
    const json& person = doc["people"][k];
    const std::string at = where + " people[" + std::to_string(k) + "]";
    if (!person.is_object() || !person.contains("pose_keypoints_2d"))
      throwMalformed(out.file, at, "a person must have \"pose_keypoints_2d\"");
    KeypointDetection d{fromTriples(person["pose_keypoints_2d"], out.file, at), -1};
    if (d.points.rows() == 0) continue;  // OpenPose writes [] when the body model was off
    if (person.contains("person_id")) {
      const json& id = person["person_id"];
      const json& first = id.is_array() && !id.empty() ? id[0] : id;
      if (first.is_number_integer() && first.get<long>() >= 0 && first.get<long>() < 1000000)
        d.trackId = static_cast<int>(first.get<long>());
    }
    addDetection(out, out.frames.back(), std::move(d), at);
  }
}

// [SECTION] AlphaPose --------------------------------------------------------------------

// AlphaPose's image_id is the image's file name ("12.jpg") or a number; frames follow its
// numeric part, or the order of first appearance when it has none.
long imageKey(const json& id, std::map<std::string, long>& seen) {
  if (id.is_number_integer()) return id.get<long>();
  const std::string s = id.is_string() ? id.get<std::string>() : id.dump();
  const long n = trailingNumber(s);
  if (n >= 0) return n;
  return seen.emplace(s, static_cast<long>(seen.size())).first->second;
}

// [SECTION] MMPose -----------------------------------------------------------------------

Eigen::MatrixX3d fromPairsAndScores(const json& kp, const json* scores, const std::string& file,
                                    const std::string& where) {
  if (!kp.is_array()) throwMalformed(file, where, "\"keypoints\" must be a list of [x, y] pairs");
  const auto p = static_cast<Eigen::Index>(kp.size());
  if (p > kMaxKeypointsPerPerson)
    throwMalformed(file, where, std::to_string(p) + " keypoints per person, more than " +
                               std::to_string(kMaxKeypointsPerPerson));
  if (scores && (!scores->is_array() || scores->size() != kp.size()))
    throwMalformed(file, where, "\"keypoint_scores\" must list one score per keypoint");
  Eigen::MatrixX3d out(p, 3);
  for (Eigen::Index i = 0; i < p; ++i) {
    const json& xy = kp[static_cast<std::size_t>(i)];
    if (!xy.is_array() || xy.size() < 2) throwMalformed(file, where, "a keypoint must be [x, y]");
    out(i, 0) = number(xy[0], file, where);
    out(i, 1) = number(xy[1], file, where);
    out(i, 2) = scores ? number((*scores)[static_cast<std::size_t>(i)], file, where) : 1.0;
    if (out(i, 2) <= 0.0) out.row(i) << kNaN, kNaN, 0.0;
  }
  return out;
}

void addMmposeInstances(KeypointFrames& out, const json& instances, const std::string& where) {
  if (!instances.is_array()) throwMalformed(out.file, where, "\"instances\" must be a list");
  for (std::size_t k = 0; k < instances.size(); ++k) {
    const json& inst = instances[k];
    const std::string at = where + " instances[" + std::to_string(k) + "]";
    if (!inst.is_object() || !inst.contains("keypoints")) throwMalformed(out.file, at, "an instance needs \"keypoints\"");
    const json* scores = inst.contains("keypoint_scores") ? &inst["keypoint_scores"] : nullptr;
    KeypointDetection d{fromPairsAndScores(inst["keypoints"], scores, out.file, at), -1};
    if (inst.contains("track_id") && inst["track_id"].is_number_integer())
      d.trackId = static_cast<int>(std::clamp<long>(inst["track_id"].get<long>(), -1, 1000000));
    addDetection(out, out.frames.back(), std::move(d), at);
  }
}

// MMPose's dataset names for the layouts we know.
std::optional<std::string> layoutFromDatasetName(const std::string& name) {
  std::string n;
  for (char c : name) n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n == "coco" || n == "coco17") return "COCO-17";
  if (n.rfind("halpe", 0) == 0 && n.find("26") != std::string::npos) return "Halpe-26";
  return std::nullopt;
}

bool hasExtension(const fs::path& path, const std::string& lowerCase) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == lowerCase;
}

bool isCsvPath(const fs::path& path) { return hasExtension(path, ".csv"); }

}  // namespace

// [SECTION] Public API -----------------------------------------------------------------------

KeypointFrames parseOpenPoseFrames(const std::vector<std::pair<std::string, std::string>>& filesAndTexts,
                                   const std::string& name) {
  KeypointFrames out;
  out.file = name;
  out.format = "OpenPose JSON";
  const std::vector<long> numbers = frameNumbersInOrder(filesAndTexts, name);
  long missing = 0;
  for (std::size_t k = 0; k < filesAndTexts.size(); ++k) {
    const auto& [file, text] = filesAndTexts[k];
    const json doc = parseJson(text, name + "/" + file);
    if (doc.is_array()) {  // one file holding a list of frames
      for (std::size_t f = 0; f < doc.size(); ++f) addOpenPoseFrame(out, doc[f], "frame " + std::to_string(f));
    } else {
      if (k > 0 && !numbers.empty()) missing += addEmptyFrames(out, numbers[k] - numbers[k - 1] - 1);
      addOpenPoseFrame(out, doc, file);
    }
  }
  checkNotEmpty(out);
  warnOfMissingFrames(out, missing, "file");
  return out;
}

KeypointFrames parseAlphaPoseJson(const std::string& text, const std::string& name) {
  const json doc = parseJson(text, name);
  if (!doc.is_array()) throwMalformed(name, "", "AlphaPose results are a list of detections");
  // What AlphaPose writes for a video with nobody in it: a result, not a malformed file, and
  // nothing to place frames by (there is no first or last image).
  if (doc.empty()) throw Error(ErrorKind::BadData, name, "", "no person detected (an empty list of detections)");
  KeypointFrames out;
  out.file = name;
  out.format = "AlphaPose JSON";
  std::map<std::string, long> seen;
  std::map<long, std::vector<std::size_t>> byFrame;
  for (std::size_t k = 0; k < doc.size(); ++k) {
    const json& d = doc[k];
    if (!d.is_object() || !d.contains("image_id") || !d.contains("keypoints"))
      throwMalformed(name, "detection " + std::to_string(k), "needs \"image_id\" and \"keypoints\"");
    byFrame[imageKey(d["image_id"], seen)].push_back(k);
  }
  // Numbered images are frames of a video: AlphaPose lists none for an image with nobody.
  const bool numbered = seen.empty();
  if (numbered) checkFrameSpan(byFrame.begin()->first, byFrame.rbegin()->first, name);
  long missing = 0;
  for (auto it = byFrame.begin(); it != byFrame.end(); ++it) {
    const auto& [frame, detections] = *it;
    if (numbered && it != byFrame.begin()) missing += addEmptyFrames(out, frame - std::prev(it)->first - 1);
    addFrame(out);
    for (std::size_t k : detections) {
      const std::string at = "detection " + std::to_string(k) + " (image " + std::to_string(frame) + ")";
      KeypointDetection det{fromTriples(doc[k]["keypoints"], name, at), -1};
      if (doc[k].contains("idx") && doc[k]["idx"].is_number_integer())
        det.trackId = static_cast<int>(std::clamp<long>(doc[k]["idx"].get<long>(), -1, 1000000));
      addDetection(out, out.frames.back(), std::move(det), at);
    }
  }
  checkNotEmpty(out);
  warnOfMissingFrames(out, missing, "detection");
  return out;
}

KeypointFrames parseMmposeJson(const std::string& text, const std::string& name) {
  const json doc = parseJson(text, name);
  KeypointFrames out;
  out.file = name;
  out.format = "MMPose JSON";
  if (doc.is_object() && doc.contains("meta_info") && doc["meta_info"].is_object() &&
      doc["meta_info"].contains("dataset_name") && doc["meta_info"]["dataset_name"].is_string())
    out.layoutHint = layoutFromDatasetName(doc["meta_info"]["dataset_name"].get<std::string>());
  if (doc.is_object() && doc.contains("instance_info")) {  // a video: frames with frame_id
    const json& frames = doc["instance_info"];
    if (!frames.is_array()) throwMalformed(name, "instance_info", "must be a list of frames");
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const std::string at = "instance_info[" + std::to_string(f) + "]";
      if (!frames[f].is_object() || !frames[f].contains("instances"))
        throwMalformed(name, at, "a frame needs \"instances\"");
      addFrame(out);
      addMmposeInstances(out, frames[f]["instances"], at);
    }
  } else if (doc.is_array()) {  // one image: its instances
    addFrame(out);
    addMmposeInstances(out, doc, "instances");
  } else {
    throwMalformed(name, "", "MMPose results need \"instance_info\" (a video) or a list of instances");
  }
  checkNotEmpty(out);
  return out;
}

bool looksLikeKeypointInput(const fs::path& path) {
  std::error_code ec;
  if (yoloLabelsFolder(path) || isPlanarTrc(path)) return true;
  if (fs::is_directory(path, ec)) {
    for (const auto& e : fs::directory_iterator(path, ec)) {
      if (e.path().extension() == ".json") return true;
    }
    return false;
  }
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".csv") return sniffKeypointCsv(path) != KeypointCsvKind::NotKeypoints;  // not our joint CSVs
  return ext == ".json";
}

KeypointImageSize parseKeypointImageSize(const std::string& text, const std::string& option) {
  const auto x = text.find_first_of("xX");
  KeypointImageSize size;
  try {
    std::size_t wEnd = 0, hEnd = 0;
    if (x == std::string::npos) throw std::invalid_argument("no x");
    size.width = std::stoi(text.substr(0, x), &wEnd);
    size.height = std::stoi(text.substr(x + 1), &hEnd);
    if (wEnd != x || hEnd != text.size() - x - 1) throw std::invalid_argument("trailing text");
  } catch (const std::exception&) {
    throw Error(ErrorKind::BadArgument, "", option, "'" + text + "' is not an image size like 1920x1080");
  }
  if (size.width < 1 || size.height < 1 || size.width > kMaxKeypointImageSidePx || size.height > kMaxKeypointImageSidePx)
    throw Error(ErrorKind::BadArgument, "", option,
                "'" + text + "': each side must be 1-" + std::to_string(kMaxKeypointImageSidePx) + " px");
  return size;
}

std::vector<std::pair<std::string, std::string>> readPerFrameFiles(const fs::path& folder, const std::string& extension) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (e.path().extension() == extension) files.push_back(e.path());
    if (static_cast<int>(files.size()) > kMaxKeypointFrames)
      throwMalformed(folder.string(), "", "more than " + std::to_string(kMaxKeypointFrames) + " " + extension + " files");
  }
  if (ec) throw Error(ErrorKind::Io, folder.string(), "", "cannot list the folder: " + ec.message());
  if (files.empty()) throw Error(ErrorKind::BadData, folder.string(), "", "no " + extension + " files in the folder");
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    const long na = trailingNumber(a.filename().string()), nb = trailingNumber(b.filename().string());
    return na != nb ? na < nb : a.filename() < b.filename();
  });
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& f : files) out.emplace_back(f.filename().string(), readFileText(f));
  return out;
}

KeypointFrames readKeypointFrames(const fs::path& path, const std::optional<KeypointImageSize>& imageSize,
                                  const std::optional<KeypointImageSize>& videoSize) {
  std::error_code ec;
  if (const auto labels = yoloLabelsFolder(path)) return readYoloPoseLabels(*labels, imageSize ? imageSize : videoSize);
  if (fs::is_directory(path, ec)) return parseOpenPoseFrames(readPerFrameFiles(path, ".json"), path.string());
  if (isCsvPath(path)) return readKeypointCsv(path, imageSize, videoSize);
  if (hasExtension(path, ".trc"))
    throw Error(ErrorKind::BadArgument, path.string(), "",
                "a TRC of 3D points (motion capture), not a pose estimator's 2D keypoints (a 2D TRC has Z = 0)");
  const std::string text = readFileText(path);
  const json doc = parseJson(text, path.string());
  const bool openPose = (doc.is_object() && doc.contains("people")) ||
                        (doc.is_array() && !doc.empty() && doc[0].is_object() && doc[0].contains("people"));
  if (openPose) return parseOpenPoseFrames({{path.filename().string(), text}}, path.string());
  // `[]` is AlphaPose's "nobody in the video" (an empty OpenPose or MMPose list says the same).
  if (doc.is_array() && (doc.empty() || (doc[0].is_object() && doc[0].contains("image_id"))))
    return parseAlphaPoseJson(text, path.string());
  if ((doc.is_object() && doc.contains("instance_info")) ||
      (doc.is_array() && !doc.empty() && doc[0].is_object() && doc[0].contains("keypoint_scores")))
    return parseMmposeJson(text, path.string());
  throwMalformed(path.string(), "",
            "not a keypoint file we read: expected OpenPose (\"people\"), AlphaPose (a list with "
            "\"image_id\") or MMPose (\"instance_info\") JSON");
}

}  // namespace ew
