#include "video/pose_model_files.h"

#include <cstdlib>
#include <system_error>
#include <unistd.h>

#include "core/common/errors.h"

#ifndef EW_POSE_MODEL_DIR
#define EW_POSE_MODEL_DIR ""
#endif

namespace ew {
namespace {

std::filesystem::path executableFolder() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

bool isFile(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

}  // namespace

std::string_view poseModelSizeName(PoseModelSize size) {
  switch (size) {
    case PoseModelSize::Lite: return "lite";
    case PoseModelSize::Heavy: return "heavy";
    case PoseModelSize::Full: break;
  }
  return "full";
}

PoseModelSize parsePoseModelSize(std::string_view name, std::string_view option) {
  if (name == "lite") return PoseModelSize::Lite;
  if (name == "full") return PoseModelSize::Full;
  if (name == "heavy") return PoseModelSize::Heavy;
  throw Error(ErrorKind::BadArgument, std::string(option), "",
              "'" + std::string(name) + "' is not a pose model: lite, full or heavy");
}

std::filesystem::path poseModelFolder() {
  if (const char* env = std::getenv("EIGENWALKER_MODELS"); env && *env) return env;
  const auto besideBin = executableFolder().parent_path() / "models";
  if (isFile(besideBin / "pose_detection.onnx")) return besideBin;
  const std::filesystem::path configured = EW_POSE_MODEL_DIR;
  if (!configured.empty() && isFile(configured / "pose_detection.onnx")) return configured;
  return besideBin;
}

std::optional<PoseModelFiles> findPoseModels(PoseModelSize size) {
  const auto folder = poseModelFolder();
  PoseModelFiles files{folder / "pose_detection.onnx",
                       folder / ("pose_landmark_" + std::string(poseModelSizeName(size)) + ".onnx"), size};
  if (!isFile(files.personDetector) || !isFile(files.landmarks)) return std::nullopt;
  return files;
}

std::string missingPoseModelAdvice() {
  return "pose detection needs MediaPipe's BlazePose models, which are not in " + poseModelFolder().string() +
         ": fetch them with `bash tools/pose_model/fetch_model.sh` (npm and network needed; `make deps` runs it), "
         "then build again (`make build`) to convert them";
}

PoseModelFiles requirePoseModels(PoseModelSize size) {
  if (auto files = findPoseModels(size)) return *files;
  throw Error(ErrorKind::Io, poseModelFolder().string(), "", missingPoseModelAdvice());
}

}  // namespace ew
