#include "video/pose_detector.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include "core/common/errors.h"

namespace ew {
namespace {

using SteadyClock = std::chrono::steady_clock;

double secondsSince(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

constexpr std::array<std::pair<int, int>, 16> kLeftRightPairs = {{{1, 4}, {2, 5}, {3, 6}, {7, 8}, {9, 10},
                                                                  {11, 12}, {13, 14}, {15, 16}, {17, 18},
                                                                  {19, 20}, {21, 22}, {23, 24}, {25, 26},
                                                                  {27, 28}, {29, 30}, {31, 32}}};

// A person being followed: the crop for the next frame.
struct Follow {
  int id = 0;
  PoseRoi roi;
  int lastFrame = 0;
};

// A found person is already followed when its hip centre lies within half a crop of a
// followed person's (the crop is about 2.5 body halves across).
bool alreadyFollowed(const PersonBox& found, const std::vector<Follow>& follows) {
  return std::any_of(follows.begin(), follows.end(), [&](const Follow& f) {
    return cv::norm(found.hipCentre - f.roi.centre) < 0.5 * std::max(f.roi.sidePx, found.roi().sidePx);
  });
}

// Two follows on the same person (a crop that drifted onto someone already followed): the
// later one is dropped.
void dropDuplicates(std::vector<Follow>& follows, std::vector<FollowedPose>& poses) {
  for (std::size_t i = 0; i < poses.size(); ++i)
    for (std::size_t j = poses.size(); j-- > i + 1;) {
      const auto& a = poses[i].landmarks;
      const auto& b = poses[j].landmarks;
      if (cv::norm(a.hipCentre - b.hipCentre) < 0.15 * std::max(a.roi.sidePx, b.roi.sidePx)) {
        const int drop = poses[j].personId;
        poses.erase(poses.begin() + static_cast<std::ptrdiff_t>(j));
        std::erase_if(follows, [&](const Follow& f) { return f.id == drop; });
      }
    }
}

class PoseFollower {
 public:
  PoseFollower(const PoseModelFiles& files, const PoseDetectionOptions& options, double fps)
      : people_(files.personDetector),
        landmarks_(files.landmarks),
        options_(options),
        searchEveryFrames_(std::max(1, static_cast<int>(std::lround(options.searchEverySeconds * fps)))) {}

  std::vector<FollowedPose> step(const cv::Mat& bgr, int frame, PoseDetectionRun& run) {
    if (follows_.empty() || (frame - options_.firstFrame) % searchEveryFrames_ == 0) search(bgr, frame, run);
    std::vector<FollowedPose> poses;
    const auto start = SteadyClock::now();
    for (auto it = follows_.begin(); it != follows_.end();) {
      PoseLandmarks found = landmarks_.detect(bgr, it->roi);
      if (found.poseScore < options_.minPoseScore) {
        it = follows_.erase(it);  // lost: the track ends here
        continue;
      }
      it->roi = found.nextRoi();
      it->lastFrame = frame;
      poses.push_back({it->id, std::move(found)});
      ++it;
    }
    run.landmarkSeconds += secondsSince(start);
    dropDuplicates(follows_, poses);
    return poses;
  }

 private:
  void search(const cv::Mat& bgr, int frame, PoseDetectionRun& run) {
    const auto start = SteadyClock::now();
    const auto found = options_.tiles ? detectPeopleWithTiles(people_, bgr) : people_.detect(bgr);
    run.personSeconds += secondsSince(start);
    for (const PersonBox& p : found) {
      if (static_cast<int>(follows_.size()) >= options_.maxPeople) break;
      if (alreadyFollowed(p, follows_)) continue;
      follows_.push_back({nextId_++, p.roi(), frame});
    }
  }

  PersonDetector people_;
  LandmarkModel landmarks_;
  PoseDetectionOptions options_;
  int searchEveryFrames_;
  std::vector<Follow> follows_;
  int nextId_ = 0;
};

// [SECTION] left and right through time

// The left/right pairs a group's labels cover (the cost looks at the body's pairs only: the
// face's points are close together), and those it swaps.
std::vector<std::pair<int, int>> pairsOf(LeftRightGroup group, bool forCost) {
  std::vector<std::pair<int, int>> out;
  for (const auto& [l, r] : kLeftRightPairs) {
    const bool arm = l >= 13 && l <= 21, leg = l >= 25;
    const bool in = group == LeftRightGroup::Body ? (!forCost || l >= 11) : group == LeftRightGroup::Arms ? arm : leg;
    if (in) out.emplace_back(l, r);
  }
  return out;
}

double travel(const PoseLandmarks& from, const PoseLandmarks& to, bool swapped,
              const std::vector<std::pair<int, int>>& pairs) {
  double sum = 0.0;
  for (const auto& [l, r] : pairs) {
    const Landmark& a = from.points[static_cast<std::size_t>(l)];
    const Landmark& b = from.points[static_cast<std::size_t>(r)];
    const Landmark& c = to.points[static_cast<std::size_t>(swapped ? r : l)];
    const Landmark& d = to.points[static_cast<std::size_t>(swapped ? l : r)];
    sum += std::hypot(c.x - a.x, c.y - a.y) + std::hypot(d.x - b.x, d.y - b.y);
  }
  return sum / std::max(1.0, to.roi.sidePx);
}

// Whole-body swaps first (the model taking the person to face the other way, for any number of
// frames), then a leg or arm pair swapped alone for a few frames (kLimbSwapCost).
void fixLeftRightOfEachPerson(PoseDetectionRun& run) {
  for (const auto& [group, cost] : {std::pair{LeftRightGroup::Body, kBodySwapCost},
                                    std::pair{LeftRightGroup::Legs, kLimbSwapCost},
                                    std::pair{LeftRightGroup::Arms, kLimbSwapCost}})
    for (int id = 0; id < run.people; ++id) {
      std::vector<std::pair<std::size_t, std::size_t>> where;  // (frame, index) of the person's poses
      int previous = std::numeric_limits<int>::min();
      const auto flush = [&, group = group, cost = cost]() {
        std::vector<const PoseLandmarks*> path;
        for (const auto& [f, i] : where) path.push_back(&run.poses[f][i].landmarks);
        const auto swaps = consistentLeftRight(path, group, cost);
        for (std::size_t k = 0; k < where.size(); ++k)
          if (swaps[k]) {
            swapLeftRight(run.poses[where[k].first][where[k].second].landmarks, group);
            ++run.leftRightSwapsUndone;
          }
        where.clear();
      };
      for (std::size_t f = 0; f < run.poses.size(); ++f)
        for (std::size_t i = 0; i < run.poses[f].size(); ++i)
          if (run.poses[f][i].personId == id) {
            if (static_cast<int>(f) != previous + 1) flush();
            where.emplace_back(f, i);
            previous = static_cast<int>(f);
          }
      flush();
    }
}

// Ids from 0 in the order people first appear; a person the detector proposed whom the
// landmark model never confirmed is not counted. Returns how many appear.
int numberPeopleInOrderOfAppearance(PoseDetectionRun& run) {
  std::map<int, int> renumbered;
  for (auto& frame : run.poses)
    for (FollowedPose& p : frame) {
      const auto [it, added] = renumbered.try_emplace(p.personId, static_cast<int>(renumbered.size()));
      p.personId = it->second;
    }
  return static_cast<int>(renumbered.size());
}

// Each person's consecutive poses, in runs (a gap starts a new run).
std::vector<std::vector<PoseLandmarks*>> runsOfEachPerson(PoseDetectionRun& run) {
  std::vector<std::vector<PoseLandmarks*>> runs;
  for (int id = 0; id < run.people; ++id) {
    std::vector<PoseLandmarks*> current;
    int previous = std::numeric_limits<int>::min();
    for (std::size_t f = 0; f < run.poses.size(); ++f)
      for (FollowedPose& p : run.poses[f])
        if (p.personId == id) {
          if (static_cast<int>(f) != previous + 1 && !current.empty()) runs.push_back(std::move(current)), current.clear();
          current.push_back(&p.landmarks);
          previous = static_cast<int>(f);
        }
    if (!current.empty()) runs.push_back(std::move(current));
  }
  return runs;
}

}  // namespace

void smoothLandmarks(const std::vector<PoseLandmarks*>& frames, int halfWindow) {
  const int n = static_cast<int>(frames.size());
  if (halfWindow < 1 || n < 2 * halfWindow + 1) return;
  // Quadratic Savitzky-Golay weights for the centre of 2m+1 points: 
  // w_i = 3 (3m^2 + 3m - 1 - 5 i^2) / ((2m + 3)(2m + 1)(2m - 1)).
  const auto weights = [](int m) {
    std::vector<double> w(static_cast<std::size_t>(2 * m + 1));
    const double norm = (2.0 * m + 3) * (2.0 * m + 1) * (2.0 * m - 1);
    for (int i = -m; i <= m; ++i) w[static_cast<std::size_t>(i + m)] = 3.0 * (3.0 * m * m + 3 * m - 1 - 5.0 * i * i) / norm;
    return w;
  };
  std::vector<std::array<double, 2 * kBlazePoseLandmarks>> raw(static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < kBlazePoseLandmarks; ++k) {
      raw[static_cast<std::size_t>(t)][static_cast<std::size_t>(2 * k)] = frames[static_cast<std::size_t>(t)]->points[static_cast<std::size_t>(k)].x;
      raw[static_cast<std::size_t>(t)][static_cast<std::size_t>(2 * k + 1)] = frames[static_cast<std::size_t>(t)]->points[static_cast<std::size_t>(k)].y;
    }
  for (int t = 0; t < n; ++t) {
    const int m = std::min({halfWindow, t, n - 1 - t});  // the window shrinks at the ends
    if (m < 1) continue;
    const auto w = weights(m);
    for (int k = 0; k < kBlazePoseLandmarks; ++k) {
      double x = 0.0, y = 0.0;
      for (int i = -m; i <= m; ++i) {
        x += w[static_cast<std::size_t>(i + m)] * raw[static_cast<std::size_t>(t + i)][static_cast<std::size_t>(2 * k)];
        y += w[static_cast<std::size_t>(i + m)] * raw[static_cast<std::size_t>(t + i)][static_cast<std::size_t>(2 * k + 1)];
      }
      frames[static_cast<std::size_t>(t)]->points[static_cast<std::size_t>(k)].x = x;
      frames[static_cast<std::size_t>(t)]->points[static_cast<std::size_t>(k)].y = y;
    }
  }
}

void swapLeftRight(PoseLandmarks& pose, LeftRightGroup group) {
  for (const auto& [l, r] : pairsOf(group, false))
    std::swap(pose.points[static_cast<std::size_t>(l)], pose.points[static_cast<std::size_t>(r)]);
}

std::vector<bool> consistentLeftRight(const std::vector<const PoseLandmarks*>& frames, LeftRightGroup group,
                                     double swapCost) {
  const auto pairs = pairsOf(group, true);
  const std::size_t n = frames.size();
  std::vector<bool> swaps(n, false);
  if (n == 0) return swaps;
  // cost[t][s]: the least cost of frames 0..t with frame t in state s (1: swapped).
  std::vector<std::array<double, 2>> cost(n);
  std::vector<std::array<int, 2>> from(n, {0, 0});
  cost[0] = {0.0, swapCost};
  for (std::size_t t = 1; t < n; ++t) {
    const double same = travel(*frames[t - 1], *frames[t], false, pairs);
    const double crossed = travel(*frames[t - 1], *frames[t], true, pairs);
    for (int s = 0; s < 2; ++s) {
      // From state p to state s: the labels move by `same` when p == s, else by `crossed`.
      const double viaKeep = cost[t - 1][0] + (s == 0 ? same : crossed);
      const double viaSwap = cost[t - 1][1] + (s == 1 ? same : crossed);
      from[t][static_cast<std::size_t>(s)] = viaSwap < viaKeep ? 1 : 0;
      cost[t][static_cast<std::size_t>(s)] = std::min(viaKeep, viaSwap) + (s == 1 ? swapCost : 0.0);
    }
  }
  int s = cost[n - 1][1] < cost[n - 1][0] ? 1 : 0;
  for (std::size_t t = n; t-- > 0;) {
    swaps[t] = s == 1;
    s = from[t][static_cast<std::size_t>(s)];
  }
  return swaps;
}

PoseDetectionRun detectPoses(const std::filesystem::path& videoFile, const PoseDetectionOptions& options) {
  const auto start = SteadyClock::now();
  const PoseModelFiles files = requirePoseModels(options.model);
  VideoSource source(videoFile);
  PoseDetectionRun run;
  run.video = source.info();
  run.model = options.model;
  if (run.video.widthPx < 32 || run.video.heightPx < 32)
    throw Error(ErrorKind::BadData, videoFile.string(), "",
                "the picture is " + std::to_string(run.video.widthPx) + " x " + std::to_string(run.video.heightPx) +
                    " px: too small to find a person in (32 x 32 at least)");
  const int last = options.lastFrame < 0 ? run.video.frameCount - 1 : std::min(options.lastFrame, run.video.frameCount - 1);
  if (options.firstFrame < 0 || options.firstFrame > last)
    throw Error(ErrorKind::BadArgument, videoFile.string(), "",
                "frames " + std::to_string(options.firstFrame) + " to " + std::to_string(last) + " hold nothing to detect");
  run.firstFrame = options.firstFrame;
  PoseFollower follower(files, options, run.video.fps > 0 ? run.video.fps : 30.0);
  const int total = last - options.firstFrame + 1;
  for (int f = options.firstFrame; f <= last; ++f) {
    auto decodeStart = SteadyClock::now();
    cv::Mat bgr;
    try {
      bgr = source.frame(f);
    } catch (const Error& e) {
      // The container promised more frames than the stream holds: keep what was read.
      if (f == options.firstFrame) throw;
      run.warnings.push_back("the video ends early: " + std::to_string(f - options.firstFrame) + " of " +
                             std::to_string(total) + " frames decode (" + e.what() + ")");
      break;
    }
    run.decodeSeconds += secondsSince(decodeStart);
    run.poses.push_back(follower.step(bgr, f, run));
    if (options.onFrame) options.onFrame(f, run.poses.back());
    if (options.progress && !options.progress(f - options.firstFrame + 1, total)) {
      run.cancelled = true;
      break;
    }
  }
  run.people = numberPeopleInOrderOfAppearance(run);
  if (options.fixLeftRight) fixLeftRightOfEachPerson(run);
  const int halfWindow = static_cast<int>(std::lround(options.smoothSeconds * (run.video.fps > 0 ? run.video.fps : 30.0) / 2.0));
  if (halfWindow >= 1)
    for (const auto& personRun : runsOfEachPerson(run)) smoothLandmarks(personRun, halfWindow);
  run.totalSeconds = secondsSince(start);
  return run;
}

KeypointFrames keypointFramesOf(const PoseDetectionRun& run) {
  KeypointFrames k;
  k.file = run.video.file;
  k.format = "BlazePose (built-in detector, " + std::string(poseModelSizeName(run.model)) + ")";
  k.pointCount = kBlazePoseLandmarks;
  k.layoutHint = "MediaPipe-33";
  if (run.video.fps > 0) k.rateHz = run.video.fps;
  k.imageSize = KeypointImageSize{run.video.widthPx, run.video.heightPx};
  k.frames.resize(static_cast<std::size_t>(run.firstFrame) + run.poses.size());
  for (std::size_t f = 0; f < run.poses.size(); ++f) {
    auto& out = k.frames[static_cast<std::size_t>(run.firstFrame) + f];
    for (const FollowedPose& p : run.poses[f]) {
      KeypointDetection d;
      d.trackId = p.personId;
      d.points.resize(kBlazePoseLandmarks, 3);
      for (int i = 0; i < kBlazePoseLandmarks; ++i) {
        const Landmark& lm = p.landmarks.points[static_cast<std::size_t>(i)];
        // A landmark outside the picture is the model's guess at a part it cannot see: missing.
        const bool inside = lm.x >= -0.5 && lm.y >= -0.5 && lm.x <= run.video.widthPx - 0.5 &&
                            lm.y <= run.video.heightPx - 0.5 && std::isfinite(lm.visibility);
        if (inside) d.points.row(i) << lm.x, lm.y, lm.visibility;
        else d.points.row(i) << std::nan(""), std::nan(""), 0.0;
      }
      out.push_back(std::move(d));
    }
  }
  k.warnings = run.warnings;
  return k;
}

}  // namespace ew
