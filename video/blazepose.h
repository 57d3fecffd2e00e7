#pragma once
// MediaPipe's BlazePose networks run by OpenCV's dnn module (issue 52; docs/DETECTOR.md): the
// person detector, which finds people in a whole frame, and the landmark model, which finds
// 33 body landmarks in a square crop that follows one person. Per-frame work only; following
// people through a video is pose_detector.h's.
//
// Image coordinates are pixels with (0, 0) the centre of the top-left pixel (OpenCV's and
// OpenPose's convention), y down.
#include <array>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <vector>

namespace ew {

// A square crop of the image, turned so that the person stands upright in it: its centre,
// side and rotation (radians; 0 upright, positive turns the crop's "up" towards +x).
struct PoseRoi {
  cv::Point2d centre;
  double sidePx = 0.0;
  double rotationRad = 0.0;

  // The image point of a point of the crop given as fractions of its side (0-1, y down).
  cv::Point2d toImage(double u, double v) const;
};

// The ROI MediaPipe derives from two points: the hip centre and a point whose distance from it
// is half the body's size (the detector's keypoints 0 and 1, the landmark model's alignment
// points 33 and 34): centred on the hip, turned so the second point is straight up, and 1.25
// times twice their distance on a side.
PoseRoi roiFromAlignmentPoints(const cv::Point2d& hipCentre, const cv::Point2d& scalePoint);

// One person found by the person detector.
struct PersonBox {
  cv::Rect2d box;  // the body's box in image pixels
  cv::Point2d hipCentre, scalePoint;
  double score = 0.0;  // 0-1
  PoseRoi roi() const { return roiFromAlignmentPoints(hipCentre, scalePoint); }
};

// One landmark in image pixels; z is depth relative to the hips, in the same pixel scale
// (negative towards the camera); visibility and presence are probabilities (0-1).
struct Landmark {
  double x = 0.0, y = 0.0, z = 0.0;
  double visibility = 0.0, presence = 0.0;
};

inline constexpr int kBlazePoseLandmarks = 33;

// The landmark model's answer for one crop.
struct PoseLandmarks {
  std::array<Landmark, kBlazePoseLandmarks> points;
  cv::Point2d hipCentre, scalePoint;  // the alignment points (33, 34): the next frame's ROI
  double poseScore = 0.0;             // the model's "a person is in the crop" probability
  PoseRoi roi;                        // the crop it was run on
  PoseRoi nextRoi() const { return roiFromAlignmentPoints(hipCentre, scalePoint); }
};

class PersonDetector {
 public:
  // Throws Error(Io) naming the file when it cannot be read, Error(Malformed) when OpenCV
  // cannot load it.
  explicit PersonDetector(const std::filesystem::path& onnxModel);
  // The people in `region` of `bgr` (the whole image by default), the region letterboxed to
  // the network's 224 x 224 input. Boxes scoring under minScore are dropped, the rest merged
  // by MediaPipe's weighted non-maximum suppression (IoU 0.3). An empty image or region
  // gives nobody.
  std::vector<PersonBox> detect(const cv::Mat& bgr, cv::Rect region = {}, double minScore = 0.5);

 private:
  cv::dnn::Net net_;
  std::vector<cv::Point2d> anchors_;  // centres as fractions of the input
};

// People in the whole frame and in square tiles across its long side (a person far away is
// small in a wide frame: a tile shows them at up to twice the size), merged.
std::vector<PersonBox> detectPeopleWithTiles(PersonDetector& detector, const cv::Mat& bgr, double minScore = 0.5);

// Merges overlapping boxes (IoU above `iou`) into one, weighted by their scores.
std::vector<PersonBox> weightedNonMaxSuppression(std::vector<PersonBox> boxes, double iou = 0.3);

class LandmarkModel {
 public:
  explicit LandmarkModel(const std::filesystem::path& onnxModel);
  // The landmarks in `roi` of `bgr`. Parts of the crop outside the image are black, as
  // MediaPipe pads them. refineFromHeatmap: MediaPipe's refinement of each landmark by the
  // heatmap around it (7 x 7 cells of 64 x 64).
  PoseLandmarks detect(const cv::Mat& bgr, const PoseRoi& roi, bool refineFromHeatmap = true);

 private:
  cv::dnn::Net net_;
};

}  // namespace ew
