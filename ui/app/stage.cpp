#include "ui/app/stage.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "core/eigenwalker/projection.h"

namespace ew::ui {

bool StageFeature::shown() const {
  return display.inverted || display.scramble != Scramble::None || display.maskDots > 0 ||
         display.dotLifetimeS > 0.0 || display.backwards || display.translating || depthReversed || turning ||
         turnedDeg != 0.0 || elevationDeg != 0.0;
}

namespace {

// x wrapped into [−period/2, period/2).
double wrappedAbout(double x, double period) { return x - period * std::floor(x / period + 0.5); }

}  // namespace

StageDots stageDots(const StageFeature& stage, const Eigen::VectorXd& w, double strideHz, double cycles,
                    double speedMmS, double alphaDeg) {
  BiologicalMotionOptions options = stage.display;
  options.translating = false;  // applied below, wrapped, so that the walker comes back
  const BiologicalMotionDisplay display(w, 2.0 * std::numbers::pi * strideHz, 0.0, options);
  const DisplayDots dots = display.at(cycles / strideHz);
  StageDots out;
  out.walker = dots.walkerMm;
  out.noise = dots.noiseMm;
  out.keepsForm = displayKeepsTheForm(options);
  if (stage.display.translating) {
    const double sign = options.backwards ? -1.0 : 1.0;
    out.walker.row(1).array() += wrappedAbout(sign * speedMmS * cycles / strideHz, kStageWrapMm);
  }
  if (stage.depthReversed) {
    // The walker's own dots mirrored in depth (core's reflection, on the dots as one row).
    const Eigen::MatrixXd row = Eigen::Map<const Eigen::MatrixXd>(out.walker.data(), 1, out.walker.size());
    const Eigen::MatrixXd mirrored = depthReversedFrames(row, alphaDeg);
    out.reversed = Eigen::Map<const Eigen::Matrix3Xd>(mirrored.data(), 3, out.walker.cols());
  }
  return out;
}

Eigen::Matrix2Xd stageProjection(const Eigen::Matrix3Xd& p, double azimuthDeg, double elevationDeg) {
  const double a = degToRad(azimuthDeg), e = degToRad(elevationDeg);
  Eigen::Matrix2Xd uv(2, p.cols());
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    const double depth = -p(0, i) * std::sin(a) + p(1, i) * std::cos(a);
    uv(0, i) = p(0, i) * std::cos(a) + p(1, i) * std::sin(a);
    uv(1, i) = p(2, i) * std::cos(e) + depth * std::sin(e);
  }
  return uv;
}

Eigen::Vector3d depthReversedOffset(double alphaDeg) {
  const double a = degToRad(alphaDeg);
  return kDepthReversedApartMm * Eigen::Vector3d(-std::sin(a), std::cos(a), 0.0);
}

double turnedAfter(const StageFeature& stage, double seconds) {
  if (!stage.turning) return stage.turnedDeg;
  double a = std::fmod(stage.turnedDeg + stage.turnDegPerS * seconds, 360.0);
  if (a > 180.0) a -= 360.0;
  if (a <= -180.0) a += 360.0;
  return a;
}

std::string stageDescription(const StageFeature& stage) {
  const BiologicalMotionOptions& d = stage.display;
  std::string out;
  const auto add = [&](const std::string& part) { out += (out.empty() ? "" : " · ") + part; };
  if (d.inverted) add("inverted");
  if (d.scramble != Scramble::None) add(std::string(scrambleName(d.scramble)) + "-scrambled");
  if (d.dotLifetimeS > 0.0) {
    char text[64];
    std::snprintf(text, sizeof text, "%d dots living %.2f s", d.lifetimeDots, d.dotLifetimeS);
    add(text);
  }
  if (d.maskDots > 0) add(std::to_string(d.maskDots) + " noise dots");
  if (d.backwards) add("walking backwards");
  if (d.translating) add("overground");
  if (stage.depthReversed) add("depth-reversed beside");
  if (stage.turning) {
    char text[64];
    std::snprintf(text, sizeof text, "turning %.0f°/s", stage.turnDegPerS);
    add(text);
  }
  if (stage.elevationDeg != 0.0) {
    char text[64];
    std::snprintf(text, sizeof text, "elevation %.0f°", stage.elevationDeg);
    add(text);
  }
  return out;
}

const char* scrambleName(Scramble s) {
  switch (s) {
    case Scramble::Phase: return "phase";
    case Scramble::Position: return "position";
    case Scramble::None: break;
  }
  return "none";
}

Scramble scrambleFromName(const std::string& name) {
  if (name == "none") return Scramble::None;
  if (name == "phase") return Scramble::Phase;
  if (name == "position") return Scramble::Position;
  throw std::invalid_argument("scramble is \"none\", \"phase\" or \"position\", not \"" + name + "\"");
}

}  // namespace ew::ui
