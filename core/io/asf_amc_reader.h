#pragma once
// Acclaim ASF (skeleton) + AMC (motion) reader: units block, root order/axis, per-bone
// direction, length, axis, dof and limits; AMC in degrees or radians. AMC stores no frame
// rate: the caller's rateHzOverride, else 120 Hz (CMU) with a warning.
//
// Forward kinematics (Acclaim convention, column vectors): for a bone b with parent p,
//   C_b = axis rotation, M_b = M_p · C_b · R_b · C_b⁻¹,  end_b = end_p + M_b · direction_b · length_b
// where R_b composes the bone's rotation dofs in the order the `dof` line lists them,
// each applied after the previous one (dof rx ry rz -> R = Rz·Ry·Rx; `axis … XYZ` the
// same way). The root: M_root = C_root · R_root · C_root⁻¹ from `orientation` and the
// rotation entries of `order`; its point is `position` + the TX TY TZ values.
// Points: "root" and one per bone, the bone's end, named by the bone. Lengths are in
// 1/length inch (`:units length 0.45` -> 56.444 mm per unit) unless unitsOverride says
// otherwise. AMC angles follow :DEGREES / :RADIANS, else the ASF's angle unit.
// Frames must be numbered consecutively; bones a frame omits keep all dofs at 0.
// Axes: +Y up (RawTrial::upAxis = {1, +1}).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

// `file` is the .amc; the skeleton is the .asf in the same folder (the one whose stem
// prefixes the AMC's, e.g. 35.asf for 35_01.amc, else the only .asf there).
RawTrial readAsfAmc(const std::filesystem::path& amcFile, const LoadOptions& options = {});
// The .asf readAsfAmc pairs with an .amc (Error(Io) naming the .amc when there is none), and
// the .amc files in an .asf's folder that pair with it (sorted), so "x.asf + y.amc" given
// together, or an .asf alone, open as the AMC trials (core/gait/dataset.cpp).
std::filesystem::path asfSkeletonFor(const std::filesystem::path& amcFile);
std::vector<std::filesystem::path> amcMotionsFor(const std::filesystem::path& asfFile);
RawTrial parseAsfAmc(std::string_view asfText, std::string_view amcText, const std::string& name,
                     const LoadOptions& options = {});
// The same, with separate names so errors in the skeleton name the .asf.
RawTrial parseAsfAmc(std::string_view asfText, std::string_view amcText,
                     const std::string& asfName, const std::string& amcName,
                     const LoadOptions& options = {});

}  // namespace ew
