#include "video/video_beside.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "video/video_source.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

constexpr std::array<const char*, 6> kVideoExtensions{".mp4", ".avi", ".mov", ".mkv", ".webm", ".m4v"};
// What tools append to a video's name for the folder or file of its keypoints.
constexpr std::array<const char*, 4> kKeypointSuffixes{"_json", "_keypoints", "_labels", "_pose"};

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

// "walk_12.txt" -> "walk": Ultralytics names a video's label files <video>_<frame>.
std::string labelPrefix(const fs::path& labelFile) {
  const std::string stem = labelFile.stem().string();
  const auto cut = stem.find_last_of('_');
  const bool numbered = cut != std::string::npos && cut + 1 < stem.size() &&
                        std::all_of(stem.begin() + static_cast<std::ptrdiff_t>(cut) + 1, stem.end(),
                                    [](unsigned char c) { return std::isdigit(c) != 0; });
  return numbered ? stem.substr(0, cut) : stem;
}

std::optional<fs::path> anyLabelFile(const fs::path& folder) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".txt") return e.path();
  return std::nullopt;
}

void addNamed(std::vector<fs::path>& out, const fs::path& folder, const std::string& stem) {
  if (stem.empty()) return;
  for (const char* ext : kVideoExtensions) {
    out.push_back(folder / (stem + ext));
    out.push_back(folder / (stem + upper(ext)));
  }
}

// Without "." or a trailing separator ("run/labels/" names "labels"), and absolute where the
// path has no folder to go up from ("labels", ".."): as given otherwise, so that what is said
// of the video reads like what the user typed.
fs::path normalised(const fs::path& p) {
  const auto trimmed = [](fs::path q) {
    q = q.lexically_normal();
    return q.has_filename() ? q : q.parent_path();
  };
  fs::path out = trimmed(p);
  const bool upward = out.filename() == "." || out.filename() == "..";
  return out.parent_path().empty() || upward ? trimmed(fs::absolute(out)) : out;
}

// The stems a keypoint file or folder's video may have: its own, and without a tool's suffix.
std::vector<std::string> stemsOf(const fs::path& keypoints) {
  const std::string stem = keypoints.stem().string();
  std::vector<std::string> out{stem};
  for (const char* suffix : kKeypointSuffixes) {
    const std::string s = suffix;
    if (stem.size() > s.size() && stem.ends_with(s)) out.push_back(stem.substr(0, stem.size() - s.size()));
  }
  return out;
}

}  // namespace

std::vector<fs::path> videoCandidatesFor(const fs::path& given) {
  const fs::path keypoints = normalised(given);
  std::vector<fs::path> out;
  if (const auto found = yoloLabelsFolder(keypoints)) {
    const fs::path labels = normalised(*found);
    std::error_code ec;
    const bool folder = fs::is_directory(labels, ec);
    if (const auto file = folder ? anyLabelFile(labels) : std::optional<fs::path>(labels)) {
      const fs::path run = folder ? labels.parent_path() : labels.parent_path().parent_path();
      addNamed(out, run, labelPrefix(*file));
      if (!folder) addNamed(out, labels.parent_path(), labelPrefix(*file));
    }
  }
  const fs::path folder = keypoints.parent_path();
  for (const std::string& stem : stemsOf(keypoints)) {
    addNamed(out, folder, stem);
    addNamed(out, folder.parent_path() / "videos", stem);
  }
  return out;
}

std::optional<KeypointVideo> videoBesideKeypoints(const fs::path& keypoints) {
  for (const fs::path& candidate : videoCandidatesFor(keypoints)) {
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) continue;
    try {
      const VideoSource video(candidate);
      const VideoInfo& info = video.info();
      return KeypointVideo{candidate.string(), {info.widthPx, info.heightPx}, info.fps};
    } catch (const std::exception&) {
      continue;  // not a video OpenCV opens: passed over (see the header)
    }
  }
  return std::nullopt;
}

}  // namespace ew
