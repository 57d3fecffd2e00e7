#pragma once
// Acclaim ASF (skeleton) + AMC (motion) reader: units block, root order/axis, per-bone
// direction, length, axis, dof and limits; AMC in degrees or radians. AMC stores no frame
// rate: the caller's rateHzOverride, else 120 Hz (CMU) with a warning.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

// `file` is the .amc; the skeleton is the .asf in the same folder (the one whose stem
// prefixes the AMC's, e.g. 35.asf for 35_01.amc, else the only .asf there).
RawTrial readAsfAmc(const std::filesystem::path& amcFile, const LoadOptions& options = {});
RawTrial parseAsfAmc(std::string_view asfText, std::string_view amcText, const std::string& name,
                     const LoadOptions& options = {});

}  // namespace ew
