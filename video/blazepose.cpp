#include "video/blazepose.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/errors.h"

namespace ew {
namespace {

// [SECTION] crops

constexpr int kDetectorInputPx = 224;
constexpr int kLandmarkInputPx = 256;
constexpr int kHeatmapPx = 64;
constexpr int kLandmarkValues = 5;  // x, y, z, visibility, presence
constexpr int kLandmarkRows = 39;   // 33 landmarks, 2 alignment points, 4 unused
constexpr double kRoiScale = 1.25;  // MediaPipe's RectTransformation around the body

double sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// The square `roi` of `bgr` warped to sizePx x sizePx: crop pixel (u, v) samples the image at
// roi.toImage((u + 0.5) / size, (v + 0.5) / size); outside the image is black.
cv::Mat cropOf(const cv::Mat& bgr, const PoseRoi& roi, int sizePx) {
  const double c = std::cos(roi.rotationRad), s = std::sin(roi.rotationRad);
  const double k = roi.sidePx / sizePx;
  // q = centre + R * ((u + 0.5) * k - side / 2, (v + 0.5) * k - side / 2)
  const double ox = 0.5 * k - 0.5 * roi.sidePx, oy = ox;
  cv::Mat cropToImage = (cv::Mat_<double>(2, 3) << c * k, -s * k, roi.centre.x + c * ox - s * oy,  //
                         s * k, c * k, roi.centre.y + s * ox + c * oy);
  cv::Mat crop;
  cv::warpAffine(bgr, crop, cropToImage, cv::Size(sizePx, sizePx), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 cv::BORDER_CONSTANT, cv::Scalar::all(0));
  return crop;
}

bool usableRoi(const PoseRoi& roi, const cv::Mat& bgr) {
  const double diagonal = std::hypot(bgr.cols, bgr.rows);
  return std::isfinite(roi.centre.x) && std::isfinite(roi.centre.y) && std::isfinite(roi.rotationRad) &&
         std::isfinite(roi.sidePx) && roi.sidePx >= 8.0 && roi.sidePx <= 4.0 * diagonal &&
         std::abs(roi.centre.x) <= 4.0 * diagonal && std::abs(roi.centre.y) <= 4.0 * diagonal;
}

cv::dnn::Net loadNet(const std::filesystem::path& onnxModel) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(onnxModel, ec))
    throw Error(ErrorKind::Io, onnxModel.string(), "", "pose model not found");
  try {
    cv::dnn::Net net = cv::dnn::readNetFromONNX(onnxModel.string());
    if (net.empty()) throw Error(ErrorKind::Malformed, onnxModel.string(), "", "OpenCV loaded an empty network");
    return net;
  } catch (const cv::Exception& e) {
    throw Error(ErrorKind::Malformed, onnxModel.string(), "", std::string("OpenCV cannot load it: ") + e.what());
  }
}

// [SECTION] the person detector's anchors and boxes

// MediaPipe's SSD anchors for the pose detector (SsdAnchorsCalculator: 5 layers at strides
// 8, 16, 32, 32, 32, fixed size): two per cell and layer, the three stride-32 layers sharing
// one 7 x 7 grid, in the order the network's 2254 outputs come.
std::vector<cv::Point2d> poseDetectorAnchors() {
  const int strides[] = {8, 16, 32, 32, 32};
  std::vector<cv::Point2d> anchors;
  for (int layer = 0; layer < 5;) {
    int perCell = 0;
    int last = layer;
    while (last < 5 && strides[last] == strides[layer]) {
      perCell += 2;
      ++last;
    }
    const int cells = (kDetectorInputPx + strides[layer] - 1) / strides[layer];
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x)
        for (int a = 0; a < perCell; ++a) anchors.emplace_back((x + 0.5) / cells, (y + 0.5) / cells);
    layer = last;
  }
  return anchors;
}

double iouOf(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double inter = (a & b).area();
  const double uni = a.area() + b.area() - inter;
  return uni > 0.0 ? inter / uni : 0.0;
}

}  // namespace

// [SECTION] ROIs

cv::Point2d PoseRoi::toImage(double u, double v) const {
  const double c = std::cos(rotationRad), s = std::sin(rotationRad);
  const double x = (u - 0.5) * sidePx, y = (v - 0.5) * sidePx;
  return {centre.x + c * x - s * y, centre.y + s * x + c * y};
}

PoseRoi roiFromAlignmentPoints(const cv::Point2d& hipCentre, const cv::Point2d& scalePoint) {
  const cv::Point2d d = scalePoint - hipCentre;
  PoseRoi roi;
  roi.centre = hipCentre;
  roi.sidePx = 2.0 * std::hypot(d.x, d.y) * kRoiScale;
  // The crop's up, (0, -1), turned by the rotation, is (sin, -cos): along d.
  roi.rotationRad = std::atan2(d.x, -d.y);
  return roi;
}

// [SECTION] the person detector

PersonDetector::PersonDetector(const std::filesystem::path& onnxModel)
    : net_(loadNet(onnxModel)), anchors_(poseDetectorAnchors()) {}

std::vector<PersonBox> PersonDetector::detect(const cv::Mat& bgr, cv::Rect region, double minScore) {
  if (bgr.empty()) return {};
  if (region.area() == 0) region = cv::Rect(0, 0, bgr.cols, bgr.rows);
  region &= cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (region.width < 2 || region.height < 2) return {};
  // The region letterboxed: the square around its centre, as MediaPipe keeps the aspect ratio.
  PoseRoi square;
  square.centre = {region.x + (region.width - 1) / 2.0, region.y + (region.height - 1) / 2.0};
  square.sidePx = std::max(region.width, region.height);
  // A tile's square is the tile; the whole frame's reaches past the image, which is black.
  const cv::Mat input = cropOf(bgr, square, kDetectorInputPx);
  net_.setInput(cv::dnn::blobFromImage(input, 1.0 / 127.5, cv::Size(), cv::Scalar::all(127.5), true, false));
  std::vector<cv::Mat> outputs;
  net_.forward(outputs, std::vector<cv::String>{"Identity", "Identity_1"});
  const cv::Mat boxes = outputs[0].reshape(1, static_cast<int>(anchors_.size()));
  const cv::Mat scores = outputs[1].reshape(1, static_cast<int>(anchors_.size()));
  std::vector<PersonBox> found;
  // Network outputs are in input pixels (224 across the square), the square's fraction (u, v)
  // at square.toImage(u, v).
  const auto toImage = [&](double u, double v) { return square.toImage(u, v); };
  for (int i = 0; i < boxes.rows; ++i) {
    const double score = sigmoid(std::clamp(static_cast<double>(scores.at<float>(i, 0)), -100.0, 100.0));
    if (!(score >= minScore)) continue;
    const float* raw = boxes.ptr<float>(i);
    const cv::Point2d& anchor = anchors_[static_cast<std::size_t>(i)];
    const double cx = raw[0] / kDetectorInputPx + anchor.x, cy = raw[1] / kDetectorInputPx + anchor.y;
    const double w = raw[2] / kDetectorInputPx, h = raw[3] / kDetectorInputPx;
    PersonBox p;
    const cv::Point2d topLeft = toImage(cx - w / 2, cy - h / 2), bottomRight = toImage(cx + w / 2, cy + h / 2);
    p.box = cv::Rect2d(topLeft, bottomRight);
    p.hipCentre = toImage(raw[4] / kDetectorInputPx + anchor.x, raw[5] / kDetectorInputPx + anchor.y);
    p.scalePoint = toImage(raw[6] / kDetectorInputPx + anchor.x, raw[7] / kDetectorInputPx + anchor.y);
    p.score = score;
    const bool finite = std::isfinite(p.box.x) && std::isfinite(p.box.y) && std::isfinite(p.box.width) &&
                        std::isfinite(p.box.height) && std::isfinite(p.hipCentre.x) && std::isfinite(p.hipCentre.y) &&
                        std::isfinite(p.scalePoint.x) && std::isfinite(p.scalePoint.y);
    if (finite && p.box.width > 0 && p.box.height > 0) found.push_back(p);
  }
  return weightedNonMaxSuppression(std::move(found));
}

std::vector<PersonBox> weightedNonMaxSuppression(std::vector<PersonBox> boxes, double iou) {
  std::sort(boxes.begin(), boxes.end(), [](const PersonBox& a, const PersonBox& b) { return a.score > b.score; });
  std::vector<PersonBox> kept;
  std::vector<bool> used(boxes.size(), false);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (used[i]) continue;
    PersonBox merged = boxes[i];
    double weight = 0.0;
    cv::Point2d tl, br, hip, scale;
    for (std::size_t j = i; j < boxes.size(); ++j) {
      if (used[j] || iouOf(boxes[i].box, boxes[j].box) <= iou) continue;
      used[j] = true;
      const double w = boxes[j].score;
      weight += w;
      tl += w * boxes[j].box.tl();
      br += w * boxes[j].box.br();
      hip += w * boxes[j].hipCentre;
      scale += w * boxes[j].scalePoint;
    }
    if (weight > 0.0) {
      merged.box = cv::Rect2d(tl / weight, br / weight);
      merged.hipCentre = hip / weight;
      merged.scalePoint = scale / weight;
    }
    kept.push_back(merged);
  }
  return kept;
}

std::vector<PersonBox> detectPeopleWithTiles(PersonDetector& detector, const cv::Mat& bgr, double minScore) {
  if (bgr.empty()) return {};
  std::vector<PersonBox> all = detector.detect(bgr, {}, minScore);
  const int shortSide = std::min(bgr.cols, bgr.rows), longSide = std::max(bgr.cols, bgr.rows);
  // Square tiles of the short side along the long one, overlapping when it does not divide.
  const int tiles = (longSide + shortSide - 1) / shortSide;
  if (tiles >= 2 && shortSide >= 32) {
    for (int t = 0; t < tiles; ++t) {
      const int start = static_cast<int>(std::lround(static_cast<double>(longSide - shortSide) * t / (tiles - 1)));
      const cv::Rect tile = bgr.cols >= bgr.rows ? cv::Rect(start, 0, shortSide, shortSide)
                                                 : cv::Rect(0, start, shortSide, shortSide);
      for (const PersonBox& p : detector.detect(bgr, tile, minScore)) all.push_back(p);
    }
  }
  return weightedNonMaxSuppression(std::move(all));
}

// [SECTION] the landmark model

LandmarkModel::LandmarkModel(const std::filesystem::path& onnxModel) : net_(loadNet(onnxModel)) {}

namespace {

// MediaPipe's RefineLandmarksFromHeatmap: a landmark moves to the mean cell of the 7 x 7
// heatmap cells around it, weighted by their sigmoid, when the largest of them is 0.5 or more.
void refineFromHeatmap(const cv::Mat& heatmap, int landmark, double& u, double& v) {
  const int centreCol = static_cast<int>(u * kHeatmapPx), centreRow = static_cast<int>(v * kHeatmapPx);
  if (!(u >= 0.0 && v >= 0.0) || centreCol >= kHeatmapPx || centreRow >= kHeatmapPx) return;
  const float* channel = heatmap.ptr<float>(0) + static_cast<std::ptrdiff_t>(landmark) * kHeatmapPx * kHeatmapPx;
  double sum = 0.0, weightedCol = 0.0, weightedRow = 0.0, maxValue = 0.0;
  for (int row = std::max(0, centreRow - 3); row < std::min(kHeatmapPx, centreRow + 4); ++row)
    for (int col = std::max(0, centreCol - 3); col < std::min(kHeatmapPx, centreCol + 4); ++col) {
      const double confidence = sigmoid(channel[row * kHeatmapPx + col]);
      sum += confidence;
      maxValue = std::max(maxValue, confidence);
      weightedCol += col * confidence;
      weightedRow += row * confidence;
    }
  if (maxValue >= 0.5 && sum > 0.0) {
    u = weightedCol / kHeatmapPx / sum;
    v = weightedRow / kHeatmapPx / sum;
  }
}

}  // namespace

PoseLandmarks LandmarkModel::detect(const cv::Mat& bgr, const PoseRoi& roi, bool refine) {
  PoseLandmarks result;
  result.roi = roi;
  if (bgr.empty() || !usableRoi(roi, bgr)) return result;  // poseScore 0: nobody
  const cv::Mat crop = cropOf(bgr, roi, kLandmarkInputPx);
  net_.setInput(cv::dnn::blobFromImage(crop, 1.0 / 255.0, cv::Size(), cv::Scalar(), true, false));
  std::vector<cv::Mat> outputs;
  net_.forward(outputs, std::vector<cv::String>{"Identity", "Identity_1", "Identity_3"});
  const float* raw = outputs[0].ptr<float>(0);
  const double flag = outputs[1].ptr<float>(0)[0];
  result.poseScore = std::isfinite(flag) ? std::clamp(flag, 0.0, 1.0) : 0.0;
  const auto fraction = [&](int row, int value) {
    return static_cast<double>(raw[row * kLandmarkValues + value]) / kLandmarkInputPx;
  };
  for (int i = 0; i < kBlazePoseLandmarks; ++i) {
    double u = fraction(i, 0), v = fraction(i, 1);
    if (refine) refineFromHeatmap(outputs[2], i, u, v);
    const cv::Point2d p = roi.toImage(u, v);
    Landmark& lm = result.points[static_cast<std::size_t>(i)];
    lm.x = p.x;
    lm.y = p.y;
    lm.z = fraction(i, 2) * roi.sidePx;
    lm.visibility = sigmoid(raw[i * kLandmarkValues + 3]);
    lm.presence = sigmoid(raw[i * kLandmarkValues + 4]);
  }
  result.hipCentre = roi.toImage(fraction(33, 0), fraction(33, 1));
  result.scalePoint = roi.toImage(fraction(34, 0), fraction(34, 1));
  static_assert(kLandmarkRows * kLandmarkValues == 195);
  return result;
}

}  // namespace ew
