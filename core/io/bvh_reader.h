#pragma once
// BVH reader: hierarchy (any channel order, 3 or 6 channels on any joint, End Sites,
// CRLF or LF), motion block, forward kinematics to global joint positions. Several roots
// are rejected. The CMU conversion's synthetic T-pose first frame is detected and dropped.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

RawTrial readBvh(const std::filesystem::path& file, const LoadOptions& options = {});
RawTrial parseBvh(std::string_view text, const std::string& name, const LoadOptions& options = {});

}  // namespace ew
