#include "video/track_files.h"

#include <ostream>
#include <system_error>

#include "core/common/errors.h"
#include "core/experiments/view_csv.h"
#include "core/io/atomic_write.h"
#include "core/keypoints/openpose_writer.h"

namespace ew {

namespace {

void writeConfidence(const std::filesystem::path& file, const JointTrack& t) {
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "frame";
    for (const auto name : kJointNames) out << "," << name;
    out << "\n";
    for (Eigen::Index r = 0; r < t.confidence.rows(); ++r) {
      out << t.firstFrame + r;
      for (int j = 0; j < kJointCount; ++j) out << "," << t.confidence(r, j);
      out << "\n";
    }
  });
}

}  // namespace

void writeTrackFiles(const std::filesystem::path& dir, const JointTrack& t) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(ErrorKind::Io, dir.string(), "", "cannot create the folder: " + ec.message());
  const std::filesystem::path keypoints = dir / "keypoints";
  std::filesystem::remove_all(keypoints, ec);
  writeOpenPoseBody25(keypoints, {OpenPosePerson{t.jointsPx, t.confidence}});
  ViewSequence view;
  view.rateHz = t.fps;
  view.framesMm = t.jointsPx;
  for (int j = 0; j < kJointCount; ++j) view.framesMm.col(2 * j + 1) *= -1.0;
  writeViewCsv(dir / "track_2d.csv", view,
               {"units=px (image pixels; u right, v up = minus the image row)",
                "first_video_frame=" + std::to_string(t.firstFrame)});
  writeConfidence(dir / "confidence.csv", t);
}

}  // namespace ew
