#pragma once
// A track's files, as `eigenwalker-cli track --out DIR` and the viewer's *Save the track* write
// them: DIR/keypoints/ as OpenPose BODY_25 JSON (one file a frame, with each joint's confidence;
// what other tools read), DIR/track_2d.csv (the project's 2D CSV: pixels, v up, the first
// video frame in its header) and DIR/confidence.csv (frame, then one column a joint).

#include <filesystem>

#include "video/joint_tracker.h"

namespace ew {

// Creates DIR when missing; an older track's keypoints/ is replaced, not mixed with this one's.
// Each file is written whole or not at all (core/io/atomic_write.h); Error(Io) naming the file.
void writeTrackFiles(const std::filesystem::path& dir, const JointTrack& track);

}  // namespace ew
