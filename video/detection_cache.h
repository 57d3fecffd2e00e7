#pragma once
// Detections kept per video, so that a second run on the same footage (reconstruct after
// detect, gait after info, the viewer after the CLI) does not detect again: keyed by the
// video's content (a 64-bit hash of every byte and its size), the model and the options that
// change the result. In $EIGENWALKER_CACHE, else $XDG_CACHE_HOME/eigenwalker, else
// ~/.cache/eigenwalker, under detections/. A damaged or foreign cache file is ignored and
// overwritten, never trusted.
#include <filesystem>
#include <optional>
#include <string>

#include "video/pose_detector.h"

namespace ew {

// The hash of the file's bytes and size, as 16 hex digits + "-" + size. Error(Io) naming it
// when it cannot be read.
std::string videoContentKey(const std::filesystem::path& video);

std::filesystem::path detectionCacheFolder();

// The cache file for this video content and these options.
std::filesystem::path detectionCacheFile(const std::string& contentKey, const PoseDetectionOptions& options);

// The cached run, or nullopt when there is none or it cannot be read back whole.
std::optional<PoseDetectionRun> loadCachedDetections(const std::filesystem::path& cacheFile,
                                                     const std::filesystem::path& video);

// Writes the run (atomically); a run that was cancelled is not cached. Errors are not thrown:
// a cache that cannot be written only costs time, and is said in the returned text ("" on success).
std::string saveCachedDetections(const std::filesystem::path& cacheFile, const PoseDetectionRun& run);

// detectPoses through the cache; `fromCache` says which happened.
PoseDetectionRun detectPosesCached(const std::filesystem::path& video, const PoseDetectionOptions& options,
                                   bool& fromCache, bool useCache = true);

}  // namespace ew
