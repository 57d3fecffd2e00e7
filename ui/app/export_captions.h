#pragma once
// Captions burnt into an exported video's frames (issue 14): each view's title and subtitle at
// the top of its half, the metrics strip's values under the 3D view's, and each view's legend
// at the bottom of its half. The words are the viewer's (ui/panels/view_captions.h,
// metric_items.h), in its font (DejaVu Sans, through OpenCV's FreeType module), so the video
// reads as the screen does.

#include <opencv2/core.hpp>
#include <opencv2/freetype.hpp>
#include <string>
#include <vector>

#include "ui/panels/metric_items.h"
#include "ui/panels/view_captions.h"

namespace ew::ui {

class CaptionPainter {
 public:
  // Throws std::runtime_error naming the font when DejaVu Sans is not installed
  // (fonts-dejavu-core).
  CaptionPainter();

  // Onto `half` (8-bit BGR, one view): `caption` and, under its subtitle, `metrics`. Text and
  // plates scale with the half's height (the viewer's sizes at 720 px).
  void paint(cv::Mat& half, const ViewCaption& caption, const std::vector<MetricItem>& metrics) const;

 private:
  cv::Ptr<cv::freetype::FreeType2> regular_, bold_;
};

}  // namespace ew::ui
