#include "video/synthetic_footage.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/common/errors.h"
#include "core/common/skeleton.h"

namespace ew {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3d jointAt(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index f, int j) {
  return frames.row(f).segment<3>(3 * j).transpose();
}

cv::Mat noiseBackground(const FootageCamera& c, unsigned seed) {
  cv::Mat noise(c.heightPx, c.widthPx, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, cv::Scalar::all(40), cv::Scalar::all(200));
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.0);
  return noise;
}

// Right limbs warm, left limbs cool, trunk and head grey-brown (BGR).
cv::Vec3d boneColour(Joint a, Joint b) {
  const auto isLeft = [](Joint j) { return mirrorJoint(j) != j && jointName(j).front() == 'l'; };
  const auto isRight = [](Joint j) { return mirrorJoint(j) != j && jointName(j).front() == 'r'; };
  if (isRight(a) || isRight(b)) return {60, 90, 220};
  if (isLeft(a) || isLeft(b)) return {220, 140, 60};
  return {110, 150, 170};
}

// Each limb's own texture: blurred noise in the limb's axes (512 texels along × 64 across, a
// texel kTexelMm on the body), so it moves with the limb as a print or folds of clothing do, in
// both directions and without repeating (a periodic pattern would let a matcher slip by a
// period).
constexpr double kTexelMm = 7.0;

cv::Mat limbTexture(unsigned seed) {
  cv::Mat noise(64, 512, CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, cv::Scalar(0.0), cv::Scalar(1.0));
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.5);
  cv::normalize(noise, noise, 0.45, 1.0, cv::NORM_MINMAX);
  return noise;
}

// The texture between texels (bilinear), so that a limb moving by a fraction of a pixel
// changes the picture by as much.
double shadeAt(const cv::Mat& texture, double tu, double tv) {
  tu = std::clamp(tu, 0.0, texture.cols - 1.001);
  tv = std::clamp(tv, 0.0, texture.rows - 1.001);
  const int u0 = static_cast<int>(tu), v0 = static_cast<int>(tv);
  const double fu = tu - u0, fv = tv - v0;
  const auto at = [&](int v, int u) { return static_cast<double>(texture.at<float>(v, u)); };
  return (1 - fv) * ((1 - fu) * at(v0, u0) + fu * at(v0, u0 + 1)) +
         fv * ((1 - fu) * at(v0 + 1, u0) + fu * at(v0 + 1, u0 + 1));
}

// How a limb's texture lies in the picture: texels per pixel along the drawn bone (the bone's
// length on the body over its length in the picture, so a limb turned in depth shows its print
// foreshortened) and across it (the body's scale at its distance). A print on the body grows as
// the walker nears the camera; one laid in pixels would not.
struct TextureScale {
  double along = 1.0, across = 1.0;
};

// One limb as a stadium of half-width `radiusPx` from a to b, its texture laid along it from a.
void paintLimb(cv::Mat& image, cv::Point2d a, cv::Point2d b, double radiusPx, cv::Vec3d colour,
               const cv::Mat& texture, TextureScale scale) {
  const cv::Point2d d = b - a;
  const double length = std::max(1e-6, std::hypot(d.x, d.y));
  const cv::Point2d u = d / length;
  const int x0 = std::max(0, static_cast<int>(std::min(a.x, b.x) - radiusPx) - 1);
  const int x1 = std::min(image.cols - 1, static_cast<int>(std::max(a.x, b.x) + radiusPx) + 1);
  const int y0 = std::max(0, static_cast<int>(std::min(a.y, b.y) - radiusPx) - 1);
  const int y1 = std::min(image.rows - 1, static_cast<int>(std::max(a.y, b.y) + radiusPx) + 1);
  for (int y = y0; y <= y1; ++y) {
    auto* row = image.ptr<cv::Vec3b>(y);
    for (int x = x0; x <= x1; ++x) {
      const cv::Point2d p(x - a.x, y - a.y);
      const double along = p.dot(u);
      const cv::Point2d nearest = u * std::clamp(along, 0.0, length);
      if (std::hypot(p.x - nearest.x, p.y - nearest.y) > radiusPx) continue;
      const double side = p.x * u.y - p.y * u.x;  // signed distance across the limb
      const double shade =
          shadeAt(texture, 64.0 + along * scale.along, 32.0 + side * scale.across);
      for (int k = 0; k < 3; ++k) row[x][k] = cv::saturate_cast<unsigned char>(colour[k] * shade);
    }
  }
}

}  // namespace

FootageCamera cameraBeside(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double azimuthDeg,
                           double distanceMm) {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  for (Eigen::Index f = 0; f < framesMm.rows(); ++f)
    target += jointAt(framesMm, f, index(Joint::Pelvis));
  target /= static_cast<double>(std::max<Eigen::Index>(1, framesMm.rows()));
  const double a = azimuthDeg * kPi / 180.0;
  FootageCamera c;
  c.centreMm = target + Eigen::Vector3d(distanceMm * std::cos(a), -distanceMm * std::sin(a), 0.0);
  c.centreMm.z() = 1100.0;
  Eigen::Vector3d look = target - c.centreMm;
  look.z() = 0.0;
  const Eigen::Vector3d z = look.normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  c.worldToCamera.row(0) = x.transpose();
  c.worldToCamera.row(1) = z.cross(x).transpose();
  c.worldToCamera.row(2) = z.transpose();
  return c;
}

Eigen::MatrixXd filmJoints(const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                           const FootageCamera& c) {
  Eigen::MatrixXd px(framesMm.rows(), kDims2);
  for (Eigen::Index f = 0; f < framesMm.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d p = c.worldToCamera * (jointAt(framesMm, f, j) - c.centreMm);
      const bool seen = p.z() > 1.0;
      px(f, 2 * j) = seen ? c.widthPx / 2.0 + c.focalPx * p.x() / p.z()
                          : std::numeric_limits<double>::quiet_NaN();
      px(f, 2 * j + 1) = seen ? c.heightPx / 2.0 + c.focalPx * p.y() / p.z()
                              : std::numeric_limits<double>::quiet_NaN();
    }
  return px;
}

Eigen::MatrixXd writeFootage(const std::filesystem::path& file,
                             const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                             const FootageCamera& c, double fps, unsigned seed) {
  const Eigen::MatrixXd px = filmJoints(framesMm, c);
  cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                         fps, cv::Size(c.widthPx, c.heightPx));
  if (!writer.isOpened()) throw Error(ErrorKind::Io, file.string(), "", "cannot write the footage");
  writer.set(cv::VIDEOWRITER_PROP_QUALITY, 95);
  const cv::Mat background = noiseBackground(c, seed);
  std::array<cv::Mat, kBones.size() + 1> textures;
  for (std::size_t b = 0; b < textures.size(); ++b)
    textures[b] = limbTexture(seed * 31u + static_cast<unsigned>(b) + 1u);
  for (Eigen::Index f = 0; f < framesMm.rows(); ++f) {
    cv::Mat image = background.clone();
    // Far limbs first: sort the bones by the depth of their middle.
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t b = 0; b < kBones.size(); ++b) {
      const Eigen::Vector3d mid = 0.5 * (jointAt(framesMm, f, index(kBones[b].first)) +
                                         jointAt(framesMm, f, index(kBones[b].second)));
      order.emplace_back(-(c.worldToCamera * (mid - c.centreMm)).z(), b);
    }
    std::sort(order.begin(), order.end());
    const double depth =
        (c.worldToCamera * (jointAt(framesMm, f, index(Joint::Pelvis)) - c.centreMm)).z();
    const double pxPerMm = c.focalPx / std::max(depth, 1.0);
    for (const auto& [negDepth, b] : order) {
      const auto [ja, jb] = kBones[b];
      const cv::Point2d a(px(f, 2 * index(ja)), px(f, 2 * index(ja) + 1)),
          e(px(f, 2 * index(jb)), px(f, 2 * index(jb) + 1));
      if (std::isnan(a.x) || std::isnan(e.x)) continue;
      const bool trunk = ja == Joint::Sternum && jb == Joint::Pelvis;
      const double boneMm =
          (jointAt(framesMm, f, index(jb)) - jointAt(framesMm, f, index(ja))).norm();
      const double drawnPx = std::max(1e-6, std::hypot(e.x - a.x, e.y - a.y));
      paintLimb(image, a, e, (trunk ? 90.0 : 45.0) * pxPerMm, boneColour(ja, jb), textures[b],
                {boneMm / drawnPx / kTexelMm, 1.0 / (pxPerMm * kTexelMm)});
    }
    const cv::Point2d head(px(f, 0), px(f, 1));
    const double texelsPerPx = 1.0 / (pxPerMm * kTexelMm);
    if (!std::isnan(head.x))
      paintLimb(image, head, head + cv::Point2d(0.0, 1.0), 100.0 * pxPerMm, {90, 120, 140},
                textures.back(), {texelsPerPx, texelsPerPx});
    writer.write(image);
  }
  return px;
}

}  // namespace ew
