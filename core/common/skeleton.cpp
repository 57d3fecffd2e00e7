#include "core/common/skeleton.h"

namespace ew {

std::string_view jointName(Joint j) { return kJointNames[static_cast<size_t>(index(j))]; }

std::optional<Joint> jointFromName(std::string_view name) {
  for (int i = 0; i < kJointCount; ++i) {
    if (kJointNames[static_cast<size_t>(i)] == name) return static_cast<Joint>(i);
  }
  return std::nullopt;
}

Joint mirrorJoint(Joint j) {
  switch (j) {
    case Joint::RShoulder: return Joint::LShoulder;
    case Joint::RElbow: return Joint::LElbow;
    case Joint::RWrist: return Joint::LWrist;
    case Joint::LShoulder: return Joint::RShoulder;
    case Joint::LElbow: return Joint::RElbow;
    case Joint::LWrist: return Joint::RWrist;
    case Joint::RHip: return Joint::LHip;
    case Joint::RKnee: return Joint::LKnee;
    case Joint::RAnkle: return Joint::LAnkle;
    case Joint::LHip: return Joint::RHip;
    case Joint::LKnee: return Joint::RKnee;
    case Joint::LAnkle: return Joint::RAnkle;
    default: return j;
  }
}

}  // namespace ew
