#include "core/io/bvh_writer.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/io/atomic_write.h"

namespace ew {
namespace {

// [SECTION] Skeleton

// Where a node of the BVH skeleton sits in each frame.
enum class Place {
  Joint,     // one of the 15 joints (`joint`)
  HeadBase,  // half-way from the sternum to the head centre
  Toe,       // a toe tip from BvhWriteOptions::toesMm (`side`: 0 right, 1 left)
  Free,      // an End Site with no measurement: carried by its parent's rotation
};

struct Node {
  const char* name;  // nullptr for an End Site
  int parent;
  Place place;
  Joint joint;
  Eigen::Vector3d restDirection;  // BVH axes; zero = the node sits on its parent
  int side = 0;
};

const Eigen::Vector3d kUp(0, 1, 0), kDown(0, -1, 0), kLeft(-1, 0, 0), kRight(1, 0, 0),
    kZero(0, 0, 0);
const Eigen::Vector3d kToeRest = Eigen::Vector3d(0, -0.3, -1).normalized();  // forward is −Z

// Depth-first order: parents before children, subtrees contiguous (the MOTION columns
// follow this order).
const std::vector<Node>& skeleton() {
  static const std::vector<Node> nodes = {
      {"Hips", -1, Place::Joint, Joint::Pelvis, kZero},           // 0
      {"LeftUpLeg", 0, Place::Joint, Joint::LHip, kLeft},         // 1
      {"LeftLeg", 1, Place::Joint, Joint::LKnee, kDown},          // 2
      {"LeftFoot", 2, Place::Joint, Joint::LAnkle, kDown},        // 3
      {nullptr, 3, Place::Toe, Joint::LAnkle, kToeRest, 1},       // 4
      {"RightUpLeg", 0, Place::Joint, Joint::RHip, kRight},       // 5
      {"RightLeg", 5, Place::Joint, Joint::RKnee, kDown},         // 6
      {"RightFoot", 6, Place::Joint, Joint::RAnkle, kDown},       // 7
      {nullptr, 7, Place::Toe, Joint::RAnkle, kToeRest, 0},       // 8
      {"Spine", 0, Place::Joint, Joint::Pelvis, kZero},           // 9
      {"Spine1", 9, Place::Joint, Joint::Sternum, kUp},           // 10
      {"Neck", 10, Place::Joint, Joint::Sternum, kZero},          // 11
      {"Head", 11, Place::HeadBase, Joint::Head, kUp},            // 12
      {nullptr, 12, Place::Free, Joint::Head, kUp},               // 13
      {"LeftShoulder", 10, Place::Joint, Joint::Sternum, kZero},  // 14
      {"LeftArm", 14, Place::Joint, Joint::LShoulder, Eigen::Vector3d(-1, -0.1, 0).normalized()},
      {"LeftForeArm", 15, Place::Joint, Joint::LElbow, kDown},     // 16
      {"LeftHand", 16, Place::Joint, Joint::LWrist, kDown},        // 17
      {nullptr, 17, Place::Free, Joint::LWrist, kDown},            // 18
      {"RightShoulder", 10, Place::Joint, Joint::Sternum, kZero},  // 19
      {"RightArm", 19, Place::Joint, Joint::RShoulder, Eigen::Vector3d(1, -0.1, 0).normalized()},
      {"RightForeArm", 20, Place::Joint, Joint::RElbow, kDown},  // 21
      {"RightHand", 21, Place::Joint, Joint::RWrist, kDown},     // 22
      {nullptr, 22, Place::Free, Joint::RWrist, kDown},          // 23
  };
  return nodes;
}

// Our axes (x right, y forward, z up) to BVH's (X right, Y up, Z backward).
Eigen::Vector3d toBvhAxes(const Eigen::Vector3d& p) { return {p.x(), p.z(), -p.y()}; }

Eigen::Vector3d jointInBvh(const Eigen::MatrixXd& frames, int f, Joint j) {
  return toBvhAxes(frames.block<1, 3>(f, 3 * index(j)).transpose());
}

// Position of every node that has one (Free end sites get NaN), BVH axes.
std::vector<Eigen::Vector3d> placeNodes(const Eigen::MatrixXd& frames, int f,
                                        const BvhWriteOptions& o) {
  const auto& nodes = skeleton();
  std::vector<Eigen::Vector3d> p(nodes.size(), Eigen::Vector3d::Constant(std::nan("")));
  for (size_t k = 0; k < nodes.size(); ++k) {
    const Node& n = nodes[k];
    if (n.place == Place::Joint) p[k] = jointInBvh(frames, f, n.joint);
    if (n.place == Place::HeadBase) {
      p[k] = 0.5 * (jointInBvh(frames, f, Joint::Sternum) + jointInBvh(frames, f, Joint::Head));
    }
    if (n.place == Place::Toe && o.toesMm) {
      p[k] = toBvhAxes(o.toesMm->block<1, 3>(f, 3 * n.side).transpose());
    }
  }
  return p;
}

bool measured(const Node& n, const BvhWriteOptions& o) {
  return n.place == Place::Joint || n.place == Place::HeadBase ||
         (n.place == Place::Toe && o.toesMm);
}

// [SECTION] Rest pose

// OFFSET of each node: its rest direction times the mean measured bone length; end sites
// without a measurement get a plausible length (hand 0.74 forearm, toes 0.45 shank:
// Winter 2009 proportions; the head's twice the Neck→Head bone, so that the mapper's
// head centre, the middle of Head and its End Site, is our head joint).
std::vector<Eigen::Vector3d> restOffsets(const Eigen::MatrixXd& frames, const BvhWriteOptions& o) {
  const auto& nodes = skeleton();
  std::vector<double> length(nodes.size(), 0.0);
  for (int f = 0; f < frames.rows(); ++f) {
    const auto p = placeNodes(frames, f, o);
    for (size_t k = 1; k < nodes.size(); ++k) {
      if (measured(nodes[k], o))
        length[k] += (p[k] - p[static_cast<size_t>(nodes[k].parent)]).norm();
    }
  }
  for (double& l : length) l /= static_cast<double>(frames.rows());
  length[13] = 2.0 * length[12];  // Head and its End Site average to the head centre
  length[18] = 0.74 * length[17];
  length[23] = 0.74 * length[22];
  if (!o.toesMm) length[4] = 0.45 * length[3], length[8] = 0.45 * length[7];
  std::vector<Eigen::Vector3d> offsets(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) offsets[k] = length[k] * nodes[k].restDirection;
  double hipHeight = 0.0;  // the root stands at the walker's mean pelvis height
  for (int f = 0; f < frames.rows(); ++f) hipHeight += jointInBvh(frames, f, Joint::Pelvis).y();
  offsets[0] = Eigen::Vector3d(0, hipHeight / static_cast<double>(frames.rows()), 0);
  return offsets;
}

// [SECTION] Rotations

// The hips' frame: x along the pelvis's left→right axis, y towards the sternum (made
// orthogonal), z = x × y. The rest pose's frame is the identity.
Eigen::Matrix3d hipsRotation(const Eigen::MatrixXd& frames, int f) {
  const Eigen::Vector3d x =
      (jointInBvh(frames, f, Joint::RHip) - jointInBvh(frames, f, Joint::LHip)).normalized();
  const Eigen::Vector3d up =
      jointInBvh(frames, f, Joint::Sternum) - jointInBvh(frames, f, Joint::Pelvis);
  const Eigen::Vector3d y = (up - up.dot(x) * x).normalized();
  Eigen::Matrix3d r;
  r << x, y, x.cross(y);
  return r;
}

// Global rotation of each node for one frame: the shortest arc that turns the node's
// (single) measured, non-zero child onto its measured direction, applied on top of the
// parent's rotation; a node without one keeps its parent's rotation.
std::vector<Eigen::Matrix3d> globalRotations(const Eigen::MatrixXd& frames, int f,
                                             const std::vector<Eigen::Vector3d>& offsets,
                                             const BvhWriteOptions& o) {
  const auto& nodes = skeleton();
  const auto p = placeNodes(frames, f, o);
  std::vector<Eigen::Matrix3d> g(nodes.size());
  g[0] = hipsRotation(frames, f);
  for (size_t k = 1; k < nodes.size(); ++k) {
    const Eigen::Matrix3d& parent = g[static_cast<size_t>(nodes[k].parent)];
    g[k] = parent;
    if (nodes[k].name == nullptr) continue;
    for (size_t c = k + 1; c < nodes.size(); ++c) {
      if (nodes[c].parent != static_cast<int>(k) || !measured(nodes[c], o) || offsets[c].isZero())
        continue;
      const Eigen::Vector3d from = parent * offsets[c];
      const Eigen::Vector3d to = p[c] - p[k];
      g[k] = Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix() * parent;
      break;
    }
  }
  return g;
}

// R = Rz(a)·Rx(b)·Ry(c) → (a, b, c) in degrees, b in [−90°, 90°].
Eigen::Vector3d eulerZxyDeg(const Eigen::Matrix3d& r) {
  const double b = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  const double c = std::atan2(-r(2, 0), r(2, 2));
  const double a = std::atan2(-r(0, 1), r(1, 1));
  return Eigen::Vector3d(a, b, c) * (180.0 / std::numbers::pi);
}

// Adds whole turns to a and c so they stay within 180° of the previous frame's values
// (the same rotation; smooth curves in animation editors).
void unwrapLike(Eigen::Vector3d& angles, const Eigen::Vector3d& previous) {
  for (int i : {0, 2}) angles[i] += 360.0 * std::round((previous[i] - angles[i]) / 360.0);
}

// [SECTION] Text

void appendf(std::string& out, const char* format, double a, double b, double c, int decimals) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, decimals, a, decimals, b, decimals, c);
  out += buffer;
}

void writeHierarchy(std::string& out, size_t k, const std::vector<Eigen::Vector3d>& offsets,
                    int depth) {
  const auto& nodes = skeleton();
  const std::string indent(static_cast<size_t>(2 * depth), ' ');
  const Node& n = nodes[k];
  if (n.parent < 0)
    out += "ROOT " + std::string(n.name) + "\n";
  else if (n.name != nullptr)
    out += indent + "JOINT " + n.name + "\n";
  else
    out += indent + "End Site\n";
  out += indent + "{\n";
  appendf(out, (indent + "  OFFSET %.*f %.*f %.*f\n").c_str(), offsets[k].x(), offsets[k].y(),
          offsets[k].z(), 6);
  if (n.parent < 0) {
    out += indent + "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  } else if (n.name != nullptr) {
    out += indent + "  CHANNELS 3 Zrotation Xrotation Yrotation\n";
  }
  for (size_t c = k + 1; c < nodes.size(); ++c) {
    if (nodes[c].parent == static_cast<int>(k)) writeHierarchy(out, c, offsets, depth + 1);
  }
  out += indent + "}\n";
}

void checkInput(const Eigen::MatrixXd& frames, double rateHz, const BvhWriteOptions& o) {
  auto bad = [](const std::string& what) { throw Error(ErrorKind::BadArgument, "", "", what); };
  if (frames.cols() != kDims3)
    bad("BVH writer: expected 45 joint columns, got " + std::to_string(frames.cols()));
  if (frames.rows() < 1) bad("BVH writer: no frames");
  if (!(rateHz > 0) || !std::isfinite(rateHz)) bad("BVH writer: frame rate must be > 0");
  if (!frames.allFinite()) bad("BVH writer: joint positions must be finite (no gaps)");
  if (o.toesMm &&
      (o.toesMm->rows() != frames.rows() || o.toesMm->cols() != 6 || !o.toesMm->allFinite())) {
    bad("BVH writer: toes must be finite, frames x 6");
  }
}

}  // namespace

std::string formatBvh(const Eigen::MatrixXd& frames, double rateHz, const BvhWriteOptions& o) {
  checkInput(frames, rateHz, o);
  const auto& nodes = skeleton();
  const std::vector<Eigen::Vector3d> offsets = restOffsets(frames, o);
  std::string out = "HIERARCHY\n";
  writeHierarchy(out, 0, offsets, 0);
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "MOTION\nFrames: %d\nFrame Time: %.10g\n",
                static_cast<int>(frames.rows()), 1.0 / rateHz);
  out += buffer;
  std::vector<Eigen::Vector3d> previous(nodes.size(), Eigen::Vector3d::Zero());
  for (int f = 0; f < frames.rows(); ++f) {
    const auto g = globalRotations(frames, f, offsets, o);
    const Eigen::Vector3d root = jointInBvh(frames, f, Joint::Pelvis);
    appendf(out, "%.*f %.*f %.*f", root.x(), root.y(), root.z(), o.decimals);
    for (size_t k = 0; k < nodes.size(); ++k) {
      if (nodes[k].name == nullptr) continue;
      const Eigen::Matrix3d local =
          nodes[k].parent < 0
              ? g[k]
              : Eigen::Matrix3d(g[static_cast<size_t>(nodes[k].parent)].transpose() * g[k]);
      Eigen::Vector3d angles = eulerZxyDeg(local);
      if (f > 0) unwrapLike(angles, previous[k]);
      previous[k] = angles;
      appendf(out, " %.*f %.*f %.*f", angles[0], angles[1], angles[2], o.decimals);
    }
    out += "\n";
  }
  return out;
}

void writeBvh(const std::filesystem::path& file, const Eigen::MatrixXd& frames, double rateHz,
              const BvhWriteOptions& options) {
  const std::string text = formatBvh(frames, rateHz, options);
  writeFileAtomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace ew
