#include "core/keypoints/keypoint_writers.h"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/errors.h"
#include "core/io/atomic_write.h"

namespace ew {
namespace {

const KeypointDetection* detectionOf(const std::vector<KeypointDetection>& frame, int person) {
  for (const auto& d : frame)
    if (d.trackId == person) return &d;
  return nullptr;
}

std::string frameFileName(const std::string& stem, int frame) {
  std::ostringstream name;
  name << stem << "_" << std::setw(12) << std::setfill('0') << frame << "_keypoints.json";
  return name.str();
}

}  // namespace

void writeMediaPipeCsv(const std::filesystem::path& file, const KeypointFrames& frames, int person,
                       const std::vector<std::string>& pointNames) {
  if (!frames.imageSize || frames.imageSize->width <= 0 || frames.imageSize->height <= 0)
    throw Error(ErrorKind::BadArgument, file.string(), "", "a MediaPipe CSV needs the image size");
  if (static_cast<int>(pointNames.size()) != frames.pointCount)
    throw Error(ErrorKind::BadArgument, file.string(), "",
                std::to_string(pointNames.size()) + " point names for " + std::to_string(frames.pointCount) + " points");
  const double w = frames.imageSize->width, h = frames.imageSize->height;
  const double rate = frames.rateHz.value_or(0.0);
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "# image_size=" << frames.imageSize->width << "x" << frames.imageSize->height << "\n";
    out << "frame" << (rate > 0 ? ",time_s" : "");
    for (const auto& n : pointNames) out << "," << n << "_x," << n << "_y," << n << "_visibility";
    out << "\n" << std::setprecision(9);
    for (int f = 0; f < frames.frameCount(); ++f) {
      out << f;
      if (rate > 0) out << "," << f / rate;
      const KeypointDetection* d = detectionOf(frames.frames[static_cast<std::size_t>(f)], person);
      for (int p = 0; p < frames.pointCount; ++p) {
        if (!d || !std::isfinite(d->points(p, 0)) || !std::isfinite(d->points(p, 1))) {
          out << ",,,";
          continue;
        }
        out << "," << d->points(p, 0) / w << "," << d->points(p, 1) / h << "," << d->points(p, 2);
      }
      out << "\n";
    }
  });
}

void writeOpenPoseJson(const std::filesystem::path& folder, const std::string& stem, const KeypointFrames& frames) {
  const auto target = folderPathWithoutTrailingSeparator(folder);
  const auto tmp = target.parent_path() / (target.filename().string() + ".tmp");
  std::error_code ec;
  std::filesystem::remove_all(tmp, ec);
  std::filesystem::create_directories(tmp, ec);
  if (ec) throw Error(ErrorKind::Io, tmp.string(), "", "cannot create the folder: " + ec.message());
  try {
    for (int f = 0; f < frames.frameCount(); ++f) {
      nlohmann::json people = nlohmann::json::array();
      for (const auto& d : frames.frames[static_cast<std::size_t>(f)]) {
        nlohmann::json flat = nlohmann::json::array();
        for (int p = 0; p < d.points.rows(); ++p) {
          const bool seen = std::isfinite(d.points(p, 0)) && std::isfinite(d.points(p, 1));
          flat.push_back(seen ? d.points(p, 0) : 0.0);
          flat.push_back(seen ? d.points(p, 1) : 0.0);
          flat.push_back(seen && std::isfinite(d.points(p, 2)) ? d.points(p, 2) : 0.0);
        }
        people.push_back({{"person_id", {d.trackId}}, {"pose_keypoints_2d", flat}});
      }
      const nlohmann::json doc = {{"version", 1.3}, {"people", people}};
      writeFileAtomically(tmp / frameFileName(stem, f), [&](std::ostream& out) { out << doc.dump() << "\n"; });
    }
    std::filesystem::remove_all(target, ec);
    std::filesystem::rename(tmp, target, ec);
    if (ec) throw Error(ErrorKind::Io, target.string(), "", "cannot move the frames into place: " + ec.message());
  } catch (...) {
    std::filesystem::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace ew
