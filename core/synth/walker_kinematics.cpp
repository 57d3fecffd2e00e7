#include "core/synth/walker_kinematics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/synth/normative_gait.h"
#include "core/synth/random.h"

namespace ew {
namespace {

// [SECTION] Constants

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr int kRight = 0, kLeft = 1;
// Width of the soft minimum over the foot contact points (mm): small enough that a
// foot in contact is within ~4 mm of the floor, large enough to round the hand-over
// from one contact point to the next as real heel-to-toe roll-over does.
constexpr double kContactSoftnessMm = 3.0;
// Phases per cycle for the progression integral and the stance correction table (a
// 120 Hz, 1 Hz cycle has 120 frames; the stride changes by < 0.1 mm from 128 to 1024).
constexpr int kGridPerCycle = 128;
// The swing ankle passes this much closer to the midline than in stance (mm).
constexpr double kSwingMedialMm = 10.0;
constexpr double kToeOffPhase = 0.62;    // swing starts here (Perry & Burnfield: 60-62 %)
constexpr double kDoubleSupport = 0.12;  // initial double support (Perry & Burnfield: 0-12 %)

double side(int leg) { return leg == kRight ? 1.0 : -1.0; }
double fractional(double x) { return x - std::floor(x); }

Eigen::Matrix3d rotX(double deg) {
  return Eigen::AngleAxisd(deg * kDegToRad, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d rotY(double deg) {
  return Eigen::AngleAxisd(deg * kDegToRad, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d rotZ(double deg) {
  return Eigen::AngleAxisd(deg * kDegToRad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Soft minimum of heights (mm) and, optionally, each one's weight in it.
template <size_t N>
double softMinimum(const std::array<double, N>& z, std::array<double, N>* weights = nullptr) {
  const double lowest = *std::min_element(z.begin(), z.end());
  std::array<double, N> e{};
  double sum = 0.0;
  for (size_t k = 0; k < N; ++k) sum += (e[k] = std::exp(-(z[k] - lowest) / kContactSoftnessMm));
  if (weights != nullptr) {
    for (size_t k = 0; k < N; ++k) (*weights)[k] = e[k] / sum;
  }
  return lowest - kContactSoftnessMm * std::log(sum);
}

// [SECTION] The walker's curves

// Everything that depends on the phase, as periodic curves of the right leg's phase τ.
struct WalkerShape {
  const SynthParams* params = nullptr;
  std::array<PeriodicCurve, 2> hip, knee, ankle, shoulder, elbow;  // [right, left]
  std::array<double, 2> legShift{};                                // leg phase = τ − legShift
  PeriodicCurve pelvisYaw, pelvisObliquity, sway, trunkLean, trunkYaw, trunkBend;
  // Stance correction (see legAt): off while the hip gain and the surge are solved.
  bool stanceIk = false;
  // The correction tabulated over the cycle (kGridPerCycle + 1 values per leg, degrees),
  // then interpolated: solving it at every frame costs ten times more and changes the
  // foot's position by under 0.1 mm.
  std::array<std::vector<double>, 2> thighCorrectionDeg;
  double strideMm = 0.0;
  PeriodicCurve surge;  // pelvis fore-aft deviation from constant speed
  // Heel and ball y relative to the pelvis at mid-stance, [leg][heel, ball].
  std::array<std::array<double, 2>, 2> midStanceY{};
};

// The normative curve with its excursion about the mean scaled by `gain`, moved by
// `offset`, reshaped by the walker's 2nd-4th harmonics, and delayed by `shift` cycles.
PeriodicCurve shapedCurve(const PeriodicCurve& norm, double gain, double offset,
                          const CurveStyle& style, double shift) {
  PeriodicCurve c = norm;
  c.a0 += offset;
  for (size_t h = 0; h < c.a.size(); ++h) {
    c.a[h] *= gain;
    c.b[h] *= gain;
  }
  for (size_t k = 0; k < style.cosDeg.size() && k + 1 < c.a.size(); ++k) {
    c.a[k + 1] += style.cosDeg[k];
    c.b[k + 1] += style.sinDeg[k];
  }
  return shiftedCurve(c, shift);
}

void makeLegCurves(const SynthParams& p, WalkerShape& w) {
  const Asymmetry& asym = p.asymmetry;
  w.legShift = {0.0, 0.5 + asym.leftPhaseOffset};
  for (int leg : {kRight, kLeft}) {
    const auto i = static_cast<size_t>(leg);
    const double shift = w.legShift[i];
    const bool left = leg == kLeft;
    w.hip[i] = shapedCurve(normativeHipFlexion(), p.hipGain * (left ? asym.hipGainRatio : 1.0),
                           p.hipOffsetDeg, p.hipStyle, shift);
    w.knee[i] = shapedCurve(normativeKneeFlexion(), p.kneeGain * (left ? asym.kneeGainRatio : 1.0),
                            p.kneeOffsetDeg, p.kneeStyle, shift);
    w.ankle[i] = shapedCurve(normativeAnkleDorsiflexion(), p.ankleGain, 0.0, p.ankleStyle, shift);
  }
}

void makeArmCurves(const SynthParams& p, WalkerShape& w) {
  // Each arm swings forward with the opposite leg (peak shoulder flexion near the
  // opposite leg's contact, half a cycle after its own), lagging by armLagCycles; the
  // elbow flexes most at the end of the forward swing (Murray et al. 1967).
  for (int leg : {kRight, kLeft}) {
    const auto i = static_cast<size_t>(leg);
    const double amplitude = p.armSwingDeg * (leg == kLeft ? p.asymmetry.armSwingRatio : 1.0);
    const double peak = w.legShift[i] + 0.5 + p.armLagCycles;
    PeriodicCurve swing = cosineCurve(p.shoulderMeanDeg, amplitude, 1, peak);
    PeriodicCurve shaped = shapedCurve(swing, 1.0, 0.0, p.shoulderStyle, 0.0);
    w.shoulder[i] = shaped;
    w.elbow[i] =
        cosineCurve(p.elbowMeanDeg, p.elbowSwingDeg * amplitude / p.armSwingDeg, 1, peak + 0.03);
  }
}

void makeTrunkCurves(const SynthParams& p, WalkerShape& w) {
  // Pelvis: right side forward at right contact (transverse), left side dropping in right
  // loading response (frontal), towards the stance leg at mid-stance (lateral sway).
  w.pelvisYaw = cosineCurve(0.0, p.pelvisRotationDeg, 1, 0.0);
  w.pelvisObliquity = cosineCurve(0.0, p.pelvisObliquityDeg, 1, 0.17);
  w.sway = cosineCurve(0.0, p.lateralSwayMm, 1, 0.30);
  // Trunk: mean lean plus the pelvic tilt's double oscillation (most anterior in late
  // stance of each leg), thorax rotating against the pelvis, bending over the stance leg.
  w.trunkLean = cosineCurve(p.trunkLeanDeg, p.pelvisTiltDeg, 2, 0.45);
  w.trunkYaw = cosineCurve(0.0, -p.trunkRotationDeg, 1, 0.0);
  w.trunkBend = cosineCurve(0.0, p.trunkBendDeg, 1, 0.30);
}

WalkerShape makeShape(const SynthParams& p) {
  WalkerShape w;
  w.params = &p;
  makeLegCurves(p, w);
  makeArmCurves(p, w);
  makeTrunkCurves(p, w);
  return w;
}

// [SECTION] Pose at one phase

struct LegPoints {
  Eigen::Vector3d hip, knee, ankle, heel, ball, toe;
};

// Medial excursion of the swing ankle: 0 in stance, a smooth bump in swing.
double swingBump(double legPhase) {
  if (legPhase < kToeOffPhase) return 0.0;
  const double s = std::sin(std::numbers::pi * (legPhase - kToeOffPhase) / (1.0 - kToeOffPhase));
  return s * s;
}

// Unit vector of a limb segment at sagittal angle `sagittalDeg` from straight down
// (+ towards +y) in a plane tilted by the frontal angle (sinFrontal towards the midline
// for the leg, away from it for the arm: the sign is in `lateral`).
Eigen::Vector3d limbDirection(double sagittalDeg, double lateral, double cosFrontal) {
  const double a = sagittalDeg * kDegToRad;
  return {lateral, std::sin(a) * cosFrontal, -std::cos(a) * cosFrontal};
}

// The leg's points for given sagittal angles (degrees) and frontal tilt.
LegPoints legGeometry(const SynthParams& p, double s, const Eigen::Vector3d& hip, double sinG,
                      double thighDeg, double kneeDeg, double ankleDeg) {
  const BodyDimensions& d = p.body;
  const size_t i = s > 0 ? 0 : 1;
  const double ratio = s > 0 ? 1.0 : p.placement.leftLegRatio;
  const double cosG = std::sqrt(1.0 - sinG * sinG);
  // Valgus tilts the shank out of the thigh's plane (sin(γ − v) ≈ sin γ − v cos γ).
  const double valgus = p.placement.kneeValgusDeg[i] * kDegToRad;
  const double sinS = sinG * std::cos(valgus) - cosG * std::sin(valgus);
  const double cosS = std::sqrt(1.0 - sinS * sinS);
  const double shankDeg = thighDeg - kneeDeg;
  LegPoints out;
  out.hip = hip;
  out.knee = hip + ratio * d.thighMm * limbDirection(thighDeg, -s * sinG, cosG);
  out.ankle = out.knee + ratio * d.shankMm * limbDirection(shankDeg, -s * sinS, cosS);
  // Foot: pitch φ = shank angle + dorsiflexion (toe up +), turned out by the toe-out angle.
  const double phi = (shankDeg + ankleDeg) * kDegToRad;
  const double rho = p.toeOutDeg * kDegToRad;
  const Eigen::Vector3d f(s * std::sin(rho) * std::cos(phi), std::cos(rho) * std::cos(phi),
                          std::sin(phi));
  const Eigen::Vector3d u(-s * std::sin(rho) * std::sin(phi), -std::cos(rho) * std::sin(phi),
                          std::cos(phi));
  // Heel 25 % of the foot behind the ankle, ball (metatarsal heads) 50 % ahead, toe
  // tip 25 % beyond the ball; sole at the ankle height below the ankle centre.
  out.heel = out.ankle - 0.25 * d.footMm * f - d.ankleHeightMm * u;
  out.ball = out.ankle + 0.50 * d.footMm * f - d.ankleHeightMm * u;
  // The toes bend at the metatarsal heads: when the foot plantarflexes they stay level
  // (pitch max(φ, 0)) instead of turning into the floor.
  const double toePitch = std::max(phi, 0.0);
  const Eigen::Vector3d toeDir(s * std::sin(rho) * std::cos(toePitch),
                               std::cos(rho) * std::cos(toePitch), std::sin(toePitch));
  out.toe = out.ball + 0.25 * d.footMm * toeDir;
  return out;
}

// The stance point held still: the heel until mid-stance (heel rocker, foot flat), the
// ball after it (heel rise, push-off). Both are on the floor at mid-stance, so the
// hand-over there is continuous.
constexpr double kMidStance = 0.3;
double heldPointY(const LegPoints& l, bool ball) { return ball ? l.ball.y() : l.heel.y(); }

// Weight of the stance correction over the leg's stance: full from the end of loading
// response to the start of pre-swing, smooth ramps at contact and toe-off.
double stanceIkWeight(double legPhase) {
  auto smooth = [](double x) { return x * x * (3.0 - 2.0 * x); };
  constexpr double ramp = 0.08;
  if (legPhase >= kToeOffPhase) return 0.0;
  if (legPhase < ramp) return smooth(legPhase / ramp);
  if (legPhase > kToeOffPhase - ramp) return smooth((kToeOffPhase - legPhase) / ramp);
  return 1.0;
}

// The thigh angle that puts the held point (heel or ball) at relative fore-aft position
// `targetY` (secant iteration from the table's angle; the point moves forward
// monotonically with thigh flexion over the stance range).
double thighForContact(const SynthParams& p, double s, const Eigen::Vector3d& hip, double sinG,
                       double thighDeg, double kneeDeg, double ankleDeg, bool ball,
                       double targetY) {
  auto residual = [&](double t) {
    return heldPointY(legGeometry(p, s, hip, sinG, t, kneeDeg, ankleDeg), ball) - targetY;
  };
  double t0 = thighDeg, r0 = residual(t0);
  double t1 = thighDeg + 1.0, r1 = residual(t1);
  for (int it = 0; it < 12 && std::abs(r1) > 1e-4 && r1 != r0; ++it) {
    const double t2 = std::clamp(t1 - r1 * (t1 - t0) / (r1 - r0), thighDeg - 25.0, thighDeg + 25.0);
    t0 = t1, r0 = r1;
    t1 = t2, r1 = residual(t1);
  }
  return t1;
}

// Normative curves are means over people and trials: fed as they are into one rigid
// chain they let the planted foot drift by several centimetres. In stance the thigh is
// therefore re-solved so the contact point stays where it was at mid-stance while the
// pelvis moves on (constant speed + surge), blended back to the curve at contact and
// toe-off (docs/SYNTHETIC.md, "Stance").
LegPoints legAt(const WalkerShape& w, int leg, const HarmonicBasis& basis, double tau,
                const Eigen::Vector3d& pelvis, const Eigen::Matrix3d& pelvisR) {
  const SynthParams& p = *w.params;
  const BodyDimensions& d = p.body;
  const auto i = static_cast<size_t>(leg);
  const double s = side(leg);
  const Eigen::Vector3d hip = pelvis + pelvisR * Eigen::Vector3d(s * 0.5 * d.hipWidthMm, 0.0, 0.0);
  // Frontal angle of the whole leg that puts the ankle on its line of progression.
  const double legPhase = fractional(tau - w.legShift[i]);
  const double ankleX = s * (0.5 * p.stepWidthMm - kSwingMedialMm * swingBump(legPhase));
  const double sinG = std::clamp(s * (hip.x() - ankleX) / (d.thighMm + d.shankMm), -0.5, 0.5);
  double thighDeg = w.hip[i](basis);
  const double kneeDeg = w.knee[i](basis), ankleDeg = w.ankle[i](basis);
  const double ik = w.stanceIk ? stanceIkWeight(legPhase) : 0.0;
  if (ik > 0.0 && !w.thighCorrectionDeg[i].empty()) {
    const double x = legPhase * kGridPerCycle;
    const auto k = std::min(static_cast<size_t>(x), static_cast<size_t>(kGridPerCycle - 1));
    const double t = x - static_cast<double>(k);
    thighDeg += (1.0 - t) * w.thighCorrectionDeg[i][k] + t * w.thighCorrectionDeg[i][k + 1];
  } else if (ik > 0.0) {
    const double tauMid = tau - (legPhase - kMidStance);
    const double pelvisAdvance =
        w.strideMm * (legPhase - kMidStance) + w.surge(tau) - w.surge(tauMid);
    const bool ball = legPhase >= kMidStance;
    const double target = w.midStanceY[i][ball ? 1 : 0] - pelvisAdvance;
    const double solved =
        thighForContact(p, s, hip, sinG, thighDeg, kneeDeg, ankleDeg, ball, target);
    thighDeg += ik * (solved - thighDeg);
  }
  return legGeometry(p, s, hip, sinG, thighDeg, kneeDeg, ankleDeg);
}

struct Pose {
  std::array<Eigen::Vector3d, kJointCount> joints;
  std::array<Eigen::Vector3d, 2> toes;      // [right, left]
  std::array<Eigen::Vector3d, 4> contacts;  // heel R, ball R, heel L, ball L
};

void placeUpperBody(const WalkerShape& w, const HarmonicBasis& basis, Pose& pose) {
  const SynthParams& p = *w.params;
  const BodyDimensions& d = p.body;
  const Eigen::Vector3d& pelvis = pose.joints[index(Joint::Pelvis)];
  const double yaw = w.trunkYaw(basis), lean = w.trunkLean(basis);
  const Eigen::Matrix3d trunkR = rotZ(yaw) * rotY(w.trunkBend(basis)) * rotX(-lean);
  const Eigen::Vector3d sternum = pelvis + trunkR * Eigen::Vector3d(0.0, 0.0, d.trunkMm);
  pose.joints[index(Joint::Sternum)] = sternum;
  // The head is stabilised in space: it follows half the thorax's rotation and lean.
  // Its centre sits slightly behind the jugular notch (over the cervical spine).
  const auto& h = p.placement.headMm;
  const Eigen::Vector3d headOffset = Eigen::Vector3d(
      h[0], h[1] - 0.15 * d.neckHeadMm, h[2] + std::sqrt(1.0 - 0.15 * 0.15) * d.neckHeadMm);
  pose.joints[index(Joint::Head)] = sternum + rotZ(0.5 * yaw) * rotX(-0.5 * lean) * headOffset;
  const Joint shoulders[2] = {Joint::RShoulder, Joint::LShoulder};
  const Joint elbows[2] = {Joint::RElbow, Joint::LElbow};
  const Joint wrists[2] = {Joint::RWrist, Joint::LWrist};
  for (int arm : {kRight, kLeft}) {
    const auto i = static_cast<size_t>(arm);
    const double s = side(arm);
    const auto& o = p.placement.shoulderMm[i];
    const Eigen::Vector3d shoulder =
        sternum + trunkR * Eigen::Vector3d(s * (0.5 * d.shoulderWidthMm + o[0]),
                                           o[1] - d.shoulderBackMm, o[2] - d.shoulderDropMm);
    const double abduction = std::sin(p.armAbductionDeg * kDegToRad);
    const double cosA = std::cos(p.armAbductionDeg * kDegToRad);
    const double upperDeg = w.shoulder[i](basis);
    const Eigen::Vector3d elbow =
        shoulder + d.upperArmMm * (trunkR * limbDirection(upperDeg, s * abduction, cosA));
    const double foreDeg = upperDeg + w.elbow[i](basis);
    const double carrying = (p.armAbductionDeg + p.placement.carryingAngleDeg[i]) * kDegToRad;
    const Eigen::Vector3d wrist =
        elbow +
        d.forearmMm * (trunkR * limbDirection(foreDeg, s * std::sin(carrying), std::cos(carrying)));
    pose.joints[index(shoulders[i])] = shoulder;
    pose.joints[index(elbows[i])] = elbow;
    pose.joints[index(wrists[i])] = wrist;
  }
}

// The pose with the pelvis at (sway, 0, 0): x absolute, y and z relative to the pelvis.
Pose relativePose(const WalkerShape& w, double tau, bool withUpperBody) {
  const HarmonicBasis basis(tau);
  Pose pose;
  const Eigen::Vector3d pelvis(w.sway(basis), 0.0, 0.0);
  const Eigen::Matrix3d pelvisR = rotZ(w.pelvisYaw(basis)) * rotY(-w.pelvisObliquity(basis));
  pose.joints[index(Joint::Pelvis)] = pelvis;
  const Joint hips[2] = {Joint::RHip, Joint::LHip};
  const Joint knees[2] = {Joint::RKnee, Joint::LKnee};
  const Joint ankles[2] = {Joint::RAnkle, Joint::LAnkle};
  for (int leg : {kRight, kLeft}) {
    const auto i = static_cast<size_t>(leg);
    const LegPoints l = legAt(w, leg, basis, tau, pelvis, pelvisR);
    pose.joints[index(hips[i])] = l.hip;
    pose.joints[index(knees[i])] = l.knee;
    pose.joints[index(ankles[i])] = l.ankle;
    pose.toes[i] = l.toe;
    pose.contacts[2 * i] = l.heel;
    pose.contacts[2 * i + 1] = l.ball;
  }
  if (withUpperBody) placeUpperBody(w, basis, pose);
  return pose;
}

// Support by phase: a leg bears weight from its contact (leg phase 0) to toe-off; the
// load passes from the trailing to the leading foot over double support (0-12 %).
double stanceWeight(double legPhase) {
  auto smooth = [](double x) { return x * x * (3.0 - 2.0 * x); };
  if (legPhase < kDoubleSupport) return smooth(legPhase / kDoubleSupport);
  if (legPhase < 0.5) return 1.0;
  if (legPhase < kToeOffPhase) return 1.0 - smooth((legPhase - 0.5) / kDoubleSupport);
  return 0.0;
}

// How each contact point (heel R, ball R, heel L, ball L) carries the body at phase τ:
// stance weight of its leg × its share of that foot's lowest point.
std::array<double, 4> supportWeights(const WalkerShape& w, const Pose& pose, double tau) {
  std::array<double, 4> out{};
  double total = 0.0;
  for (size_t leg = 0; leg < 2; ++leg) {
    std::array<double, 2> footShare{};
    softMinimum<2>({pose.contacts[2 * leg].z(), pose.contacts[2 * leg + 1].z()}, &footShare);
    const double stance = stanceWeight(fractional(tau - w.legShift[leg]));
    for (size_t k = 0; k < 2; ++k) total += (out[2 * leg + k] = stance * footShare[k]);
  }
  for (double& x : out) x /= total;
  return out;
}

// Height of the pelvis: the supporting contact points on the floor, raised further if
// a point of either foot would be below it (so nothing passes through the floor; the
// clearance check in solveWalker keeps swing feet above it, so this rarely acts).
double pelvisHeight(const WalkerShape& w, const Pose& pose, double tau) {
  const std::array<double, 4> support = supportWeights(w, pose, tau);
  double supported = 0.0;
  std::array<double, 4> heights{};
  for (size_t k = 0; k < 4; ++k) {
    supported += support[k] * pose.contacts[k].z();
    heights[k] = pose.contacts[k].z();
  }
  const double lowest = *std::min_element(heights.begin(), heights.end());
  return -std::min(supported, lowest);
}

// [SECTION] Progression

struct CycleProgression {
  double strideMm = 0.0;  // pelvis advance per cycle with the supporting feet planted
  PeriodicCurve surge;    // periodic fore-aft deviation from constant speed (mm)
};

// No-slip condition on the supporting contact points: ẏ_pelvis = −Σ_i w_i ẏ_i (relative
// velocities), integrated over one cycle on a grid. Its mean gives the stride; its
// periodic part the shape of the pelvis surge (1st and 2nd harmonics), rescaled to the
// walker's surge amplitude (docs/SYNTHETIC.md explains why the amplitude is not taken
// from the legs as is).
CycleProgression progressionOverCycle(const WalkerShape& w) {
  constexpr int n = kGridPerCycle;
  std::vector<std::array<double, 4>> contactY(n), weights(n);
  for (int k = 0; k < n; ++k) {
    const double tau = static_cast<double>(k) / n;
    const Pose pose = relativePose(w, tau, false);
    weights[static_cast<size_t>(k)] = supportWeights(w, pose, tau);
    for (size_t c = 0; c < 4; ++c) contactY[static_cast<size_t>(k)][c] = pose.contacts[c].y();
  }
  std::vector<double> velocity(n);  // dy_pelvis / dτ
  for (int k = 0; k < n; ++k) {
    const auto& next = contactY[static_cast<size_t>((k + 1) % n)];
    const auto& prev = contactY[static_cast<size_t>((k + n - 1) % n)];
    double v = 0.0;
    for (size_t c = 0; c < 4; ++c)
      v -= weights[static_cast<size_t>(k)][c] * (next[c] - prev[c]) * 0.5 * n;
    velocity[static_cast<size_t>(k)] = v;
  }
  std::vector<double> y(n + 1, 0.0);
  for (int k = 0; k < n; ++k) {
    const auto i = static_cast<size_t>(k);
    y[i + 1] = y[i] + 0.5 * (velocity[i] + velocity[(i + 1) % n]) / n;
  }
  CycleProgression out;
  out.strideMm = y.back();
  std::vector<double> deviation(n);
  for (int k = 0; k < n; ++k) {
    deviation[static_cast<size_t>(k)] = y[static_cast<size_t>(k)] - out.strideMm * k / n;
  }
  out.surge = periodicCurveFromSamples(deviation, 2);
  out.surge.a0 = 0.0;
  double lo = 0.0, hi = 0.0;
  for (int k = 0; k < 64; ++k) {
    const double v = out.surge(k / 64.0);
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  const double scale = hi > lo ? w.params->pelvisSurgeMm / (hi - lo) : 0.0;
  for (size_t h = 0; h < out.surge.a.size(); ++h) out.surge.a[h] *= scale, out.surge.b[h] *= scale;
  return out;
}

// Switches on the stance correction: the pelvis moves at stride × f plus the surge, and
// each foot's contact stays where the curves put it at mid-stance.
void enableStanceIk(WalkerShape& w, const CycleProgression& progression) {
  for (size_t leg = 0; leg < 2; ++leg) {
    const Pose pose = relativePose(w, fractional(w.legShift[leg] + kMidStance), false);
    w.midStanceY[leg] = {pose.contacts[2 * leg].y(), pose.contacts[2 * leg + 1].y()};
  }
  w.strideMm = progression.strideMm;
  w.surge = progression.surge;
  w.stanceIk = true;
  // Tabulate the correction over each leg's own phase.
  std::array<std::vector<double>, 2> table;
  for (size_t leg = 0; leg < 2; ++leg) {
    table[leg].resize(kGridPerCycle + 1);
    for (int k = 0; k <= kGridPerCycle; ++k) {
      const double legPhase = static_cast<double>(k) / kGridPerCycle;
      const double tau = fractional(legPhase + w.legShift[leg]);
      const HarmonicBasis basis(tau);
      const Pose exact = relativePose(w, tau, false);
      const Eigen::Vector3d thigh = exact.joints[index(leg == 0 ? Joint::RKnee : Joint::LKnee)] -
                                    exact.joints[index(leg == 0 ? Joint::RHip : Joint::LHip)];
      // Sagittal angle of the thigh from straight down, as limbDirection defines it.
      const double solved = std::atan2(thigh.y(), -thigh.z()) / kDegToRad;
      table[leg][static_cast<size_t>(k)] = solved - w.hip[leg](basis);
    }
  }
  w.thighCorrectionDeg = table;
}

// [SECTION] Sampling

// Start time of each cycle (s), durations varying by strideTimeCv around the mean.
std::vector<double> cycleStarts(const SynthParams& p, int cycles, Rng& rng) {
  const double mean = 1.0 / p.strideHz();
  std::vector<double> starts = {0.0};
  for (int k = 0; k < cycles; ++k) {
    const double z = std::clamp(rng.normal(), -3.0, 3.0);
    starts.push_back(starts.back() + mean * (1.0 + p.strideTimeCv * z));
  }
  return starts;
}

}  // namespace

double strideLengthFromLegs(const SynthParams& params) {
  const WalkerShape w = makeShape(params);
  return progressionOverCycle(w).strideMm;
}

double solveHipGain(const SynthParams& params) {
  SynthParams p = params;
  auto residual = [&](double gain) {
    p.hipGain = gain;
    return strideLengthFromLegs(p) - params.strideLengthMm;
  };
  // The stride grows monotonically with the hip excursion in this range: secant steps.
  double g0 = 1.0, r0 = residual(g0);
  double g1 = 1.15, r1 = residual(g1);
  for (int it = 0; it < 30 && std::abs(r1) > 0.1 && r1 != r0; ++it) {
    const double g2 = std::clamp(g1 - r1 * (g1 - g0) / (r1 - r0), 0.3, 2.5);
    g0 = g1, r0 = r1;
    g1 = g2, r1 = residual(g1);
  }
  return std::abs(r1) <= std::abs(r0) ? g1 : g0;
}

SynthTrajectories simulateWalker(const SynthParams& params, const SimulationOptions& options,
                                 std::uint64_t seed) {
  WalkerShape w = makeShape(params);
  const CycleProgression progression = progressionOverCycle(w);
  enableStanceIk(w, progression);
  const double stride = progression.strideMm;
  Rng rng(seed);
  SynthTrajectories out;
  out.rateHz = options.rateHz;
  out.strideLengthMm = stride;
  out.startPhase = rng.uniform();
  const double meanCycleS = 1.0 / params.strideHz();
  const int frames =
      std::max(2, static_cast<int>(std::lround(options.cycles * meanCycleS * options.rateHz)));
  const std::vector<double> starts =
      cycleStarts(params, static_cast<int>(std::ceil(options.cycles)) + 2, rng);
  // Mean over the cycles the trial overlaps (it starts inside cycle 0).
  const size_t covered =
      std::min(starts.size() - 1, static_cast<size_t>(std::ceil(options.cycles)) + 1);
  out.strideHz = static_cast<double>(covered) / starts[covered];
  out.jointsMm.resize(frames, kDims3);
  out.toesMm.resize(frames, 6);
  const double t0 = out.startPhase * (starts[1] - starts[0]);
  const double y0 = stride * out.startPhase + progression.surge(out.startPhase);
  size_t k = 0;
  for (int f = 0; f < frames; ++f) {
    const double t = t0 + f / options.rateHz;
    while (k + 2 < starts.size() && t >= starts[k + 1]) ++k;
    const double frac = std::clamp((t - starts[k]) / (starts[k + 1] - starts[k]), 0.0, 1.0);
    const Pose pose = relativePose(w, frac, true);
    double y = stride * (static_cast<double>(k) + frac) + progression.surge(frac) - y0;
    if (options.treadmill) y -= stride * out.strideHz * (f / options.rateHz);  // the belt
    const Eigen::Vector3d shift(0.0, y, pelvisHeight(w, pose, frac));
    for (int j = 0; j < kJointCount; ++j) {
      out.jointsMm.block<1, 3>(f, 3 * j) =
          (pose.joints[static_cast<size_t>(j)] + shift).transpose();
    }
    for (size_t i = 0; i < 2; ++i)
      out.toesMm.block<1, 3>(f, 3 * static_cast<Eigen::Index>(i)) =
          (pose.toes[i] + shift).transpose();
  }
  if (options.treadmill) {
    // On a belt the walker stays about its mean position.
    const double meanY = out.jointsMm.col(3 * index(Joint::Pelvis) + 1).mean();
    for (int j = 0; j < kJointCount; ++j) out.jointsMm.col(3 * j + 1).array() -= meanY;
    for (int i = 0; i < 2; ++i) out.toesMm.col(3 * i + 1).array() -= meanY;
  }
  return out;
}

AngleSummary summarizeAngles(const SynthParams& params) {
  const WalkerShape w = makeShape(params);
  AngleSummary s;
  double hipMin = 1e9, hipMax = -1e9, ankleMin = 1e9;
  for (int k = 0; k < 200; ++k) {
    const double tau = k / 200.0;
    const HarmonicBasis basis(tau);
    const double hip = w.hip[0](basis), knee = w.knee[0](basis), ankle = w.ankle[0](basis);
    hipMin = std::min(hipMin, hip);
    hipMax = std::max(hipMax, hip);
    ankleMin = std::min(ankleMin, ankle);
    if (tau < 0.35) s.kneeLoadingPeakDeg = std::max(s.kneeLoadingPeakDeg, knee);
    if (tau >= 0.5 && tau < 0.9) s.kneePeakSwingDeg = std::max(s.kneePeakSwingDeg, knee);
  }
  s.hipRomDeg = hipMax - hipMin;
  s.anklePeakPlantarDeg = -ankleMin;
  return s;
}

}  // namespace ew
