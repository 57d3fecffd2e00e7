// Skeleton joint centres (BVH, ASF/AMC) -> the 15 joints of METHOD §1.
// The rules, and why each point was chosen, are in docs/JOINTS.md ("BVH (CMU, Mixamo)",
// "ASF/AMC (CMU)"). Each skeleton convention is a table of rules; a rule is a list of
// alternatives, each the mean of one or more of the file's points (names compared without
// a "namespace:" prefix and case-insensitively, so "mixamorig:LeftArm" is "leftarm").

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/errors.h"
#include "core/io/text_table.h"
#include "core/mapping/joint_mapping.h"

namespace ew {
namespace {

// [SECTION] Rules

using PointSet = std::vector<std::string_view>;  // the mean of these points

struct JointRule {
  Joint joint;
  std::vector<PointSet> alternatives;  // first one whose points all exist wins
};

struct SkeletonConvention {
  std::string_view source;
  std::vector<JointRule> rules;  // a missing head is estimated; every other rule is needed
  bool restoresCmuThorax = false;  // see restoreCmuThorax()
};

// Limbs shared by the CMU BVH conversion and Mixamo: a BVH joint is where its bone
// starts, so LeftLeg is the knee, LeftFoot the ankle, LeftArm the shoulder, LeftForeArm
// the elbow, LeftHand the wrist.
std::vector<JointRule> bvhLimbRules() {
  return {
      {Joint::Pelvis, {{"leftupleg", "rightupleg"}}},
      {Joint::LHip, {{"leftupleg"}}},
      {Joint::LKnee, {{"leftleg"}}},
      {Joint::LAnkle, {{"leftfoot"}}},
      {Joint::RHip, {{"rightupleg"}}},
      {Joint::RKnee, {{"rightleg"}}},
      {Joint::RAnkle, {{"rightfoot"}}},
      {Joint::LShoulder, {{"leftarm"}}},
      {Joint::LElbow, {{"leftforearm"}}},
      {Joint::LWrist, {{"lefthand"}}},
      {Joint::RShoulder, {{"rightarm"}}},
      {Joint::RElbow, {{"rightforearm"}}},
      {Joint::RWrist, {{"righthand"}}},
  };
}

const std::vector<SkeletonConvention>& conventions() {
  static const std::vector<SkeletonConvention> all = [] {
    // CMU BVH (Hahne): Neck sits on Spine1 with a zero offset, so the BVH's Neck->Neck1
    // bone is the ASF's lower neck; Neck1 matches the ASF thorax end in distance from
    // the pelvis (docs/JOINTS.md has the measurements). Head centre: middle of the
    // Head bone (Head joint to its End Site, the top of the skull).
    SkeletonConvention cmuBvh{"CMU BVH (Hahne conversion)", bvhLimbRules(), true};
    cmuBvh.rules.push_back({Joint::Sternum, {{"neck1"}}});
    cmuBvh.rules.push_back({Joint::Head, {{"head", "head_end"}, {"head"}}});
    // Mixamo and most game rigs: Neck is the base of the neck, HeadTop_End the top of
    // the skull (a JOINT, or an End Site named Head_End by our reader).
    SkeletonConvention mixamo{"Mixamo-style BVH", bvhLimbRules()};
    mixamo.rules.push_back({Joint::Sternum, {{"neck"}}});
    mixamo.rules.push_back(
        {Joint::Head, {{"head", "headtop_end"}, {"head", "head_end"}, {"head"}}});
    // CMU ASF/AMC: points are bone ends, so lhipjoint is the hip, lfemur the knee,
    // ltibia the ankle, lclavicle the shoulder, lhumerus the elbow, lradius the wrist.
    SkeletonConvention cmuAsf{"CMU ASF/AMC",
                              {
                                  {Joint::Pelvis, {{"lhipjoint", "rhipjoint"}}},
                                  {Joint::LHip, {{"lhipjoint"}}},
                                  {Joint::LKnee, {{"lfemur"}}},
                                  {Joint::LAnkle, {{"ltibia"}}},
                                  {Joint::RHip, {{"rhipjoint"}}},
                                  {Joint::RKnee, {{"rfemur"}}},
                                  {Joint::RAnkle, {{"rtibia"}}},
                                  {Joint::LShoulder, {{"lclavicle"}}},
                                  {Joint::LElbow, {{"lhumerus"}}},
                                  {Joint::LWrist, {{"lradius"}}},
                                  {Joint::RShoulder, {{"rclavicle"}}},
                                  {Joint::RElbow, {{"rhumerus"}}},
                                  {Joint::RWrist, {{"rradius"}}},
                                  {Joint::Sternum, {{"lowerneck"}}},
                                  {Joint::Head, {{"upperneck", "head"}}},
                              }};
    return std::vector<SkeletonConvention>{cmuBvh, mixamo, cmuAsf};
  }();
  return all;
}

// [SECTION] Matching

// "mixamorig:LeftArm" -> "leftarm": exporters prefix a namespace and vary the case.
std::string normalName(std::string_view label) {
  const size_t colon = label.rfind(':');
  if (colon != std::string_view::npos) label.remove_prefix(colon + 1);
  return toLower(trim(label));
}

using LabelIndex = std::map<std::string, int, std::less<>>;

// Column indices of the first alternative whose points all exist; empty if none does.
std::vector<int> resolve(const JointRule& rule, const LabelIndex& labels) {
  for (const PointSet& set : rule.alternatives) {
    std::vector<int> points;
    for (auto name : set) {
      auto it = labels.find(name);
      if (it == labels.end()) break;
      points.push_back(it->second);
    }
    if (points.size() == set.size()) return points;
  }
  return {};
}

// Names a convention needs that the file lacks (the first alternative of each rule).
std::vector<std::string> missingNames(const SkeletonConvention& c, const LabelIndex& labels) {
  std::vector<std::string> missing;
  for (const JointRule& rule : c.rules) {
    if (rule.joint == Joint::Head || !resolve(rule, labels).empty()) continue;
    for (auto name : rule.alternatives.front()) {
      if (labels.count(name) == 0 &&
          std::find(missing.begin(), missing.end(), name) == missing.end()) {
        missing.emplace_back(name);
      }
    }
  }
  return missing;
}

[[noreturn]] void throwUnknownSkeleton(const RawTrial& raw, const LabelIndex& labels) {
  std::string problem = "skeleton not recognised. Joints found: " + listForMessage(raw.labels, 40) + ".";
  for (const auto& c : conventions()) {
    problem += " " + std::string(c.source) + " would need: " + listForMessage(missingNames(c, labels), 40) + ".";
  }
  throw Error(ErrorKind::UnknownMarkerSet, raw.file, "", problem);
}

}  // namespace

// [SECTION] CMU BVH thorax

// Hahne's CMU conversion gives Neck (and both shoulder chains) a zero offset from Spine1:
// the ASF's thorax segment is gone, so everything it carries (neck, head, shoulder
// girdle, arms) sits one segment too low, ~100 mm (docs/JOINTS.md). The CMU spine is
// three near-equal segments (subject 35: 2.03, 2.03, 2.06 units), so the thorax is
// restored by repeating the Spine->Spine1 segment above Spine1, moving the upper-body
// joints rigidly. Applied only when Neck coincides with Spine1 in every frame (the
// conversion's signature); returns the mean shift in mm, 0 when not applied.
double restoreCmuThorax(const RawTrial& raw, const LabelIndex& labels, JointTrial& out) {
  auto spine = labels.find("spine"), spine1 = labels.find("spine1"), neck = labels.find("neck");
  if (spine == labels.end() || spine1 == labels.end() || neck == labels.end()) return 0.0;
  const Eigen::MatrixXd lower = raw.positionsMm.middleCols(3 * spine->second, 3);
  const Eigen::MatrixXd upper = raw.positionsMm.middleCols(3 * spine1->second, 3);
  const Eigen::MatrixXd neckBase = raw.positionsMm.middleCols(3 * neck->second, 3);
  if (!((neckBase - upper).rowwise().norm().array() < 1.0).all()) return 0.0;
  const Eigen::MatrixXd shift = upper - lower;  // frames x 3
  for (Joint j : {Joint::Head, Joint::Sternum, Joint::LShoulder, Joint::LElbow, Joint::LWrist,
                  Joint::RShoulder, Joint::RElbow, Joint::RWrist}) {
    out.positionsMm.middleCols(3 * index(j), 3) += shift;
  }
  return shift.rowwise().norm().mean();
}

// [SECTION] Mapping

JointTrial mapSkeletonJoints(const RawTrial& raw) {
  LabelIndex labels;
  for (int k = 0; k < raw.pointCount(); ++k) {
    labels.emplace(normalName(raw.labels[static_cast<size_t>(k)]), k);  // first wins
  }
  if (raw.positionsMm.cols() != 3 * static_cast<Eigen::Index>(raw.labels.size())) {
    throw Error(ErrorKind::BadData, raw.file, "", "positions do not match the joint labels");
  }
  for (const SkeletonConvention& c : conventions()) {
    if (!missingNames(c, labels).empty()) continue;
    JointTrial out = jointTrialShell(raw, std::string(c.source), raw.frameCount());
    bool headFound = false;
    for (const JointRule& rule : c.rules) {
      const auto points = resolve(rule, labels);
      if (points.empty()) continue;  // only the head may be missing here
      Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(raw.frameCount(), 3);
      for (int p : points) sum += raw.positionsMm.middleCols(3 * p, 3);
      out.positionsMm.middleCols(3 * index(rule.joint), 3) = sum / static_cast<double>(points.size());
      headFound = headFound || rule.joint == Joint::Head;
    }
    if (c.restoresCmuThorax) {
      if (const double mm = restoreCmuThorax(raw, labels, out); mm > 0.0) {
        out.warnings.push_back("CMU BVH conversion without a thorax segment (Neck on Spine1): "
                               "upper body raised by the Spine->Spine1 segment, " +
                               std::to_string(static_cast<int>(std::lround(mm))) + " mm");
      }
    }
    if (!headFound) {
      for (int f = 0; f < out.frameCount(); ++f) {
        out.positionsMm.block<1, 3>(f, 3 * index(Joint::Head)) =
            estimateHead(jointAt(out.positionsMm, f, Joint::Pelvis),
                         jointAt(out.positionsMm, f, Joint::Sternum))
                .transpose();
      }
      out.estimated[static_cast<size_t>(index(Joint::Head))] = true;
      out.warnings.push_back("the skeleton has no head joint: head estimated from the trunk axis");
    }
    return out;
  }
  throwUnknownSkeleton(raw, labels);
}

}  // namespace ew
