#include "ui/app/export_captions.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "ui/app/theme.h"

namespace ew::ui {
namespace {

// The viewer's caption plate and text at 720 px high (view_overlay.cpp's sizes, one scale).
constexpr double kTitlePx = 22.0, kTextPx = 15.0, kPadPx = 10.0, kLinePx = 1.35;
const cv::Scalar kPlate(30, 25, 22);  // BGR: the dark theme's plate
constexpr double kPlateAlpha = 0.78;
const cv::Scalar kTitleColour(245, 242, 240), kTextColour(200, 196, 192), kDimColour(160, 156, 152);

cv::Ptr<cv::freetype::FreeType2> fontFrom(const char* file) {
  const auto path = findFont(file);
  if (path.empty())
    throw std::runtime_error(std::string("video captions: the font ") + file +
                             " is not installed (fonts-dejavu-core)");
  auto font = cv::freetype::createFreeType2();
  font->loadFontData(path.string(), 0);
  return font;
}

cv::Scalar bgr(const glm::vec4& rgba) {
  return {255.0 * rgba.b, 255.0 * rgba.g, 255.0 * rgba.r};
}

// A dark, partly see-through plate behind text, clipped to the image.
void plate(cv::Mat& image, cv::Rect r) {
  r &= cv::Rect(0, 0, image.cols, image.rows);
  if (r.area() <= 0) return;
  cv::Mat roi = image(r);
  cv::Mat dark(roi.size(), roi.type(), kPlate);
  cv::addWeighted(dark, kPlateAlpha, roi, 1.0 - kPlateAlpha, 0.0, roi);
}

struct Line {
  std::string text;
  cv::freetype::FreeType2* font;
  int heightPx;
  cv::Scalar colour;
};

// `text` broken between words into lines no wider than `widthPx`.
std::vector<std::string> wrapped(cv::freetype::FreeType2& font, const std::string& text, int heightPx,
                                 int widthPx) {
  std::vector<std::string> lines;
  std::string line, word;
  const auto fits = [&](const std::string& t) {
    int baseline = 0;
    return font.getTextSize(t, heightPx, -1, &baseline).width <= widthPx;
  };
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != ' ') {
      word += text[i];
      continue;
    }
    const std::string joined = line.empty() ? word : line + " " + word;
    if (!line.empty() && !fits(joined)) {
      lines.push_back(line);
      line = word;
    } else {
      line = joined;
    }
    word.clear();
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

// Lines stacked from `topLeft` on one plate.
void drawLines(cv::Mat& image, cv::Point topLeft, const std::vector<Line>& lines, int pad) {
  int width = 0, height = 0;
  for (const Line& l : lines) {
    int baseline = 0;
    width = std::max(width, l.font->getTextSize(l.text, l.heightPx, -1, &baseline).width);
    height += static_cast<int>(std::lround(kLinePx * l.heightPx));
  }
  plate(image, cv::Rect(topLeft.x, topLeft.y, width + 2 * pad, height + pad));
  int y = topLeft.y + pad / 2;
  for (const Line& l : lines) {
    y += static_cast<int>(std::lround(kLinePx * l.heightPx));
    l.font->putText(image, l.text, cv::Point(topLeft.x + pad, y - l.heightPx / 4), l.heightPx, l.colour, -1,
                    cv::LINE_AA, true);
  }
}

// A metric in a line of them: its label's short form (before the strip's double space), its
// value and its note. The strip's words stay; its layout does not fit a caption.
std::string metricText(const MetricItem& m) {
  const std::string name = m.label.substr(0, m.label.find("  "));
  std::string t = name + " " + m.value;
  if (!m.note.empty()) t += " " + m.note;
  // No line breaks inside one metric: its spaces are no-break spaces (U+00A0).
  std::string kept;
  for (char ch : t) kept += ch == ' ' ? std::string("\xC2\xA0") : std::string(1, ch);
  return kept;
}

// Every metric on as few lines as the width allows, "·" between them; a bad one (a view angle
// more than 10° off) in the viewer's red.
void addMetricLines(std::vector<Line>& lines, const std::vector<MetricItem>& metrics, cv::freetype::FreeType2* font,
                    int heightPx, int widthPx) {
  std::string all;
  bool bad = false;
  for (const MetricItem& m : metrics) {
    all += (all.empty() ? "" : "  ·  ") + metricText(m);
    bad = bad || m.tone == MetricTone::Bad;
  }
  for (const auto& l : wrapped(*font, all, heightPx, widthPx))
    lines.push_back({l, font, heightPx, bad ? cv::Scalar(140, 115, 255) : kTitleColour});
}

}  // namespace

CaptionPainter::CaptionPainter() : regular_(fontFrom("DejaVuSans.ttf")), bold_(fontFrom("DejaVuSans-Bold.ttf")) {}

void CaptionPainter::paint(cv::Mat& half, const ViewCaption& caption, const std::vector<MetricItem>& metrics) const {
  const double s = half.rows / 720.0;
  const int title = static_cast<int>(std::lround(kTitlePx * s)), text = static_cast<int>(std::lround(kTextPx * s));
  const int pad = static_cast<int>(std::lround(kPadPx * s));
  const int width = half.cols - 4 * pad;
  std::vector<Line> top;
  for (const auto& l : wrapped(*bold_, caption.title, title, width)) top.push_back({l, bold_.get(), title, kTitleColour});
  for (const auto& l : wrapped(*regular_, caption.subtitle, text, width))
    top.push_back({l, regular_.get(), text, kTextColour});
  addMetricLines(top, metrics, regular_.get(), text, width);
  drawLines(half, cv::Point(pad, pad), top, pad);
  // The legend from the bottom-left corner upwards: a disc or a line in the item's colour.
  const int row = static_cast<int>(std::lround(kLinePx * text)), swatch = text;
  const int legendHeight = row * static_cast<int>(caption.legend.size());
  if (caption.legend.empty()) return;
  int legendWidth = 0;
  for (const LegendItem& item : caption.legend) {
    int baseline = 0;
    legendWidth = std::max(legendWidth, regular_->getTextSize(item.label, text, -1, &baseline).width);
  }
  const cv::Point corner(pad, half.rows - pad - legendHeight - pad);
  plate(half, cv::Rect(corner.x, corner.y, legendWidth + swatch + 3 * pad, legendHeight + pad));
  int y = corner.y + pad / 2;
  for (const LegendItem& item : caption.legend) {
    const cv::Point mid(corner.x + pad + swatch / 2, y + row / 2);
    if (item.line)
      cv::line(half, mid - cv::Point(swatch / 2, 0), mid + cv::Point(swatch / 2, 0), bgr(item.colour),
               std::max(2, text / 6), cv::LINE_AA);
    else
      cv::circle(half, mid, std::max(3, swatch / 3), bgr(item.colour), cv::FILLED, cv::LINE_AA);
    regular_->putText(half, item.label, cv::Point(corner.x + 2 * pad + swatch, y + row - text / 4 - 1), text,
                      kDimColour, -1, cv::LINE_AA, true);
    y += row;
  }
}

}  // namespace ew::ui
