#include "core/keypoints/keypoint_trial.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/common/statistics.h"
#include "core/io/reader_limits.h"

namespace ew {
namespace {

using Eigen::Vector2d;

// A detection joins a track when its centre is within this share of the person's size.
constexpr double kMaxStepOfSize = 0.5;
constexpr int kMaxTrackGapFrames = 15;
// A detection with fewer points is noise, not a person.
constexpr int kMinPointsPerDetection = 3;
// The walker is chosen among tracks present at least this share as long as the longest.
constexpr double kMinShareOfLongest = 0.5;
// A joint's alternative is used when its points are all seen in this share of the frames.
constexpr double kAlternativeShare = 0.5;

struct Shape {
  Vector2d centre = Vector2d::Constant(kNaN);
  double heightPx = 0.0;
  int points = 0;
};

Shape shapeOf(const Eigen::MatrixX3d& p) {
  Shape s;
  Vector2d sum = Vector2d::Zero();
  double top = std::numeric_limits<double>::infinity(), bottom = -top;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    if (!std::isfinite(p(i, 0)) || !std::isfinite(p(i, 1))) continue;
    sum += Vector2d(p(i, 0), p(i, 1));
    top = std::min(top, p(i, 1));
    bottom = std::max(bottom, p(i, 1));
    ++s.points;
  }
  if (s.points > 0) s.centre = sum / s.points, s.heightPx = bottom - top;
  return s;
}

// The median over frames of the seen joints' extent down the image (a detection's height).
double medianHeightPx(const Eigen::MatrixXd& jointsPx) {
  std::vector<double> heights;
  Eigen::MatrixX3d points(kJointCount, 3);
  for (Eigen::Index f = 0; f < jointsPx.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) points.row(j) << jointsPx(f, 2 * j), jointsPx(f, 2 * j + 1), 1.0;
    const Shape shape = shapeOf(points);
    if (shape.points >= 2) heights.push_back(shape.heightPx);
  }
  return heights.empty() ? 0.0 : median(heights);
}

struct Active {
  int track;
  Vector2d centre;
  double size;
  int lastFrame;
};

// [SECTION] Joints of one layout ------------------------------------------------------------

bool pointSeen(const Eigen::MatrixX3d& p, int i, double minConfidence) {
  return i < p.rows() && std::isfinite(p(i, 0)) && std::isfinite(p(i, 1)) && p(i, 2) >= minConfidence;
}

struct JointChoice {
  std::array<int, kJointCount> alternative{};  // -1: never seen
};

// Per joint the first alternative whose points are all seen in kAlternativeShare of the
// person's frames, else the one seen most, else none.
JointChoice chooseAlternatives(const KeypointLayout& layout, const std::vector<const Eigen::MatrixX3d*>& person,
                               double minConfidence) {
  JointChoice c;
  for (int j = 0; j < kJointCount; ++j) {
    const auto& alts = layout.joints[static_cast<std::size_t>(j)];
    int best = -1;
    double bestShare = 0.0;
    for (std::size_t a = 0; a < alts.size(); ++a) {
      int seen = 0;
      for (const auto* p : person) {
        seen += std::all_of(alts[a].begin(), alts[a].end(), [&](int i) { return pointSeen(*p, i, minConfidence); });
      }
      const double share = person.empty() ? 0.0 : static_cast<double>(seen) / static_cast<double>(person.size());
      if (share >= kAlternativeShare) {
        best = static_cast<int>(a);
        break;
      }
      if (share > bestShare) best = static_cast<int>(a), bestShare = share;
    }
    c.alternative[static_cast<std::size_t>(j)] = best;
  }
  return c;
}

// The mean of the points, when every one of them is seen.
std::optional<Vector2d> meanIfSeen(const Eigen::MatrixX3d& p, const std::vector<int>& pts, double minConfidence) {
  if (!std::all_of(pts.begin(), pts.end(), [&](int i) { return pointSeen(p, i, minConfidence); })) return std::nullopt;
  Vector2d sum = Vector2d::Zero();
  for (int i : pts) sum += Vector2d(p(i, 0), p(i, 1));
  return Vector2d(sum / static_cast<double>(pts.size()));
}

Eigen::RowVectorXd jointsOf(const KeypointLayout& layout, const JointChoice& c, const Eigen::MatrixX3d& p,
                            double minConfidence) {
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Constant(2 * kJointCount, kNaN);
  for (int j = 0; j < kJointCount; ++j) {
    const int a = c.alternative[static_cast<std::size_t>(j)];
    if (a < 0) continue;
    const auto& pts = layout.joints[static_cast<std::size_t>(j)][static_cast<std::size_t>(a)];
    if (const auto mean = meanIfSeen(p, pts, minConfidence)) row.segment<2>(2 * j) = mean->transpose();
  }
  return row;
}

// Share of the checks an upright person passes (v grows downwards): ankles below knees
// below hips below shoulders, head above the sternum. The wrong reading of a 25-point file
// puts eyes where shoulders are and fails them.
double uprightShare(const Eigen::MatrixXd& joints) {
  const std::vector<std::pair<Joint, Joint>> below = {
      {Joint::RAnkle, Joint::RKnee}, {Joint::LAnkle, Joint::LKnee}, {Joint::RKnee, Joint::RHip},
      {Joint::LKnee, Joint::LHip},   {Joint::RHip, Joint::RShoulder}, {Joint::LHip, Joint::LShoulder},
      {Joint::Sternum, Joint::Head}};
  int pass = 0, total = 0;
  for (Eigen::Index f = 0; f < joints.rows(); ++f) {
    for (const auto& [low, high] : below) {
      const double vLow = joints(f, 2 * index(low) + 1), vHigh = joints(f, 2 * index(high) + 1);
      if (!std::isfinite(vLow) || !std::isfinite(vHigh)) continue;
      pass += vLow > vHigh;
      ++total;
    }
  }
  return total ? static_cast<double>(pass) / total : 0.0;
}

std::string percent(double share) { return std::to_string(static_cast<int>(std::lround(100.0 * share))) + " %"; }

// [SECTION] Choices --------------------------------------------------------------------------

int chooseWalker(const std::vector<PersonTrack>& people, std::string& reason, std::vector<std::string>& warnings,
                 int frameCount) {
  const double longest = static_cast<double>(people.front().frames.size());
  int best = 0;
  double bestMoves = -1.0;
  for (std::size_t k = 0; k < people.size(); ++k) {
    if (static_cast<double>(people[k].frames.size()) < kMinShareOfLongest * longest) continue;
    const double moves = people[k].travelPx / std::max(people[k].sizePx, 1.0);
    if (moves > bestMoves) best = static_cast<int>(k), bestMoves = moves;
  }
  if (bestMoves < 0.5) {
    best = 0;
    warnings.push_back("nobody in the clip moves more than half a body height: using the person present longest");
  }
  std::ostringstream r;
  r.precision(1);
  r << std::fixed << "person " << best + 1 << " of " << people.size() << ": in "
    << people[static_cast<std::size_t>(best)].frames.size() << " of " << frameCount << " frames, moves "
    << people[static_cast<std::size_t>(best)].travelPx / std::max(people[static_cast<std::size_t>(best)].sizePx, 1.0)
    << " body heights";
  reason = r.str();
  return best;
}

std::vector<const Eigen::MatrixX3d*> detectionsOf(const KeypointFrames& frames, const PersonTrack& t) {
  std::vector<const Eigen::MatrixX3d*> out;
  for (std::size_t i = 0; i < t.frames.size(); ++i) {
    out.push_back(&frames.frames[static_cast<std::size_t>(t.frames[i])][static_cast<std::size_t>(t.detection[i])].points);
  }
  return out;
}

// The person's joints, one row per frame it is in (PersonTrack::jointsPx).
Eigen::MatrixXd presentJoints(const KeypointLayout& layout, const KeypointFrames& frames, const PersonTrack& t,
                              double minConfidence) {
  const auto person = detectionsOf(frames, t);
  const JointChoice c = chooseAlternatives(layout, person, minConfidence);
  Eigen::MatrixXd out(static_cast<Eigen::Index>(t.frames.size()), 2 * kJointCount);
  for (std::size_t i = 0; i < t.frames.size(); ++i)
    out.row(static_cast<Eigen::Index>(i)) = jointsOf(layout, c, *person[i], minConfidence);
  return out;
}

// Each joint's confidence over the whole clip (KeypointTrial::jointConfidence): the least of
// its points' where the joint is made, NaN elsewhere.
Eigen::MatrixXd personJointConfidence(const KeypointLayout& layout, const KeypointFrames& frames, const PersonTrack& t,
                                      double minConfidence) {
  const auto person = detectionsOf(frames, t);
  const JointChoice c = chooseAlternatives(layout, person, minConfidence);
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(frames.frameCount(), kJointCount, kNaN);
  for (std::size_t i = 0; i < t.frames.size(); ++i) {
    const Eigen::MatrixX3d& p = *person[i];
    for (int j = 0; j < kJointCount; ++j) {
      const int a = c.alternative[static_cast<std::size_t>(j)];
      if (a < 0) continue;
      const auto& pts = layout.joints[static_cast<std::size_t>(j)][static_cast<std::size_t>(a)];
      if (!std::all_of(pts.begin(), pts.end(), [&](int k) { return pointSeen(p, k, minConfidence); })) continue;
      double least = 1.0;
      for (int k : pts) least = std::min(least, p(k, 2));
      out(t.frames[i], j) = least;
    }
  }
  return out;
}

// The walker's heel and toe points over the whole clip (KeypointTrial::feetPx): per frame the
// first alternative whose points are all seen; NaN elsewhere. Empty without foot points.
Eigen::MatrixXd personFeet(const KeypointLayout& layout, const KeypointFrames& frames, const PersonTrack& t,
                           double minConfidence) {
  if (!layout.hasFeet()) return {};
  const auto person = detectionsOf(frames, t);
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(frames.frameCount(), 2 * kFootPointCount, kNaN);
  for (std::size_t i = 0; i < t.frames.size(); ++i) {
    for (int f = 0; f < kFootPointCount; ++f) {
      for (const auto& pts : layout.feet[static_cast<std::size_t>(f)]) {
        const auto mean = meanIfSeen(*person[i], pts, minConfidence);
        if (!mean) continue;
        out.row(t.frames[i]).segment<2>(2 * f) = mean->transpose();
        break;
      }
    }
  }
  return out;
}

// The same over the whole clip: NaN where the person is not.
Eigen::MatrixXd personJoints(const KeypointLayout& layout, const KeypointFrames& frames, const PersonTrack& t,
                             double minConfidence) {
  const Eigen::MatrixXd present = presentJoints(layout, frames, t, minConfidence);
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(frames.frameCount(), 2 * kJointCount, kNaN);
  for (std::size_t i = 0; i < t.frames.size(); ++i) out.row(t.frames[i]) = present.row(static_cast<Eigen::Index>(i));
  return out;
}

// The rows of a whole-clip joint matrix for the frames the person is in.
Eigen::MatrixXd presentRows(const Eigen::MatrixXd& joints, const PersonTrack& t) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(t.frames.size()), joints.cols());
  for (std::size_t i = 0; i < t.frames.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = joints.row(t.frames[i]);
  return out;
}

const KeypointLayout& chooseLayout(const KeypointFrames& frames, const PersonTrack& walker,
                                   const KeypointOptions& options, std::string& source,
                                   std::vector<std::string>& warnings, std::shared_ptr<const KeypointLayout>& built) {
  if (options.layout) {
    const KeypointLayout& l = keypointLayoutNamed(*options.layout);
    if (static_cast<int>(l.points.size()) != frames.pointCount)
      throw Error(ErrorKind::BadArgument, frames.file, "--layout",
                  l.name + " has " + std::to_string(l.points.size()) + " points, the file " +
                      std::to_string(frames.pointCount));
    source = "given (--layout)";
    return l;
  }
  if (!frames.pointNames.empty()) {  // the file names its points: by name, not by count
    PointNamesLayout named = layoutForPointNames(frames.pointNames, frames.file, options.mappingFile);
    source = named.source;
    built = std::move(named.layout);
    return *built;
  }
  const auto candidates = keypointLayoutsWithPoints(frames.pointCount);
  if (candidates.empty()) {
    std::string known;
    for (const auto& l : keypointLayouts()) known += (known.empty() ? "" : ", ") + l.name + " " + std::to_string(l.points.size());
    throw Error(ErrorKind::BadData, frames.file, "",
                std::to_string(frames.pointCount) + " keypoints per person: no layout we know has that many (" +
                    known + ")");
  }
  if (frames.layoutHint) {
    for (const auto* l : candidates) {
      if (l->name == *frames.layoutHint) {
        source = "stated by the file";
        return *l;
      }
    }
  }
  if (candidates.size() == 1) {
    source = "the only layout with " + std::to_string(frames.pointCount) + " points";
    return *candidates.front();
  }
  const KeypointLayout* best = nullptr;
  double bestShare = -1.0;
  std::string others;
  std::vector<double> shares;
  for (const auto* l : candidates) {
    const double share = uprightShare(personJoints(*l, frames, walker, options.minConfidence));
    shares.push_back(share);
    if (share > bestShare) best = l, bestShare = share;
  }
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (candidates[k] != best) others += (others.empty() ? "" : ", ") + candidates[k]->name + " " + percent(shares[k]);
  }
  source = "guessed: upright in " + percent(bestShare) + " of checks as " + best->name + " (" + others +
           "); --layout overrides";
  if (bestShare < 0.6) warnings.push_back("no layout reads the person upright (best " + best->name + ", " +
                                          percent(bestShare) + "): give --layout");
  return *best;
}

// The layout's sternum, first alternative, is its two shoulders' first alternatives averaged.
bool sternumIsTheShouldersMidpoint(const KeypointLayout& layout) {
  const auto first = [&](Joint j) -> const std::vector<int>* {
    const auto& alternatives = layout.joints[static_cast<std::size_t>(index(j))];
    return alternatives.empty() ? nullptr : &alternatives.front();
  };
  const auto *sternum = first(Joint::Sternum), *right = first(Joint::RShoulder), *left = first(Joint::LShoulder);
  if (!sternum || !right || !left || sternum->size() != 2 || right->size() != 1 || left->size() != 1) return false;
  const std::vector<int> shoulders = {right->front(), left->front()};
  return std::is_permutation(sternum->begin(), sternum->end(), shoulders.begin());
}

std::string confidenceText(double minConfidence) { return std::to_string(minConfidence).substr(0, 4); }

// Which joints the trial sees and how often; a warning for those never seen; Error(BadData)
// naming the file when the walk's minimum joints are among them.
void checkSeenJoints(KeypointTrial& t, const KeypointOptions& options) {
  for (int j = 0; j < kJointCount; ++j)
    t.derived[static_cast<std::size_t>(j)] = !t.layout->derived[static_cast<std::size_t>(j)].empty();
  const std::string why = "above confidence " + confidenceText(options.minConfidence);
  const std::vector<std::string> unseen = countSeenJoints(t);
  if (!unseen.empty()) {
    std::string list;
    for (const auto& u : unseen) list += (list.empty() ? "" : ", ") + u;
    t.warnings.push_back("never seen " + why + ": " + list + " (to be estimated from a model)");
  }
  requireWalkJoints(t, why);
}

// The 15 joints as their own layout, each its own point (a tracker's output).
std::shared_ptr<const KeypointLayout> jointLayout() {
  auto l = std::make_shared<KeypointLayout>();
  l->name = "15 joints (docs/METHOD.md §1)";
  l->about = "the joints themselves, as a tracker follows them";
  for (int j = 0; j < kJointCount; ++j) {
    l->points.emplace_back(jointName(static_cast<Joint>(j)));
    l->joints[static_cast<std::size_t>(j)] = {{j}};
  }
  return l;
}

}  // namespace

std::vector<std::string> countSeenJoints(KeypointTrial& t) {
  std::vector<std::string> unseen;
  for (int j = 0; j < kJointCount; ++j) {
    const auto seen = static_cast<double>(t.jointsPx.col(2 * j).array().isFinite().count());
    t.seenShare[static_cast<std::size_t>(j)] = t.frameCount ? seen / t.frameCount : 0.0;
    t.missing[static_cast<std::size_t>(j)] = seen == 0;
    if (seen == 0) unseen.emplace_back(jointName(static_cast<Joint>(j)));
  }
  return unseen;
}

void requireWalkJoints(const KeypointTrial& t, const std::string& why) {
  for (Joint j : {Joint::Pelvis, Joint::RKnee, Joint::LKnee, Joint::RAnkle, Joint::LAnkle}) {
    if (t.missing[static_cast<std::size_t>(index(j))])
      throw Error(ErrorKind::BadData, t.file, "",
                  std::string(jointName(j)) + " of " + t.chosenReason.substr(0, t.chosenReason.find(':')) +
                      " is never seen " + why + ": a walk needs pelvis, knees and ankles");
  }
}

// [SECTION] Public API -------------------------------------------------------------------------

namespace {

// People grouped by their trackIds (KeypointFrames::trackIdsFollowPeople); detections without
// one, or with too few points, are left out.
std::vector<PersonTrack> tracksByIds(const KeypointFrames& frames) {
  std::map<int, std::size_t> trackOf;
  std::vector<PersonTrack> tracks;
  std::vector<std::vector<double>> heights;
  std::vector<Vector2d> firstCentre;
  for (int f = 0; f < frames.frameCount(); ++f) {
    const auto& dets = frames.frames[static_cast<std::size_t>(f)];
    for (std::size_t d = 0; d < dets.size(); ++d) {
      const Shape shape = shapeOf(dets[d].points);
      if (dets[d].trackId < 0 || shape.points < kMinPointsPerDetection) continue;
      auto [it, added] = trackOf.try_emplace(dets[d].trackId, tracks.size());
      if (added) {
        tracks.emplace_back();
        heights.emplace_back();
        firstCentre.push_back(shape.centre);
      }
      PersonTrack& t = tracks[it->second];
      if (!t.frames.empty() && t.frames.back() == f) continue;  // one detection per id and frame
      t.frames.push_back(f);
      t.detection.push_back(static_cast<int>(d));
      heights[it->second].push_back(shape.heightPx);
      t.travelPx = std::max(t.travelPx, (shape.centre - firstCentre[it->second]).norm());
    }
  }
  for (std::size_t k = 0; k < tracks.size(); ++k) tracks[k].sizePx = median(heights[k]);
  std::stable_sort(tracks.begin(), tracks.end(),
                   [](const PersonTrack& a, const PersonTrack& b) { return a.frames.size() > b.frames.size(); });
  return tracks;
}

}  // namespace

std::vector<PersonTrack> trackPeople(const KeypointFrames& frames) {
  if (frames.trackIdsFollowPeople) return tracksByIds(frames);
  std::vector<PersonTrack> tracks;
  std::vector<Active> active;
  std::vector<std::vector<double>> heights;
  std::vector<Vector2d> firstCentre;
  for (int f = 0; f < frames.frameCount(); ++f) {
    const auto& dets = frames.frames[static_cast<std::size_t>(f)];
    std::vector<Shape> shapes;
    for (const auto& d : dets) shapes.push_back(shapeOf(d.points));
    // Candidate pairs, nearest first.
    std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
    for (std::size_t a = 0; a < active.size(); ++a) {
      if (f - active[a].lastFrame > kMaxTrackGapFrames) continue;
      for (std::size_t d = 0; d < shapes.size(); ++d) {
        if (shapes[d].points < kMinPointsPerDetection) continue;
        const double dist = (shapes[d].centre - active[a].centre).norm();
        if (dist <= kMaxStepOfSize * std::max(active[a].size, shapes[d].heightPx)) pairs.emplace_back(dist, a, d);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> usedActive(active.size(), false), usedDet(shapes.size(), false);
    const auto extend = [&](std::size_t a, std::size_t d) {
      PersonTrack& t = tracks[static_cast<std::size_t>(active[a].track)];
      t.frames.push_back(f);
      t.detection.push_back(static_cast<int>(d));
      heights[static_cast<std::size_t>(active[a].track)].push_back(shapes[d].heightPx);
      t.travelPx = std::max(t.travelPx, (shapes[d].centre - firstCentre[static_cast<std::size_t>(active[a].track)]).norm());
      active[a].centre = shapes[d].centre;
      active[a].size = std::max(shapes[d].heightPx, 1.0);
      active[a].lastFrame = f;
    };
    for (const auto& [dist, a, d] : pairs) {
      if (usedActive[a] || usedDet[d]) continue;
      usedActive[a] = usedDet[d] = true;
      extend(a, d);
    }
    for (std::size_t d = 0; d < shapes.size(); ++d) {
      if (usedDet[d] || shapes[d].points < kMinPointsPerDetection) continue;
      tracks.emplace_back();
      heights.emplace_back();
      firstCentre.push_back(shapes[d].centre);
      active.push_back({static_cast<int>(tracks.size() - 1), shapes[d].centre, 1.0, f});
      extend(active.size() - 1, d);
    }
  }
  for (std::size_t k = 0; k < tracks.size(); ++k) tracks[k].sizePx = median(heights[k]);
  std::stable_sort(tracks.begin(), tracks.end(),
                   [](const PersonTrack& a, const PersonTrack& b) { return a.frames.size() > b.frames.size(); });
  return tracks;
}

namespace {

// "59.94", "60": a frame rate as people write it.
std::string rateText(double hz) {
  std::ostringstream out;
  out << std::setprecision(4) << hz;
  return out.str();
}

// The rate and the image size: given, else the file's, else the video's (found beside it).
void takeRateAndSize(KeypointTrial& t, const KeypointFrames& frames, const KeypointOptions& options) {
  const std::string video = options.video ? "the video (" + options.video->file + ")" : "";
  if (options.imageSize) {
    t.imageSize = options.imageSize, t.imageSizeSource = "given";
  } else if (frames.imageSize) {
    t.imageSize = frames.imageSize, t.imageSizeSource = "the file";
  } else if (options.video) {
    t.imageSize = options.video->size, t.imageSizeSource = video;
  }
  if (options.fps) {
    t.rateHz = checkedGivenRateHz(*options.fps, frames.file, "--fps"), t.rateSource = "given";
  } else if (frames.rateHz) {
    t.rateHz = *frames.rateHz, t.rateSource = "the file";
  } else if (options.video && options.video->fps > 0.0) {
    t.rateHz = checkedFileRateHz(options.video->fps, options.video->file, "frame rate"), t.rateSource = video;
    // Worth a word when the keypoints came from another tool: the video beside them may not be
    // the footage they were detected in. A video detected here is its own rate.
    if (options.video->file != frames.file) t.warnings.push_back("frame rate " + rateText(t.rateHz) + " fps: " + video);
  }
  t.rateAssumed = t.rateSource == "assumed";
}

}  // namespace

KeypointTrial cleanKeypoints(const KeypointFrames& frames, const KeypointOptions& options) {
  KeypointTrial t;
  t.file = frames.file;
  t.format = frames.format;
  t.frameCount = frames.frameCount();
  t.warnings = frames.warnings;
  takeRateAndSize(t, frames, options);
  for (const auto& f : frames.frames) t.maxPeople = std::max(t.maxPeople, static_cast<int>(f.size()));
  t.people = trackPeople(frames);
  if (t.people.empty()) {
    // What the reader or the detector noticed may be why (a video that ends early).
    std::string why;
    for (const auto& w : frames.warnings) why += "; " + w;
    throw Error(ErrorKind::BadData, frames.file, "", "no detection has " + std::to_string(kMinPointsPerDetection) +
                                                         " or more keypoints: nobody to follow" + why);
  }
  if (options.person) {
    if (*options.person < 0 || *options.person >= static_cast<int>(t.people.size()))
      throw Error(ErrorKind::BadArgument, frames.file, "--person",
                  "person " + std::to_string(*options.person + 1) + " asked for, the clip has " +
                      std::to_string(t.people.size()));
    t.chosen = *options.person;
    t.chosenReason = "person " + std::to_string(t.chosen + 1) + " of " + std::to_string(t.people.size()) + " (chosen)";
  } else {
    t.chosen = chooseWalker(t.people, t.chosenReason, t.warnings, t.frameCount);
  }
  const PersonTrack& walker = t.people[static_cast<std::size_t>(t.chosen)];
  t.layout = &chooseLayout(frames, walker, options, t.layoutSource, t.warnings, t.builtLayout);
  t.jointsPx = personJoints(*t.layout, frames, walker, options.minConfidence);
  t.jointConfidence = personJointConfidence(*t.layout, frames, walker, options.minConfidence);
  t.feetPx = personFeet(*t.layout, frames, walker, options.minConfidence);
  if (options.detectorOffsets) {
    t.detectorOffsetMm = t.layout->detectorOffsetMm;
    t.sternumFromShoulders = sternumIsTheShouldersMidpoint(*t.layout);
  }
  for (auto& person : t.people) person.jointsPx = presentJoints(*t.layout, frames, person, options.minConfidence);
  checkSeenJoints(t, options);
  return t;
}

int personRowAt(const PersonTrack& person, int frame) {
  const auto it = std::lower_bound(person.frames.begin(), person.frames.end(), frame);
  return it != person.frames.end() && *it == frame ? static_cast<int>(it - person.frames.begin()) : -1;
}

KeypointTrial readKeypointTrial(const std::filesystem::path& path, const KeypointOptions& options) {
  if (isPlanarTrc(path)) return readPlanarTrc(path, options);
  return cleanKeypoints(readKeypointFrames(path, options.imageSize, options.videoSize()), options);
}

KeypointTrial trialFromJoints(const Eigen::MatrixXd& jointsPx, const Eigen::MatrixXd& confidence,
                              const std::string& file, const std::string& format, const KeypointOptions& options) {
  if (jointsPx.cols() != 2 * kJointCount || confidence.rows() != jointsPx.rows() || confidence.cols() != kJointCount)
    throw Error(ErrorKind::BadArgument, file, "", "a track needs frames × 30 pixels and frames × 15 confidences");
  if (jointsPx.rows() > kMaxKeypointFrames)
    throw Error(ErrorKind::BadArgument, file, "", "more than " + std::to_string(kMaxKeypointFrames) + " frames");
  if (!options.fps) throw Error(ErrorKind::BadArgument, file, "", "a track needs its frame rate");
  KeypointTrial t;
  t.file = file;
  t.format = format;
  t.rateHz = checkedFileRateHz(*options.fps, file, "frame rate");
  t.rateAssumed = false, t.rateSource = "given";
  t.frameCount = static_cast<int>(jointsPx.rows());
  t.builtLayout = jointLayout();
  t.layout = t.builtLayout.get();
  t.layoutSource = "the tracker's own joints";
  t.imageSize = options.imageSize;
  if (t.imageSize) t.imageSizeSource = "given";
  t.jointsPx = jointsPx;
  PersonTrack person;
  for (Eigen::Index f = 0; f < jointsPx.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      if (confidence(f, j) >= options.minConfidence && std::isfinite(confidence(f, j))) continue;
      t.jointsPx(f, 2 * j) = t.jointsPx(f, 2 * j + 1) = std::numeric_limits<double>::quiet_NaN();
    }
    if (t.jointsPx.row(f).array().isFinite().any()) person.frames.push_back(static_cast<int>(f));
  }
  person.detection.assign(person.frames.size(), 0);
  person.jointsPx = presentRows(t.jointsPx, person);
  person.sizePx = medianHeightPx(t.jointsPx);  // the walking checks measure in body heights
  t.maxPeople = person.frames.empty() ? 0 : 1;
  t.people.push_back(std::move(person));
  t.chosenReason = "the tracked person";
  checkSeenJoints(t, options);
  return t;
}

}  // namespace ew
