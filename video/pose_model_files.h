#pragma once
// Where the pose detector's converted models are (issue 52): the build converts MediaPipe's
// BlazePose .tflite files, fetched by tools/pose_model/fetch_model.sh, to ONNX in
// <build>/models (cmake/pose_models.cmake). Nothing is downloaded at run time.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace ew {

// BlazePose's three landmark models: lite is fastest, heavy most accurate (docs/DETECTOR.md).
enum class PoseModelSize { Lite, Full, Heavy };

std::string_view poseModelSizeName(PoseModelSize size);  // "lite", "full", "heavy"
// Error(BadArgument) naming `option` for anything but the three names.
PoseModelSize parsePoseModelSize(std::string_view name, std::string_view option = "--model");

struct PoseModelFiles {
  std::filesystem::path personDetector;
  std::filesystem::path landmarks;
  PoseModelSize size = PoseModelSize::Full;
};

// The folder the models are looked for in: $EIGENWALKER_MODELS when set, else the build's
// models/ beside bin/ (where the programs run from), else the build folder this binary was
// configured with.
std::filesystem::path poseModelFolder();

// The two files for `size`, or nullopt when either is missing.
std::optional<PoseModelFiles> findPoseModels(PoseModelSize size = PoseModelSize::Full);

// The same, but throws Error(Io) saying that detection needs the models, where they were
// looked for, and the commands that fetch and convert them.
PoseModelFiles requirePoseModels(PoseModelSize size = PoseModelSize::Full);

// The sentence the programs show when the models are missing.
std::string missingPoseModelAdvice();

}  // namespace ew
