#pragma once
// The 15-joint skeleton of METHOD §1: fixed joint order, names and drawing bones.
// Every trajectory matrix in core stores frames as rows and joints joint-major:
// columns x0,y0,z0,x1,y1,z1,… (45 columns in 3D) or u0,v0,u1,v1,… (30 in 2D).

#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace ew {

inline constexpr int kJointCount = 15;
inline constexpr int kDims3 = 3 * kJointCount;  // 45 values per 3D frame
inline constexpr int kDims2 = 2 * kJointCount;  // 30 values per 2D frame

enum class Joint : int {
  Head = 0,
  Sternum = 1,
  Pelvis = 2,
  RShoulder = 3,
  RElbow = 4,
  RWrist = 5,
  LShoulder = 6,
  LElbow = 7,
  LWrist = 8,
  RHip = 9,
  RKnee = 10,
  RAnkle = 11,
  LHip = 12,
  LKnee = 13,
  LAnkle = 14,
};

constexpr int index(Joint j) { return static_cast<int>(j); }

// METHOD §1 names, also the CSV column stems (head_x, …, l_ankle_z).
inline constexpr std::array<std::string_view, kJointCount> kJointNames = {
    "head",    "sternum",    "pelvis", "r_shoulder", "r_elbow",
    "r_wrist", "l_shoulder", "l_elbow", "l_wrist",   "r_hip",
    "r_knee",  "r_ankle",    "l_hip",  "l_knee",     "l_ankle"};

inline constexpr std::array<std::pair<Joint, Joint>, 14> kBones = {{
    {Joint::Head, Joint::Sternum},
    {Joint::Sternum, Joint::Pelvis},
    {Joint::Sternum, Joint::RShoulder},
    {Joint::Sternum, Joint::LShoulder},
    {Joint::RShoulder, Joint::RElbow},
    {Joint::RElbow, Joint::RWrist},
    {Joint::LShoulder, Joint::LElbow},
    {Joint::LElbow, Joint::LWrist},
    {Joint::Pelvis, Joint::RHip},
    {Joint::Pelvis, Joint::LHip},
    {Joint::RHip, Joint::RKnee},
    {Joint::RKnee, Joint::RAnkle},
    {Joint::LHip, Joint::LKnee},
    {Joint::LKnee, Joint::LAnkle},
}};

std::string_view jointName(Joint j);
std::optional<Joint> jointFromName(std::string_view name);

// The mirror partner of a joint (r_knee <-> l_knee); midline joints map to themselves.
Joint mirrorJoint(Joint j);

}  // namespace ew
