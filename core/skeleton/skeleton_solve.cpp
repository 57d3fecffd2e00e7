#include "core/skeleton/skeleton_solve.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/common/errors.h"

namespace ew {

namespace {

constexpr int kTorsoBones = 6;  // the first six entries of kTreeOrder
constexpr int kTorsoChoices = 1 << kTorsoBones;
constexpr int kLimbChoices = 4;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Limb {
  int firstTreeEntry;  // into kTreeOrder: the upper segment, then the lower
  bool isLeg;
};
constexpr std::array<Limb, 4> kLimbs = {{{6, false}, {8, false}, {10, true}, {12, true}}};

int bitSign(int choice, int bit) { return (choice >> bit) & 1 ? -1 : 1; }

Eigen::Vector3d placeChild(const JointRays& rays, const Eigen::Vector3d& parent, int child, double lengthMm, int sign) {
  const RayRoots r = rootsOnRay(rays, child, parent, lengthMm);
  return rays.origin.col(child) + (r.t0 + sign * r.halfGap) * rays.direction.col(child);
}

// Places the tree entries [first, first + count) of one frame with their signs.
void placeEntries(const JointRays& rays, const BoneLengths& bones, const std::array<int, kBoneCount>& signs, int first,
                  int count, JointMatrix& joints) {
  for (int i = first; i < first + count; ++i) {
    const TreeBone& tb = kTreeOrder[static_cast<size_t>(i)];
    const auto b = static_cast<size_t>(tb.bone);
    joints.col(index(tb.child)) = placeChild(rays, joints.col(index(tb.parent)), index(tb.child), bones.mm[b], signs[b]);
  }
}

double oneMinusCos(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double n = a.norm() * b.norm();
  return n > 0.0 ? 1.0 - a.dot(b) / n : 0.0;
}

// Hips not symmetric about the pelvis, the shoulder line not along the hip line, the head
// not continuing the trunk, the trunk leaning backward (walkers lean forward, and the
// sternum sits in front of the pelvis's centre).
double torsoImplausibility(const JointMatrix& j, const BoneLengths& bones, const Eigen::Vector3d& up) {
  const Eigen::Vector3d pelvis = j.col(index(Joint::Pelvis));
  const Eigen::Vector3d right = j.col(index(Joint::RHip)) - j.col(index(Joint::LHip));
  const Eigen::Vector3d hipSum = j.col(index(Joint::RHip)) + j.col(index(Joint::LHip)) - 2.0 * pelvis;
  const double hipScale2 = bones.mm[8] * bones.mm[8] + bones.mm[9] * bones.mm[9];
  const double hips = hipScale2 > 0.0 ? hipSum.squaredNorm() / hipScale2 : 0.0;
  const double shoulders = oneMinusCos(j.col(index(Joint::RShoulder)) - j.col(index(Joint::LShoulder)), right);
  const Eigen::Vector3d trunk = j.col(index(Joint::Sternum)) - pelvis;
  const double head = oneMinusCos(j.col(index(Joint::Head)) - j.col(index(Joint::Sternum)), trunk);
  const Eigen::Vector3d forward = up.cross(right);
  const double n = forward.norm() * trunk.norm();
  const double lean = n > 0.0 ? forward.dot(trunk) / n : 0.0;
  return hips + shoulders + head + std::min(0.0, lean) * std::min(0.0, lean);
}

// An arm hangs at the side of the trunk: the elbow and the wrist are not nearer the body's
// midline than the shoulder (the sine of the angle by which they are; a flipped arm seen
// from the side reaches through the trunk).
double armAcrossBody(const JointMatrix& j, const Limb& limb, const Eigen::Vector3d& right) {
  const TreeBone& upper = kTreeOrder[static_cast<size_t>(limb.firstTreeEntry)];
  const TreeBone& lower = kTreeOrder[static_cast<size_t>(limb.firstTreeEntry + 1)];
  const Eigen::Vector3d shoulder = j.col(index(upper.parent));
  const double side = upper.parent == Joint::RShoulder ? 1.0 : -1.0;
  const Eigen::Vector3d outward = side * right.normalized();
  double cost = 0.0;
  for (const Joint k : {upper.child, lower.child}) {
    const Eigen::Vector3d v = j.col(index(k)) - shoulder;
    const double n = v.norm();
    if (n > 0.0) cost += std::pow(std::min(0.0, v.dot(outward) / n), 2);
  }
  return cost;
}

// A knee flexes backward (the shank turns behind the thigh), an elbow forward: with the
// body's right axis r, the knee's (thigh × shank)·r ≤ 0 and the elbow's (upper × fore)·r ≥ 0.
// The cost is the squared sine of the bend the wrong way.
double hingeImplausibility(const JointMatrix& j, const Limb& limb) {
  const TreeBone& upper = kTreeOrder[static_cast<size_t>(limb.firstTreeEntry)];
  const TreeBone& lower = kTreeOrder[static_cast<size_t>(limb.firstTreeEntry + 1)];
  const Eigen::Vector3d right = limb.isLeg ? j.col(index(Joint::RHip)) - j.col(index(Joint::LHip))
                                           : j.col(index(Joint::RShoulder)) - j.col(index(Joint::LShoulder));
  const Eigen::Vector3d a = j.col(index(upper.child)) - j.col(index(upper.parent));
  const Eigen::Vector3d b = j.col(index(lower.child)) - j.col(index(upper.child));
  const double n = a.norm() * b.norm() * right.norm();
  if (!(n > 0.0)) return 0.0;
  const double bend = a.cross(b).dot(right) / n;
  const double wrong = limb.isLeg ? std::max(0.0, bend) : std::max(0.0, -bend);
  return wrong * wrong + (limb.isLeg ? 0.0 : armAcrossBody(j, limb, right));
}

void checkInputs(const std::vector<JointRays>& rays, const std::vector<Eigen::Vector3d>& roots, double rateHz) {
  if (rays.empty()) throw Error(ErrorKind::BadArgument, "skeleton", "", "no frames to reconstruct");
  if (rays.size() != roots.size()) {
    throw Error(ErrorKind::BadArgument, "skeleton", "",
                std::to_string(rays.size()) + " frames of rays but " + std::to_string(roots.size()) + " roots");
  }
  if (!(rateHz > 0.0) || !std::isfinite(rateHz)) {
    throw Error(ErrorKind::BadArgument, "skeleton", "", "the rate must be positive and finite");
  }
  for (size_t t = 0; t < rays.size(); ++t) {
    for (int j = 0; j < kJointCount; ++j) {
      if (!rays[t].origin.col(j).allFinite() || !rays[t].direction.col(j).allFinite()) {
        throw Error(ErrorKind::BadData, "skeleton", "frame " + std::to_string(t),
                    std::string(jointName(static_cast<Joint>(j))) +
                        " is not seen: the geometry needs every joint in every frame (fill gaps first)");
      }
    }
    if (!roots[t].allFinite()) {
      throw Error(ErrorKind::BadData, "skeleton", "frame " + std::to_string(t), "the root is not finite");
    }
  }
}

// Stage 1: one bone's branch over the frames, up to one sign for the whole clip. The bone's
// depth offset along the child's ray is δ(t) = s(t)·g(t), g = √(L² − ρ²) measured with the
// parent at the root's depth on its own ray (exact for an orthographic view, where g does
// not depend on the parent's depth). A real bone's δ(t) is smooth: where the bone turns
// through the image plane g touches 0 and δ changes sign with a steady slope, where it only
// approaches the plane δ comes back with the same sign. Viterbi over the sign pairs
// (s(t−1), s(t)) minimises Σ (δ(t+1) − 2δ(t) + δ(t−1))², which tells the two apart.
std::vector<int> relativeBranch(const std::vector<double>& gap) {
  const int frames = static_cast<int>(gap.size());
  std::vector<int> signs(static_cast<size_t>(frames), 1);
  if (frames < 3) return signs;
  // State k at pair-frame t (frames t, t+1): bit 0 the sign at t, bit 1 the sign at t+1.
  const auto signAt = [](int state, int bit) { return (state >> bit) & 1 ? -1.0 : 1.0; };
  const int pairs = frames - 1;
  std::vector<double> cost(4, 0.0), next(4);
  std::vector<int> back(static_cast<size_t>(pairs * 4), 0);
  for (int t = 1; t < pairs; ++t) {
    for (int s = 0; s < 4; ++s) {
      double best = kInf;
      int arg = 0;
      for (int p = 0; p < 4; ++p) {
        if (signAt(p, 1) != signAt(s, 0)) continue;  // the shared frame t has one sign
        const double d2 = signAt(s, 1) * gap[static_cast<size_t>(t + 1)] - 2.0 * signAt(s, 0) * gap[static_cast<size_t>(t)] +
                          signAt(p, 0) * gap[static_cast<size_t>(t - 1)];
        const double c = cost[static_cast<size_t>(p)] + d2 * d2;
        if (c < best) { best = c; arg = p; }
      }
      next[static_cast<size_t>(s)] = best;
      back[static_cast<size_t>(t * 4 + s)] = arg;
    }
    std::swap(cost, next);
  }
  int state = static_cast<int>(std::min_element(cost.begin(), cost.end()) - cost.begin());
  for (int t = pairs - 1; t >= 0; --t) {
    signs[static_cast<size_t>(t + 1)] = static_cast<int>(signAt(state, 1));
    signs[static_cast<size_t>(t)] = static_cast<int>(signAt(state, 0));
    if (t > 0) state = back[static_cast<size_t>(t * 4 + state)];
  }
  if (signs.front() < 0)
    for (int& v : signs) v = -v;
  return signs;
}

// g(t) of one bone (stage 1's measurement).
std::vector<double> branchGaps(const std::vector<JointRays>& rays, const std::vector<Eigen::Vector3d>& roots,
                               const TreeBone& tb, double lengthMm) {
  std::vector<double> gap(rays.size());
  const int p = index(tb.parent);
  for (size_t t = 0; t < rays.size(); ++t) {
    const JointRays& r = rays[t];
    const Eigen::Vector3d parent =
        r.origin.col(p) + r.direction.col(p).dot(roots[t] - r.origin.col(p)) * r.direction.col(p);
    gap[t] = rootsOnRay(r, index(tb.child), parent, lengthMm).halfGap;
  }
  return gap;
}


// Each bone's root nearer the guide's bone vector, depth-first from the root.
std::array<int, kBoneCount> guidedSigns(const JointRays& rays, const Eigen::Vector3d& root, const BoneLengths& bones,
                                        const JointMatrix& guide) {
  std::array<int, kBoneCount> signs{};
  JointMatrix joints;
  joints.col(index(Joint::Pelvis)) = root;
  for (const TreeBone& tb : kTreeOrder) {
    const auto b = static_cast<size_t>(tb.bone);
    const Eigen::Vector3d parent = joints.col(index(tb.parent));
    const Eigen::Vector3d want = guide.col(index(tb.child)) - guide.col(index(tb.parent));
    const Eigen::Vector3d plus = placeChild(rays, parent, index(tb.child), bones.mm[b], 1);
    const Eigen::Vector3d minus = placeChild(rays, parent, index(tb.child), bones.mm[b], -1);
    signs[b] = (plus - parent - want).squaredNorm() <= (minus - parent - want).squaredNorm() ? 1 : -1;
    joints.col(index(tb.child)) = signs[b] > 0 ? plus : minus;
  }
  return signs;
}

// Stages 1 and 2 (the header): per bone its branch over the clip up to a sign, then the 14
// signs by the least implausible clip. Returns the signs of every frame.
std::vector<std::array<int, kBoneCount>> plausibleSigns(const std::vector<JointRays>& rays,
                                                        const std::vector<Eigen::Vector3d>& rootsMm,
                                                        const BoneLengths& bones, const SkeletonSolveOptions& options) {
  const size_t frames = rays.size();

  // Stage 1: every bone's branch over the clip, up to one sign per bone.
  std::array<std::vector<int>, kBoneCount> relative;
  for (const TreeBone& tb : kTreeOrder) {
    relative[static_cast<size_t>(tb.bone)] =
        relativeBranch(branchGaps(rays, rootsMm, tb, bones.mm[static_cast<size_t>(tb.bone)]));
  }
  const auto signsAt = [&](size_t t, const std::array<int, kBoneCount>& global) {
    std::array<int, kBoneCount> s{};
    for (int b = 0; b < kBoneCount; ++b) s[static_cast<size_t>(b)] = global[static_cast<size_t>(b)] * relative[static_cast<size_t>(b)][t];
    return s;
  };

  // Stage 2: the 14 clip-wide signs by the least implausible whole clip: the torso's 64
  // choices, each with every limb's best of its 4 given that torso.
  double bestTotal = kInf;
  std::array<int, kBoneCount> best{};
  std::vector<JointMatrix> torso(frames);
  for (int choice = 0; choice < kTorsoChoices; ++choice) {
    std::array<int, kBoneCount> global;
    global.fill(1);
    for (int i = 0; i < kTorsoBones; ++i) global[static_cast<size_t>(kTreeOrder[static_cast<size_t>(i)].bone)] = bitSign(choice, i);
    double total = 0.0;
    for (size_t t = 0; t < frames; ++t) {
      torso[t].col(index(Joint::Pelvis)) = rootsMm[t];
      placeEntries(rays[t], bones, signsAt(t, global), 0, kTorsoBones, torso[t]);
      total += options.symmetryWeight * torsoImplausibility(torso[t], bones, options.upMm);
    }
    for (const Limb& limb : kLimbs) {
      double bestLimb = kInf;
      int bestChoice = 0;
      for (int lc = 0; lc < kLimbChoices && total < bestTotal; ++lc) {
        std::array<int, kBoneCount> g = global;
        g[static_cast<size_t>(kTreeOrder[static_cast<size_t>(limb.firstTreeEntry)].bone)] = bitSign(lc, 0);
        g[static_cast<size_t>(kTreeOrder[static_cast<size_t>(limb.firstTreeEntry + 1)].bone)] = bitSign(lc, 1);
        double cost = 0.0;
        for (size_t t = 0; t < frames && cost < bestLimb; ++t) {
          JointMatrix j = torso[t];
          placeEntries(rays[t], bones, signsAt(t, g), limb.firstTreeEntry, 2, j);
          cost += options.hingeWeight * hingeImplausibility(j, limb);
        }
        if (cost < bestLimb) { bestLimb = cost; bestChoice = lc; }
      }
      total += bestLimb;
      global[static_cast<size_t>(kTreeOrder[static_cast<size_t>(limb.firstTreeEntry)].bone)] = bitSign(bestChoice, 0);
      global[static_cast<size_t>(kTreeOrder[static_cast<size_t>(limb.firstTreeEntry + 1)].bone)] = bitSign(bestChoice, 1);
    }
    if (total < bestTotal) { bestTotal = total; best = global; }
  }
  std::vector<std::array<int, kBoneCount>> signs;
  for (size_t t = 0; t < frames; ++t) signs.push_back(signsAt(t, best));
  return signs;
}

}  // namespace

SkeletonSequence solveSkeletonSequence(const std::vector<JointRays>& rays, const std::vector<Eigen::Vector3d>& rootsMm,
                                       const BoneLengths& bones, double rateHz, const SkeletonSolveOptions& options) {
  checkInputs(rays, rootsMm, rateHz);
  const size_t frames = rays.size();
  std::vector<std::array<int, kBoneCount>> signs;
  if (options.guideMm.empty()) {
    signs = plausibleSigns(rays, rootsMm, bones, options);
  } else {
    if (options.guideMm.size() != frames)
      throw Error(ErrorKind::BadArgument, "skeleton", "", "the guide needs one pose per frame");
    for (size_t t = 0; t < frames; ++t) {
      if (!options.guideMm[t].allFinite())
        throw Error(ErrorKind::BadArgument, "skeleton", "frame " + std::to_string(t), "the guide's pose is not finite");
      signs.push_back(guidedSigns(rays[t], rootsMm[t], bones, options.guideMm[t]));
    }
  }

  SkeletonSequence out;
  out.framesMm.resize(static_cast<Eigen::Index>(frames), kDims3);
  out.poseCost = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(frames));
  for (size_t t = 0; t < frames; ++t) {
    out.signs.push_back(signs[t]);
    const TreePlacement placed = placeTree(rays[t], rootsMm[t], bones, out.signs.back());
    for (int b = 0; b < kBoneCount; ++b) {
      if (!placed.clamped[static_cast<size_t>(b)]) continue;
      ++out.clampedFrames[static_cast<size_t>(b)];
      ++out.clampedBoneFrames;
    }
    double cost = options.symmetryWeight * torsoImplausibility(placed.joints, bones, options.upMm);
    for (const Limb& limb : kLimbs) cost += options.hingeWeight * hingeImplausibility(placed.joints, limb);
    out.poseCost(static_cast<Eigen::Index>(t)) = cost;
    for (int j = 0; j < kJointCount; ++j)
      out.framesMm.row(static_cast<Eigen::Index>(t)).segment<3>(3 * j) = placed.joints.col(j).transpose();
  }
  return out;
}

}  // namespace ew
