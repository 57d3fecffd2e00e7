// Layouts for files whose points are named by the user (DeepLabCut): an embedded layout
// when the names are one's, else the user's joint mapping file. Declared in keypoint_layout.h.

#include <algorithm>

#include "core/common/errors.h"
#include "core/io/text_table.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/mapping/mapping_file.h"
#include "core/mapping/marker_sets.h"

namespace ew {
namespace {

// Index of `name` in `names` under `same`; -1 if absent.
template <class Same>
int findName(const std::vector<std::string>& names, const std::string& name, Same same) {
  const auto it = std::find_if(names.begin(), names.end(), [&](const std::string& n) { return same(n, name); });
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

bool sameIgnoringCase(const std::string& a, const std::string& b) { return toLower(a) == toLower(b); }

// The embedded layout's joints re-indexed to the file's order of the same names; nullptr
// when the names are not exactly the layout's.
std::shared_ptr<const KeypointLayout> embeddedLayoutNamedLike(const std::vector<std::string>& names) {
  for (const auto& l : keypointLayouts()) {
    if (l.points.size() != names.size()) continue;
    std::vector<int> fileIndex;  // layout point -> file point
    for (const auto& p : l.points) fileIndex.push_back(findName(names, p, sameIgnoringCase));
    if (std::find(fileIndex.begin(), fileIndex.end(), -1) != fileIndex.end()) continue;
    bool sameOrder = true;
    for (std::size_t i = 0; i < fileIndex.size(); ++i) sameOrder = sameOrder && fileIndex[i] == static_cast<int>(i);
    if (sameOrder)  // the table itself, not a copy
      return std::shared_ptr<const KeypointLayout>(std::shared_ptr<const KeypointLayout>(), &l);
    auto reordered = std::make_shared<KeypointLayout>(l);
    reordered->points = names;
    for (auto& alternatives : reordered->joints) {
      for (auto& points : alternatives) {
        for (int& i : points) i = fileIndex[static_cast<std::size_t>(i)];
      }
    }
    return reordered;
  }
  return nullptr;
}

// Labels compare as in mapping files elsewhere (case-insensitive, "Subject:" dropped).
bool sameLabel(const std::string& a, const std::string& b) { return normaliseMarkerLabel(a) == normaliseMarkerLabel(b); }

std::shared_ptr<const KeypointLayout> layoutFromMapping(const std::vector<std::string>& names, const std::string& file,
                                                        const std::filesystem::path& mappingFile) {
  const JointMapping mapping = readJointMappingFile(mappingFile);
  auto l = std::make_shared<KeypointLayout>();
  l->name = "mapping " + mappingFile.filename().string();
  l->about = "the points of " + file + " as the joint mapping file " + mappingFile.string() + " maps them";
  l->file = mappingFile.string();
  l->points = names;
  for (std::size_t j = 0; j < mapping.joints.size(); ++j) {
    const auto& labels = mapping.joints[j];
    if (labels.empty()) continue;  // absent: for the model to estimate
    std::vector<int> points;
    for (const auto& label : labels) {
      points.push_back(findName(names, label, sameLabel));
      if (points.back() < 0)
        throw Error(ErrorKind::BadArgument, mappingFile.string(), "joints." + std::string(kJointNames[j]),
                    "'" + label + "' is not a point of " + file + " (its points: " + listForMessage(names, 40) + ")");
    }
    l->joints[j].push_back(points);
    if (labels.size() > 1) l->derived[j] = "mean of " + listForMessage(labels, 10);
  }
  return l;
}

}  // namespace

PointNamesLayout layoutForPointNames(const std::vector<std::string>& names, const std::string& file,
                                     const std::optional<std::filesystem::path>& mappingFile) {
  // The user's mapping first: it is their word, even when the names are a known layout's.
  if (mappingFile)
    return {layoutFromMapping(names, file, *mappingFile), "joint mapping file " + mappingFile->string()};
  if (auto embedded = embeddedLayoutNamedLike(names))
    return {embedded, "the file's point names are " + embedded->name + "'s"};
  throw Error(ErrorKind::BadData, file, "",
              "its points (" + listForMessage(names, 40) +
                  ") are no layout we know: give a joint mapping file saying which make each joint");
}

}  // namespace ew
