#pragma once
// Joint angles of a 15-joint skeleton over a whole sequence (Zou et al. 2009, §5.1: a
// rotation per joint, from its parent segment's frame to its own, as Euler angles).
//
// Segment frames are right-handed, X forward, Y up along the segment (distal → proximal),
// Z to the walker's right, as OpenSim's models have them:
// - ground: Y the given up, X the clip's mean pelvis forward made horizontal;
// - pelvis: Z along the hip line, Y the trunk (pelvis → sternum) made perpendicular to it
//   — the 15 joints put no pelvic landmark off the hip line, so the pelvis's up is the
//   trunk's and "pelvis tilt" is the trunk's lean; thorax: Z along the shoulder line, Y the trunk;
// - thigh and shank: Y along the segment, Z the knee's hinge axis (thigh × shank, pointing
//   right); upper arm and forearm likewise with the elbow's hinge; head: Y sternum → head,
//   Z the thorax's. A straight limb has no hinge: below 20° of flexion the hinge is blended
//   into the parent's Z (fully at 5°), so the long-axis rotation (hip and arm rotation)
//   is measured where the limb is bent and the parent's otherwise.
//
// Each joint's rotation parent → child is split as Z, then X, then Y (the Cardan sequence of
// OpenSim's hip, pelvis and lumbar joints and of ISB's hip): flexion, adduction, rotation.
// The paper's eq. 7–10 (Z–Y–X with no twist) give a segment's direction alone; the twist
// here comes from the next joint's hinge. Signs: flexion positive forward at hip and
// shoulder and positive bending at knee and elbow; adduction (towards the midline) and
// internal rotation positive on both sides; pelvis tilt, list and rotation are OpenSim's
// (tilt positive backward, rotation positive turning left). The ankle has no angle from the 15
// joints alone (no foot point); where the input has the feet's heel and toe (JointTrial::feetMm),
// jointAnglesWithFeet adds it and the foot progression angle.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ew {

struct JointAngles {
  std::vector<std::string> names;  // OpenSim coordinate names (hip_flexion_r, knee_angle_r, …)
  Eigen::MatrixXd degrees;         // T × names.size(); NaN where a joint it needs is missing
  Eigen::MatrixXd pelvisM;         // T × 3: the pelvis in the ground frame (X forward, Y up, Z right), m
};

// The column names, in order.
const std::vector<std::string>& jointAngleNames();

// framesMm: T × 45 (METHOD §1 joint order), any right-handed frame; upMm: the ground's up in
// it (any length). Throws Error(BadArgument) naming `name` for a bad shape or a zero or
// non-finite up, and Error(BadData) when no frame has the pelvis, hips and sternum (no heading).
JointAngles jointAngles(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, const Eigen::Vector3d& upMm,
                        const std::string& name);

// The columns jointAnglesWithFeet adds: ankle_angle_r, foot_progression_r, ankle_angle_l,
// foot_progression_l.
//   ankle_angle     90° less the angle between the shank (ankle → knee) and the foot (heel → toe):
//                   0 with the shank square to the foot, dorsiflexion positive (OpenSim's sign).
//                   Heel and toe markers at one height above the sole (Plug-in Gait's HEE and
//                   TOE) read 0 standing; a detector's heel and big toe near the floor about the same.
//   foot_progression  the foot's long axis (heel → toe) in the horizontal plane against the
//                   ground frame's forward (the clip's mean heading), toe out positive on both sides
//                   (Perry & Burnfield; Baker, Measuring Walking, ch. 7).
const std::vector<std::string>& footAngleNames();

// jointAngles, then the footAngleNames() columns from feetMm (T × 12, FootPoint order, the frames'
// axes; NaN where a point is missing). An empty feetMm, or one of another shape, adds the
// columns as NaN; so does a frame missing the heel, the toe, the knee or the ankle.
JointAngles jointAnglesWithFeet(const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                                const Eigen::Ref<const Eigen::MatrixXd>& feetMm, const Eigen::Vector3d& upMm,
                                const std::string& name);

// The body's up: the mean over frames of the unit vector from the ankles' midpoint to the
// head (frames where any of the three is missing are skipped); snapped to the nearest signed
// axis when within `snapDegrees` of it (motion capture's up is an axis; 90 always snaps, METHOD
// §2's rule; 0 never). Zero when no frame has them.
Eigen::Vector3d bodyUp(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double snapDegrees = 15.0);

// Written atomically. CSV: "time_s,<names>" with `comments` as "# " lines first. .mot: OpenSim's
// storage format (name, version=1, nRows, nColumns, inDegrees=yes, endheader, then a
// tab-separated "time <names>" table). NaN is written as "nan". The format is chosen by
// the extension (.csv, .mot; anything else is Error(BadArgument)).
void writeJointAngles(const std::string& file, const JointAngles& angles, double rateHz,
                      const std::vector<std::string>& comments = {});

}  // namespace ew
