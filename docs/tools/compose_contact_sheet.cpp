// Composes screenshots into one contact sheet: each image scaled to a thumbnail of the given
// width, laid out in rows and columns, captioned. Used by layout_contact_sheet.sh; not part of
// the build.
//
//   compose_contact_sheet OUT.png THUMB_WIDTH COLUMNS TITLE (IMAGE CAPTION)...
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 7 || (argc - 5) % 2 != 0) {
    std::cerr << "usage: compose_contact_sheet OUT.png THUMB_WIDTH COLUMNS TITLE (IMAGE CAPTION)...\n";
    return 2;
  }
  const int thumbW = std::atoi(argv[2]), columns = std::atoi(argv[3]);
  if (thumbW < 64 || columns < 1) {
    std::cerr << "compose_contact_sheet: a thumbnail width of at least 64 and one column or more\n";
    return 2;
  }
  std::vector<cv::Mat> thumbs;
  std::vector<std::string> captions;
  int thumbH = 0;
  for (int i = 5; i + 1 < argc; i += 2) {
    const cv::Mat image = cv::imread(argv[i]);
    if (image.empty()) {
      std::cerr << argv[i] << ": cannot read the image\n";
      return 1;
    }
    cv::Mat thumb;
    cv::resize(image, thumb, cv::Size(thumbW, image.rows * thumbW / image.cols), 0, 0, cv::INTER_AREA);
    thumbH = std::max(thumbH, thumb.rows);
    thumbs.push_back(thumb);
    captions.push_back(argv[i + 1]);
  }
  const int captionH = 28, titleH = 44, gap = 12;
  const int rows = (static_cast<int>(thumbs.size()) + columns - 1) / columns;
  cv::Mat sheet(titleH + rows * (thumbH + captionH + gap) + gap, columns * (thumbW + gap) + gap, CV_8UC3,
                cv::Scalar(255, 255, 255));
  cv::putText(sheet, argv[4], cv::Point(gap, 30), cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  for (size_t k = 0; k < thumbs.size(); ++k) {
    const int r = static_cast<int>(k) / columns, c = static_cast<int>(k) % columns;
    const int x = gap + c * (thumbW + gap), y = titleH + r * (thumbH + captionH + gap);
    cv::putText(sheet, captions[k], cv::Point(x, y + 20), cv::FONT_HERSHEY_SIMPLEX, 0.55, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
    thumbs[k].copyTo(sheet(cv::Rect(x, y + captionH, thumbs[k].cols, thumbs[k].rows)));
    cv::rectangle(sheet, cv::Rect(x, y + captionH, thumbs[k].cols, thumbs[k].rows), cv::Scalar(160, 160, 160));
  }
  if (!cv::imwrite(argv[1], sheet)) {
    std::cerr << argv[1] << ": cannot write the sheet\n";
    return 1;
  }
  return 0;
}
