#include "core/skeleton/bone_sources.h"

#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"

namespace ew {
namespace {

// Zou et al. 2009, Table 2, in kBones order: head–sternum (neck), sternum–pelvis (lower +
// upper torso), clavicles, upper and lower arms, hips, thighs, legs.
constexpr std::array<double, kBoneCount> kZouTable2 = {20, 54, 21, 21, 21, 24, 21, 24, 10, 10, 30, 36, 30, 36};

void checkStature(double statureMm, const std::string& what) {
  if (!(statureMm >= 500.0 && statureMm <= 2500.0))
    throw Error(ErrorKind::BadArgument, what, "", "a stature of 0.5-2.5 m is needed for bone lengths, got " +
                                                      std::to_string(statureMm / 1000.0) + " m");
}

int boneIndex(Joint a, Joint b) {
  for (int i = 0; i < kBoneCount; ++i) {
    const auto [p, c] = kBones[static_cast<std::size_t>(i)];
    if ((p == a && c == b) || (p == b && c == a)) return i;
  }
  return -1;
}

}  // namespace

double standingChainMm(const BoneLengths& bones) {
  double sum = 0;
  for (const auto& [a, b] : {std::pair{Joint::RAnkle, Joint::RKnee}, std::pair{Joint::RKnee, Joint::RHip},
                             std::pair{Joint::Pelvis, Joint::Sternum},
                             std::pair{Joint::Sternum, Joint::Head}})
    sum += bones.mm[static_cast<std::size_t>(boneIndex(a, b))];
  return sum;
}

BoneLengths scaledToStature(const BoneLengths& bones, double statureMm, const std::string& what) {
  checkStature(statureMm, what);
  const double chain = standingChainMm(bones);
  if (!(chain > 0.0 && std::isfinite(chain)))
    throw Error(ErrorKind::BadArgument, what, "", "bone lengths with no length from ankle to head");
  BoneLengths out;
  for (int i = 0; i < kBoneCount; ++i)
    out.mm[static_cast<std::size_t>(i)] =
        bones.mm[static_cast<std::size_t>(i)] * kHeadAboveAnklesPerStature * statureMm / chain;
  return out;
}

BoneLengths boneLengthsFromZouTable2(double statureMm, const std::string& what) {
  BoneLengths relative;
  relative.mm = kZouTable2;
  return scaledToStature(relative, statureMm, what);
}

BoneLengths boneLengthsFromWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS,
                                  const std::string& what) {
  if (w.size() != 225 || !w.allFinite())
    throw Error(ErrorKind::BadArgument, what, "", "a walker needs 225 finite Fourier values");
  if (!(omegaRadS > 0.0 && std::isfinite(omegaRadS)))
    throw Error(ErrorKind::BadArgument, what, "", "a walker needs a positive gait frequency");
  constexpr int kFrames = 64;
  const double rateHz = kFrames * omegaRadS / (2.0 * std::numbers::pi);
  const BoneLengths bones = boneLengthsFromFrames(synthesizeFrames(w, omegaRadS, 0.0, frameTimes(kFrames, rateHz)), what);
  for (double l : bones.mm)
    if (!(l > 0.0)) throw Error(ErrorKind::BadArgument, what, "", "the walker has a bone of length 0");
  return bones;
}

BoneLengths boneLengthsFromReferenceFrame(const Eigen::Ref<const Eigen::RowVectorXd>& frame, int referenceBone,
                                          double referenceLengthMm, const std::string& what) {
  if (frame.size() != 2 * kJointCount)
    throw Error(ErrorKind::BadArgument, what, "", "a reference frame needs 30 values (u, v per joint)");
  if (referenceBone < 0 || referenceBone >= kBoneCount)
    throw Error(ErrorKind::BadArgument, what, "", "no such reference bone");
  if (!(referenceLengthMm > 0.0 && std::isfinite(referenceLengthMm)))
    throw Error(ErrorKind::BadArgument, what, "", "the reference bone's length must be positive");
  std::array<double, kBoneCount> image{};
  for (int i = 0; i < kBoneCount; ++i) {
    const auto [a, b] = kBones[static_cast<std::size_t>(i)];
    const Eigen::Vector2d d(frame[2 * index(a)] - frame[2 * index(b)], frame[2 * index(a) + 1] - frame[2 * index(b) + 1]);
    if (!d.allFinite())
      throw Error(ErrorKind::BadData, what, "",
                  "the reference frame does not show " + std::string(jointName(a)) + "–" + std::string(jointName(b)));
    image[static_cast<std::size_t>(i)] = d.norm();
  }
  const double ref = image[static_cast<std::size_t>(referenceBone)];
  if (!(ref > 0.0)) {
    const auto [a, b] = kBones[static_cast<std::size_t>(referenceBone)];
    throw Error(ErrorKind::BadData, what, "",
                "the reference bone " + std::string(jointName(a)) + "–" + std::string(jointName(b)) +
                    " has no length in the reference frame");
  }
  BoneLengths out;
  for (int i = 0; i < kBoneCount; ++i) out.mm[static_cast<std::size_t>(i)] = image[static_cast<std::size_t>(i)] * referenceLengthMm / ref;
  return out;
}

}  // namespace ew
