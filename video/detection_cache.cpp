#include "video/detection_cache.h"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/errors.h"
#include "core/io/atomic_write.h"

namespace ew {
namespace {

// Bumped whenever the detector's output for the same options changes, so that old cache files
// are not taken for new results.
constexpr int kCacheVersion = 2;

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 33);
}

nlohmann::json roiJson(const PoseRoi& r) { return {r.centre.x, r.centre.y, r.sidePx, r.rotationRad}; }

PoseRoi roiFrom(const nlohmann::json& j) {
  PoseRoi r;
  r.centre = {j.at(0).get<double>(), j.at(1).get<double>()};
  r.sidePx = j.at(2).get<double>();
  r.rotationRad = j.at(3).get<double>();
  return r;
}

nlohmann::json optionsJson(const PoseDetectionOptions& o) {
  return {{"version", kCacheVersion},       {"model", poseModelSizeName(o.model)},
          {"tiles", o.tiles},               {"search_every_s", o.searchEverySeconds},
          {"max_people", o.maxPeople},      {"min_pose_score", o.minPoseScore},
          {"fix_left_right", o.fixLeftRight}, {"smooth_s", o.smoothSeconds}, {"first", o.firstFrame},
          {"last", o.lastFrame}};
}

}  // namespace

std::string videoContentKey(const std::filesystem::path& video) {
  std::ifstream in(video, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, video.string(), "", "cannot open the video to hash it");
  std::uint64_t h = 0x243f6a8885a308d3ULL, size = 0;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    const auto n = static_cast<std::size_t>(in.gcount());
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, buffer.data() + i, 8);
      h = mix(h, word);
    }
    for (; i < n; ++i) h = mix(h, static_cast<unsigned char>(buffer[i]));
    size += n;
  }
  std::ostringstream key;
  key << std::hex << std::setw(16) << std::setfill('0') << mix(h, size) << std::dec << "-" << size;
  return key.str();
}

std::filesystem::path detectionCacheFolder() {
  if (const char* env = std::getenv("EIGENWALKER_CACHE"); env && *env) return std::filesystem::path(env) / "detections";
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "eigenwalker" / "detections";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "eigenwalker" / "detections";
  return std::filesystem::temp_directory_path() / "eigenwalker" / "detections";
}

std::filesystem::path detectionCacheFile(const std::string& contentKey, const PoseDetectionOptions& options) {
  std::uint64_t h = 0;
  for (char c : optionsJson(options).dump()) h = mix(h, static_cast<unsigned char>(c));
  std::ostringstream name;
  name << contentKey << "-" << poseModelSizeName(options.model) << "-" << std::hex << (h & 0xffffffffULL) << ".json";
  return detectionCacheFolder() / name.str();
}

std::string saveCachedDetections(const std::filesystem::path& cacheFile, const PoseDetectionRun& run) {
  if (run.cancelled) return "a cancelled run is not cached";
  nlohmann::json frames = nlohmann::json::array();
  for (const auto& poses : run.poses) {
    nlohmann::json people = nlohmann::json::array();
    for (const FollowedPose& p : poses) {
      nlohmann::json points = nlohmann::json::array();
      for (const Landmark& lm : p.landmarks.points) points.push_back({lm.x, lm.y, lm.z, lm.visibility, lm.presence});
      const auto& l = p.landmarks;
      people.push_back({{"id", p.personId},
                        {"score", l.poseScore},
                        {"roi", roiJson(l.roi)},
                        {"align", {l.hipCentre.x, l.hipCentre.y, l.scalePoint.x, l.scalePoint.y}},
                        {"points", points}});
    }
    frames.push_back(people);
  }
  const nlohmann::json doc = {{"eigenwalker_detections", kCacheVersion},
                              {"video", {{"width", run.video.widthPx}, {"height", run.video.heightPx},
                                         {"fps", run.video.fps}, {"frames", run.video.frameCount},
                                         {"codec", run.video.codec}}},
                              {"model", poseModelSizeName(run.model)},
                              {"first_frame", run.firstFrame},
                              {"people", run.people},
                              {"swaps_undone", run.leftRightSwapsUndone},
                              {"warnings", run.warnings},
                              {"frames", frames}};
  try {
    std::error_code ec;
    std::filesystem::create_directories(cacheFile.parent_path(), ec);
    writeFileAtomically(cacheFile, [&](std::ostream& out) { out << doc.dump() << "\n"; });
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::optional<PoseDetectionRun> loadCachedDetections(const std::filesystem::path& cacheFile,
                                                     const std::filesystem::path& video) {
  std::ifstream in(cacheFile);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json doc = nlohmann::json::parse(in);
    if (doc.at("eigenwalker_detections").get<int>() != kCacheVersion) return std::nullopt;
    PoseDetectionRun run;
    const auto& v = doc.at("video");
    run.video.file = video.string();
    run.video.widthPx = v.at("width").get<int>();
    run.video.heightPx = v.at("height").get<int>();
    run.video.fps = v.at("fps").get<double>();
    run.video.frameCount = v.at("frames").get<int>();
    run.video.codec = v.at("codec").get<std::string>();
    run.model = parsePoseModelSize(doc.at("model").get<std::string>());
    run.firstFrame = doc.at("first_frame").get<int>();
    run.people = doc.at("people").get<int>();
    run.leftRightSwapsUndone = doc.at("swaps_undone").get<int>();
    run.warnings = doc.at("warnings").get<std::vector<std::string>>();
    for (const auto& people : doc.at("frames")) {
      std::vector<FollowedPose> poses;
      for (const auto& p : people) {
        FollowedPose f;
        f.personId = p.at("id").get<int>();
        f.landmarks.poseScore = p.at("score").get<double>();
        f.landmarks.roi = roiFrom(p.at("roi"));
        const auto& a = p.at("align");
        f.landmarks.hipCentre = {a.at(0).get<double>(), a.at(1).get<double>()};
        f.landmarks.scalePoint = {a.at(2).get<double>(), a.at(3).get<double>()};
        const auto& pts = p.at("points");
        if (pts.size() != f.landmarks.points.size()) return std::nullopt;
        for (std::size_t i = 0; i < pts.size(); ++i) {
          Landmark& lm = f.landmarks.points[i];
          lm.x = pts[i].at(0).get<double>(), lm.y = pts[i].at(1).get<double>(), lm.z = pts[i].at(2).get<double>();
          lm.visibility = pts[i].at(3).get<double>(), lm.presence = pts[i].at(4).get<double>();
        }
        poses.push_back(std::move(f));
      }
      run.poses.push_back(std::move(poses));
    }
    return run;
  } catch (const std::exception&) {
    return std::nullopt;  // damaged or from another version: detect again
  }
}

PoseDetectionRun detectPosesCached(const std::filesystem::path& video, const PoseDetectionOptions& options,
                                   bool& fromCache, bool useCache) {
  fromCache = false;
  if (!useCache) return detectPoses(video, options);
  const auto file = detectionCacheFile(videoContentKey(video), options);
  if (auto cached = loadCachedDetections(file, video)) {
    fromCache = true;
    return *cached;
  }
  PoseDetectionRun run = detectPoses(video, options);
  if (const std::string problem = saveCachedDetections(file, run); !problem.empty())
    run.warnings.push_back("the detections were not cached: " + problem);
  return run;
}

}  // namespace ew
