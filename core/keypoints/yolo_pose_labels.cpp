// Ultralytics YOLO pose labels: what `yolo pose predict save_txt=True` writes, one text file
// per frame with one line per person (docs/KEYPOINTS.md). Declared in keypoint_frames.h.
//
// A line is "class cx cy w h" (the box) then x y [visibility] per keypoint, all as fractions
// of the image, then the box's confidence (save_conf=True) and the track id (`yolo track`).
// Ultralytics zeroes the x, y of a keypoint whose confidence is under 0.5, and writes no file
// for a frame where nobody was detected: the frame number in the file name places each file.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/io/file_bytes.h"
#include "core/io/text_table.h"
#include "core/keypoints/keypoint_frames.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

constexpr int kBoxValues = 5;  // class, centre x, centre y, width, height
// The keypoint counts of the layouts we know (docs/KEYPOINTS.md), most common first: the
// field count of a line is read against these.
constexpr std::array<int, 5> kKnownPointCounts{17, 26, 25, 33, 18};
// Fractions of the image; a little outside it is a keypoint the model put past the edge.
constexpr double kLowestFraction = -1.0, kHighestFraction = 2.0;

// How the numbers of a line are laid out.
struct LabelLayout {
  int points = 0;
  int perPoint = 3;   // x, y, visibility; or 2: x, y
  int extras = 0;     // after the keypoints: box confidence and/or track id
  bool trackId = false;
};

std::vector<double> lineNumbers(const TextLine& line, const std::string& file) {
  std::vector<double> values;
  for (std::string_view word : splitWords(line.text)) {
    double v = 0.0;
    if (!parseFinite(word, v))
      throwMalformed(file, linePosition(line.number), shownWord(word) + " is not a finite number");
    values.push_back(v);
  }
  return values;
}

// The layouts a line of `count` numbers can be: known point counts first, three values a
// point before two (Ultralytics' COCO models write visibility).
std::vector<LabelLayout> candidateLayouts(int count) {
  std::vector<LabelLayout> out;
  for (int perPoint : {3, 2}) {
    for (int extras = 0; extras <= 2; ++extras) {
      for (int points : kKnownPointCounts) {
        if (kBoxValues + perPoint * points + extras == count) out.push_back({points, perPoint, extras, false});
      }
    }
  }
  return out;
}

bool isWholeNumber(double v) { return v >= 1.0 && v < 1e7 && v == std::floor(v); }

// One extra number is a track id when it is a whole number in every line (a box confidence
// is a fraction below 1), else the confidence.
LabelLayout decideLayout(const std::vector<std::vector<std::vector<double>>>& perFile, int count,
                         const std::string& file) {
  const auto candidates = candidateLayouts(count);
  if (candidates.empty())
    throwMalformed(file, "line 1",
                   std::to_string(count) + " numbers: a YOLO pose label is 5 box values, then x y visibility (or x y) "
                   "per keypoint for 17, 18, 25, 26 or 33 keypoints, then the box confidence and the track id");
  LabelLayout layout = candidates.front();
  if (layout.extras == 2) layout.trackId = true;
  if (layout.extras == 1)
    layout.trackId = std::all_of(perFile.begin(), perFile.end(), [](const auto& lines) {
      return std::all_of(lines.begin(), lines.end(), [](const auto& v) { return isWholeNumber(v.back()); });
    });
  return layout;
}

KeypointDetection detectionFrom(const std::vector<double>& v, const LabelLayout& layout, const KeypointImageSize& size,
                                const std::string& file, const std::string& where) {
  KeypointDetection d;
  d.points.resize(layout.points, 3);
  for (int i = 0; i < layout.points; ++i) {
    const std::size_t at = static_cast<std::size_t>(kBoxValues + layout.perPoint * i);
    const double x = v[at], y = v[at + 1], visibility = layout.perPoint == 3 ? v[at + 2] : 1.0;
    if (x < kLowestFraction || x > kHighestFraction || y < kLowestFraction || y > kHighestFraction)
      throwMalformed(file, where,
                     "keypoint " + std::to_string(i + 1) + " at (" + std::to_string(x) + ", " + std::to_string(y) +
                         "): YOLO labels hold each coordinate as a share of the image's side (0-1), not pixels");
    // Ultralytics writes 0, 0 for a keypoint under its visibility threshold.
    const bool absent = (x == 0.0 && y == 0.0) || !(visibility > 0.0);
    if (absent) {
      d.points.row(i) << kNaN, kNaN, 0.0;
    } else {
      d.points.row(i) << x * size.width, y * size.height, std::min(visibility, 1.0);
    }
  }
  if (layout.trackId && isWholeNumber(v.back())) d.trackId = static_cast<int>(v.back());
  return d;
}

struct LabelFile {
  long number = -1;  // the frame number in its name
  std::string name, text;
};

// Where each file's frame goes: Ultralytics numbers a video's frames from 1 ("walk_1.txt");
// a folder whose numbers start at 0 counts from 0.
std::vector<long> frameIndices(const std::vector<LabelFile>& files, const std::string& folder) {
  if (files.size() == 1) return {0};
  std::map<long, const LabelFile*> byNumber;
  for (const LabelFile& f : files) {
    if (f.number < 0)
      throwMalformed(folder, f.name, "no frame number in the file name (Ultralytics writes <video>_<frame>.txt)");
    const auto [it, added] = byNumber.emplace(f.number, &f);
    if (!added)
      throwMalformed(folder, f.name,
                     "frame " + std::to_string(f.number) + " has two label files (" + it->second->name + " and " +
                         f.name + "): one video's labels to a folder");
  }
  const long base = byNumber.begin()->first == 0 ? 0 : 1;
  if (byNumber.rbegin()->first - base >= kMaxKeypointFrames)
    throwMalformed(folder, byNumber.rbegin()->second->name,
                   "frame " + std::to_string(byNumber.rbegin()->first) + ": more than " +
                       std::to_string(kMaxKeypointFrames) + " frames");
  std::vector<long> out;
  for (const LabelFile& f : files) out.push_back(f.number - base);
  return out;
}

bool readsAsLabelLine(std::string_view line) {
  const auto words = splitWords(line);
  if (words.empty()) return false;
  double v = 0.0;
  for (std::string_view w : words) {
    if (!parseFinite(w, v)) return false;
  }
  return !candidateLayouts(static_cast<int>(words.size())).empty();
}

// The first .txt file (by name) of a folder, or none.
std::optional<fs::path> firstTextFile(const fs::path& folder) {
  std::optional<fs::path> first;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (e.path().extension() == ".txt" && (!first || e.path().filename() < first->filename())) first = e.path();
  }
  return first;
}

// From the file's first 64 KiB (a line of 33 keypoints is about 1 KB): a large text file
// that is something else is not read whole to find out.
bool fileReadsAsLabels(const fs::path& file) {
  const std::string head = readFileStart(file);
  const auto lines = splitLines(head);
  // The last line may be cut by the 64 KiB: only whole lines count.
  for (std::size_t i = 0; i + (head.size() == kSniffBytes ? 1 : 0) < lines.size(); ++i) {
    if (!trim(lines[i].text).empty()) return readsAsLabelLine(lines[i].text);
  }
  return false;
}

}  // namespace

std::optional<fs::path> yoloLabelsFolder(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) {
    const bool text = path.extension() == ".txt" && fs::is_regular_file(path, ec);
    return text && fileReadsAsLabels(path) ? std::optional<fs::path>(path) : std::nullopt;
  }
  for (const fs::path& folder : {path, path / "labels"}) {
    if (!fs::is_directory(folder, ec)) continue;
    const auto first = firstTextFile(folder);
    if (first && fileReadsAsLabels(*first)) return folder;
  }
  return std::nullopt;
}

KeypointFrames parseYoloPoseLabels(const std::vector<std::pair<std::string, std::string>>& filesAndTexts,
                                   const std::string& name, std::optional<KeypointImageSize> imageSize) {
  std::vector<LabelFile> files;
  for (const auto& [file, text] : filesAndTexts) files.push_back({trailingNumber(file), file, text});
  if (files.empty()) throw Error(ErrorKind::BadData, name, "", "no label files");
  std::sort(files.begin(), files.end(), [](const LabelFile& a, const LabelFile& b) {
    return a.number != b.number ? a.number < b.number : a.name < b.name;
  });
  if (!imageSize)
    throw Error(ErrorKind::BadArgument, name, "",
                "YOLO labels hold " + std::string(kNeedsImageSize) +
                    ": give the video's size in pixels (the image size option, e.g. 1920x1080), or put "
                    "the video beside the labels");
  const auto indices = frameIndices(files, name);
  // Every line of every file, parsed first: the field layout is decided from all of them.
  std::vector<std::vector<std::vector<double>>> perFile;
  std::size_t count = 0;  // numbers a line, set by the first line
  for (const LabelFile& f : files) {
    perFile.emplace_back();
    for (const TextLine& line : splitLines(f.text)) {
      if (trim(line.text).empty()) continue;
      if (perFile.back().size() >= static_cast<std::size_t>(kMaxPeoplePerFrame))
        throwMalformed(name + "/" + f.name, "", "more than " + std::to_string(kMaxPeoplePerFrame) + " people in one frame");
      perFile.back().push_back(lineNumbers(line, name + "/" + f.name));
      const std::size_t n = perFile.back().back().size();
      if (count == 0) count = n;
      if (n != count)
        throwMalformed(name + "/" + f.name, linePosition(line.number),
                       std::to_string(n) + " numbers where the first line had " + std::to_string(count));
    }
  }
  if (count == 0) throw Error(ErrorKind::BadData, name, "", "no person detected in any of the label files");
  const LabelLayout layout = decideLayout(perFile, static_cast<int>(count), name);

  KeypointFrames out;
  out.file = name;
  out.format = "YOLO pose labels";
  out.pointCount = layout.points;
  const long frames = *std::max_element(indices.begin(), indices.end()) + 1;
  out.frames.resize(static_cast<std::size_t>(frames));
  for (std::size_t k = 0; k < files.size(); ++k) {
    auto& frame = out.frames[static_cast<std::size_t>(indices[k])];
    for (std::size_t i = 0; i < perFile[k].size(); ++i)
      frame.push_back(detectionFrom(perFile[k][i], layout, *imageSize, name + "/" + files[k].name,
                                    "detection " + std::to_string(i + 1)));
  }
  const long empty = frames - static_cast<long>(files.size());
  if (empty > 0)
    out.warnings.push_back(std::to_string(empty) + " of the " + std::to_string(frames) +
                           " frames have no label file: Ultralytics writes none where nobody was detected, so they "
                           "are frames with nobody");
  return out;
}

KeypointFrames readYoloPoseLabels(const fs::path& labels, std::optional<KeypointImageSize> imageSize) {
  std::error_code ec;
  std::vector<std::pair<std::string, std::string>> texts;
  if (fs::is_directory(labels, ec)) {
    texts = readPerFrameFiles(labels, ".txt");
  } else {
    texts.emplace_back(labels.filename().string(), readFileText(labels));
  }
  return parseYoloPoseLabels(texts, labels.string(), imageSize);
}

}  // namespace ew
