#include "plots/raster_plot.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <sstream>

#include "core/common/errors.h"

namespace ew {

namespace {

const cv::Scalar kBlack(0, 0, 0), kAxisGrey(200, 200, 200), kWhite(255, 255, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

cv::Scalar bgr(const Rgb& c) { return cv::Scalar(c[2], c[1], c[0]); }

// Text anchored at (x, y) with horizontal alignment -1 left, 0 centre, 1 right.
void text(cv::Mat& img, const std::string& s, int x, int y, int align = -1, double scale = 0.5,
          int thickness = 1, cv::Scalar color = kBlack) {
  int base = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, thickness, &base);
  const int x0 = align < 0 ? x : align == 0 ? x - size.width / 2 : x - size.width;
  cv::putText(img, s, {x0, y}, kFont, scale, color, thickness, cv::LINE_AA);
}

// Vertical text: drawn on a strip, rotated 90° counter-clockwise.
void verticalText(cv::Mat& img, const std::string& s, int xCenter, int yCenter, double scale = 0.55) {
  int base = 0;
  const cv::Size size = cv::getTextSize(s, kFont, scale, 1, &base);
  cv::Mat strip(size.height + base + 6, size.width + 6, CV_8UC3, kWhite);
  cv::putText(strip, s, {3, size.height + 2}, kFont, scale, kBlack, 1, cv::LINE_AA);
  cv::Mat rotated;
  cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  const int x0 = std::clamp(xCenter - rotated.cols / 2, 0, img.cols - rotated.cols);
  const int y0 = std::clamp(yCenter - rotated.rows / 2, 0, img.rows - rotated.rows);
  rotated.copyTo(img(cv::Rect(x0, y0, rotated.cols, rotated.rows)));
}

double niceStep(double range, int targetTicks) {
  const double raw = range / std::max(targetTicks, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * mag >= raw) return m * mag;
  }
  return 10 * mag;
}

std::string tickLabel(double v, double step) {
  std::ostringstream s;
  if (std::abs(v) < step * 1e-6) v = 0;
  if (step >= 1 || std::abs(v) >= 1e4) {
    s.setf(std::ios::fixed);
    s.precision(0);
  } else {
    s.setf(std::ios::fixed);
    s.precision(static_cast<int>(std::ceil(-std::log10(step))) + (step * std::pow(10.0, std::ceil(-std::log10(step))) == 2.5 ? 1 : 0));
  }
  s << v;
  return s.str();
}

void dashedLine(cv::Mat& img, cv::Point a, cv::Point b, const cv::Scalar& color, int thickness) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int dashes = std::max(1, static_cast<int>(len / 10));
  for (int i = 0; i < dashes; i += 2) {
    const double t0 = static_cast<double>(i) / dashes, t1 = std::min(1.0, static_cast<double>(i + 1) / dashes);
    cv::line(img, {static_cast<int>(a.x + t0 * (b.x - a.x)), static_cast<int>(a.y + t0 * (b.y - a.y))},
             {static_cast<int>(a.x + t1 * (b.x - a.x)), static_cast<int>(a.y + t1 * (b.y - a.y))}, color, thickness,
             cv::LINE_AA);
  }
}

void writePng(const std::filesystem::path& file, const cv::Mat& img) {
  bool ok = false;
  try {
    ok = cv::imwrite(file.string(), img);
  } catch (const cv::Exception& e) {
    throw Error(ErrorKind::Io, file.string(), "", e.what());
  }
  if (!ok) throw Error(ErrorKind::Io, file.string(), "", "cannot write PNG");
}

struct Axes {
  cv::Rect area;
  double x0, x1, y0, y1;
  bool logX;
  double tx(double x) const {
    const double u = logX ? (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) : (x - x0) / (x1 - x0);
    return area.x + u * area.width;
  }
  double ty(double y) const { return area.y + area.height - (y - y0) / (y1 - y0) * area.height; }
  // Pixels clamped far outside any image (OpenCV clips), so no conversion overflows.
  cv::Point at(double x, double y) const {
    const auto px = [](double v) {
      return static_cast<int>(std::lround(std::clamp(v, -1e5, 1e5)));
    };
    return {px(tx(x)), px(ty(y))};
  }
  // A point that can be placed: finite, and positive x on a log axis. Others (NaN E_r of a
  // walker without depth motion, say) are gaps in the line.
  bool drawable(double x, double y) const {
    return std::isfinite(x) && std::isfinite(y) && (!logX || x > 0.0);
  }
};

double spreadAt(const PlotSeries& s, size_t i) {
  return i < s.spread.size() && std::isfinite(s.spread[i]) ? s.spread[i] : 0.0;
}

// hi > lo afterwards, even where lo + 1 rounds back to lo.
void widen(double lo, double& hi) {
  if (hi <= lo) hi = lo + 1.0;
  if (hi <= lo) hi = lo + std::abs(lo);
}

Axes axesFor(const LinePlot& p, cv::Rect area) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  const Axes probe{area, 1.0, 10.0, 0.0, 1.0, p.logX};
  for (const auto& s : p.series) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!probe.drawable(s.x[i], s.y[i])) continue;
      const double d = spreadAt(s, i);
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i] - d);
      y1 = std::max(y1, s.y[i] + d);
    }
  }
  if (x0 > x1) x0 = p.logX ? 1 : 0, x1 = p.logX ? 10 : 1, y0 = 0, y1 = 1;
  x0 = p.xMin.value_or(x0);
  x1 = p.xMax.value_or(x1);
  y0 = p.yMin.value_or(y0);
  y1 = p.yMax.value_or(y1 + 0.08 * (y1 - y0));  // headroom for the legend
  widen(x0, x1);
  widen(y0, y1);
  return {area, x0, x1, y0, y1, p.logX};
}

// The plot's own preconditions (caller mistakes): Error(BadArgument) naming the plot.
void checkPlotSize(const std::filesystem::path& file, const std::string& title, int width,
                   int height) {
  if (width < 320 || height < 240 || width > 8192 || height > 8192)
    throw Error(ErrorKind::BadArgument, file.string(), "",
                "plot '" + title + "': the size must be 320-8192 x 240-8192 pixels, got " +
                    std::to_string(width) + " x " + std::to_string(height));
}

void checkLinePlot(const std::filesystem::path& file, const LinePlot& p) {
  const auto bad = [&](const std::string& problem) {
    throw Error(ErrorKind::BadArgument, file.string(), "", "plot '" + p.title + "': " + problem);
  };
  for (const auto& s : p.series) {
    if (s.y.size() != s.x.size() || (!s.spread.empty() && s.spread.size() != s.x.size()))
      bad("series '" + s.label + "' has " + std::to_string(s.x.size()) + " x, " +
          std::to_string(s.y.size()) + " y and " + std::to_string(s.spread.size()) +
          " spread values");
  }
  for (const auto& limit : {p.xMin, p.xMax, p.yMin, p.yMax}) {
    if (limit && !std::isfinite(*limit)) bad("axis limits must be finite");
  }
  if (p.logX && p.xMin && !(*p.xMin > 0.0)) bad("a log-scale x axis needs a positive xMin");
  if (p.logX && p.xMax && !(*p.xMax > 0.0)) bad("a log-scale x axis needs a positive xMax");
  if (p.xTickStep && !(*p.xTickStep > 0.0 && std::isfinite(*p.xTickStep)))
    bad("the x tick step must be positive and finite");
}

// Ticks from `first` by `step` up to `last`: at most kMaxTicks, and none once adding the
// step no longer changes the value (a step below the values' resolution).
constexpr int kMaxTicks = 200;

std::vector<double> ticks(double first, double last, double step) {
  std::vector<double> out;
  if (!std::isfinite(first) || !(step > 0.0) || !std::isfinite(step)) return out;
  for (double v = first; v <= last && out.size() < kMaxTicks; v += step) {
    out.push_back(v);
    if (v + step == v) break;
  }
  return out;
}

void drawTicks(cv::Mat& img, const Axes& ax, const LinePlot& p) {
  const cv::Rect& a = ax.area;
  std::vector<double> xt;
  if (ax.logX) {
    for (double d = std::pow(10.0, std::floor(std::log10(ax.x0))); d > 0.0 && d <= ax.x1 * 1.0001;
         d *= 10) {
      for (double m : {1.0, 2.0, 5.0}) {
        if (m * d >= ax.x0 * 0.9999 && m * d <= ax.x1 * 1.0001) xt.push_back(m * d);
      }
    }
  } else {
    const double step = p.xTickStep.value_or(niceStep(ax.x1 - ax.x0, 8));
    xt = ticks(std::ceil(ax.x0 / step - 1e-9) * step, ax.x1 + 1e-9 * step, step);
  }
  for (double v : xt) {
    const int x = ax.at(v, ax.y0).x;
    cv::line(img, {x, a.y}, {x, a.y + a.height}, kAxisGrey, 1);
    cv::line(img, {x, a.y + a.height}, {x, a.y + a.height + 5}, kBlack, 1);
    text(img, tickLabel(v, ax.logX ? 1.0 : p.xTickStep.value_or(niceStep(ax.x1 - ax.x0, 8))), x, a.y + a.height + 22, 0);
  }
  const double ystep = niceStep(ax.y1 - ax.y0, 6);
  for (double v : ticks(std::ceil(ax.y0 / ystep - 1e-9) * ystep, ax.y1 + 1e-9 * ystep, ystep)) {
    const int y = ax.at(ax.x0, v).y;
    cv::line(img, {a.x, y}, {a.x + a.width, y}, kAxisGrey, 1);
    cv::line(img, {a.x - 5, y}, {a.x, y}, kBlack, 1);
    text(img, tickLabel(v, ystep), a.x - 8, y + 5, 1);
  }
}

void drawSeries(cv::Mat& img, const Axes& ax, const PlotSeries& s) {
  const cv::Rect& a = ax.area;
  bool allDrawable = true;
  for (size_t i = 0; i < s.x.size(); ++i) allDrawable = allDrawable && ax.drawable(s.x[i], s.y[i]);
  if (!s.spread.empty() && allDrawable) {  // translucent ± band (non-finite SDs count as 0)
    std::vector<cv::Point> poly;
    for (size_t i = 0; i < s.x.size(); ++i) poly.push_back(ax.at(s.x[i], s.y[i] + spreadAt(s, i)));
    for (size_t i = s.x.size(); i-- > 0;) poly.push_back(ax.at(s.x[i], s.y[i] - spreadAt(s, i)));
    cv::Mat layer = img.clone();
    cv::fillPoly(layer, std::vector<std::vector<cv::Point>>{poly}, bgr(s.color), cv::LINE_AA);
    cv::Mat roi = img(a);
    cv::addWeighted(layer(a), 0.18, roi, 0.82, 0, roi);
  }
  cv::Mat plotArea = img(a);
  const cv::Point offset(a.x, a.y);
  for (size_t i = 1; s.lines && i < s.x.size(); ++i) {
    if (!ax.drawable(s.x[i - 1], s.y[i - 1]) || !ax.drawable(s.x[i], s.y[i])) continue;
    const cv::Point p0 = ax.at(s.x[i - 1], s.y[i - 1]) - offset, p1 = ax.at(s.x[i], s.y[i]) - offset;
    if (s.dashed) dashedLine(plotArea, p0, p1, bgr(s.color), 2);
    else cv::line(plotArea, p0, p1, bgr(s.color), 2, cv::LINE_AA);
  }
  if (s.markers) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (ax.drawable(s.x[i], s.y[i]))
        cv::circle(plotArea, ax.at(s.x[i], s.y[i]) - offset, 4, bgr(s.color), cv::FILLED,
                   cv::LINE_AA);
    }
  }
}

// The corner of the plot area where the legend hides the fewest drawn points.
cv::Rect legendBox(const cv::Rect& a, cv::Size size, const std::vector<cv::Point>& drawn) {
  std::vector<cv::Rect> corners = {{a.x + a.width - size.width - 10, a.y + 10, size.width, size.height},
                                   {a.x + 10, a.y + 10, size.width, size.height},
                                   {a.x + a.width - size.width - 10, a.y + a.height - size.height - 10, size.width, size.height},
                                   {a.x + 10, a.y + a.height - size.height - 10, size.width, size.height}};
  cv::Rect best = corners.front();
  long fewest = -1;
  for (const auto& box : corners) {
    const cv::Rect padded(box.x - 6, box.y - 6, box.width + 12, box.height + 12);
    const long hidden = std::count_if(drawn.begin(), drawn.end(), [&](const cv::Point& p) { return padded.contains(p); });
    if (fewest < 0 || hidden < fewest) {
      fewest = hidden;
      best = box;
    }
  }
  return best;
}

void drawLegend(cv::Mat& img, const cv::Rect& a, const std::vector<PlotSeries>& all,
                const std::vector<std::string>& notes, const std::vector<cv::Point>& drawn = {}) {
  std::vector<PlotSeries> series;
  std::copy_if(all.begin(), all.end(), std::back_inserter(series), [](const PlotSeries& s) { return !s.label.empty(); });
  int width = 0;
  for (const auto& s : series) width = std::max(width, cv::getTextSize(s.label, kFont, 0.5, 1, nullptr).width + 50);
  for (const auto& n : notes) width = std::max(width, cv::getTextSize(n, kFont, 0.45, 1, nullptr).width + 16);
  const int height = 22 * static_cast<int>(series.size() + notes.size()) + 10;
  const cv::Rect box = legendBox(a, {width, height}, drawn);
  cv::rectangle(img, box, kWhite, cv::FILLED);
  cv::rectangle(img, box, kBlack, 1);
  int y = box.y + 20;
  for (const auto& s : series) {
    const cv::Point l0(box.x + 8, y - 5), l1(box.x + 38, y - 5);
    if (s.dashed) dashedLine(img, l0, l1, bgr(s.color), 2);
    else if (s.lines) cv::line(img, l0, l1, bgr(s.color), 2, cv::LINE_AA);
    if (s.markers) cv::circle(img, (l0 + l1) / 2, 4, bgr(s.color), cv::FILLED, cv::LINE_AA);
    text(img, s.label, box.x + 46, y);
    y += 22;
  }
  for (const auto& n : notes) {
    text(img, n, box.x + 8, y, -1, 0.45);
    y += 22;
  }
}

}  // namespace

void saveLinePlot(const std::filesystem::path& file, const LinePlot& p, int width, int height) {
  checkPlotSize(file, p.title, width, height);
  checkLinePlot(file, p);
  cv::Mat img(height, width, CV_8UC3, kWhite);
  const cv::Rect area(95, 55, width - 125, height - 125);
  const Axes ax = axesFor(p, area);
  drawTicks(img, ax, p);
  std::vector<cv::Point> drawn;
  for (const auto& s : p.series) {
    drawSeries(img, ax, s);
    for (size_t i = 0; i < s.x.size(); ++i) {  // points along each segment, for the legend
      if (!ax.drawable(s.x[i], s.y[i])) continue;
      const cv::Point b = ax.at(s.x[i], s.y[i]);
      const cv::Point e = i + 1 < s.x.size() && ax.drawable(s.x[i + 1], s.y[i + 1])
                              ? ax.at(s.x[i + 1], s.y[i + 1])
                              : b;
      for (int t = 0; t < 8; ++t) drawn.push_back(b + (e - b) * t / 8);
    }
  }
  cv::rectangle(img, area, kBlack, 1);
  text(img, p.title, width / 2, 32, 0, 0.62, 1);
  text(img, p.xLabel, area.x + area.width / 2, height - 22, 0, 0.55);
  verticalText(img, p.yLabel, 22, area.y + area.height / 2);
  drawLegend(img, area, p.series, p.notes, drawn);
  writePng(file, img);
}

void saveBarPlot(const std::filesystem::path& file, const BarPlot& p, int width, int height) {
  checkPlotSize(file, p.title, width, height);
  if (p.seriesLabels.size() != p.seriesColors.size())
    throw Error(ErrorKind::BadArgument, file.string(), "",
                "plot '" + p.title + "': " + std::to_string(p.seriesLabels.size()) +
                    " series labels but " + std::to_string(p.seriesColors.size()) + " colours");
  for (const auto& g : p.groups) {
    if (g.values.size() > p.seriesColors.size())
      throw Error(ErrorKind::BadArgument, file.string(), "",
                  "plot '" + p.title + "': group '" + g.label + "' has " +
                      std::to_string(g.values.size()) + " values for " +
                      std::to_string(p.seriesColors.size()) + " series");
  }
  cv::Mat img(height, width, CV_8UC3, kWhite);
  // The group labels sit left of the bars: as wide as the widest, within a half of the image.
  int labels = 150;
  for (const auto& g : p.groups) labels = std::max(labels, cv::getTextSize(g.label, kFont, 0.45, 1, nullptr).width);
  const int left = std::min(labels + 20, width / 2);
  const cv::Rect area(left, 55, width - left - 30, height - 120);
  // Non-finite values (and a non-finite reference) are left out: no bar, no scale.
  const double reference =
      p.referenceValue && std::isfinite(*p.referenceValue) ? *p.referenceValue : 0.0;
  double vmax = reference;
  for (const auto& g : p.groups) {
    for (double v : g.values) {
      if (std::isfinite(v)) vmax = std::max(vmax, v);
    }
  }
  // A third more than the longest bar: room for the legend beside the bars, not over them.
  vmax = vmax > 0 && std::isfinite(vmax * 1.35) ? vmax * 1.35 : 1.0;
  const Axes ax{area, 0.0, vmax, 0.0, 1.0, false};
  const double step = niceStep(vmax, 6);
  for (double v : ticks(0.0, vmax, step)) {
    const int x = ax.at(v, 0.0).x;
    cv::line(img, {x, area.y}, {x, area.y + area.height}, kAxisGrey, 1);
    text(img, tickLabel(v, step), x, area.y + area.height + 20, 0);
  }
  std::vector<cv::Point> barPoints;
  const double rowH = static_cast<double>(area.height) / static_cast<double>(std::max<size_t>(p.groups.size(), 1));
  const size_t k = std::max<size_t>(p.seriesLabels.size(), 1);
  for (size_t g = 0; g < p.groups.size(); ++g) {
    const double top = area.y + static_cast<double>(g) * rowH;
    text(img, p.groups[g].label, area.x - 8, static_cast<int>(top + rowH / 2 + 5), 1, 0.45);
    for (size_t s = 0; s < p.groups[g].values.size(); ++s) {
      if (!std::isfinite(p.groups[g].values[s])) continue;
      const double barH = rowH * 0.8 / static_cast<double>(k);
      const int y0 = static_cast<int>(top + rowH * 0.1 + static_cast<double>(s) * barH);
      const int x1 = ax.at(p.groups[g].values[s], 0.0).x;
      cv::rectangle(img, cv::Rect(area.x, y0, std::max(1, x1 - area.x), std::max(1, static_cast<int>(barH) - 1)),
                    bgr(p.seriesColors[s]), cv::FILLED);
      // Points along the bar, so the legend goes to the corner it hides least.
      for (int x = area.x; x <= x1; x += 8) barPoints.emplace_back(x, y0 + static_cast<int>(barH / 2));
    }
  }
  std::vector<PlotSeries> legend;
  for (size_t s = 0; s < p.seriesLabels.size(); ++s) legend.push_back({p.seriesLabels[s], {}, {}, {}, p.seriesColors[s], false, false});
  if (p.referenceValue && std::isfinite(*p.referenceValue)) {
    const int x = ax.at(*p.referenceValue, 0.0).x;
    dashedLine(img, {x, area.y}, {x, area.y + area.height}, kBlack, 2);
    legend.push_back({p.referenceLabel, {}, {}, {}, {0, 0, 0}, true, false});
  }
  cv::rectangle(img, area, kBlack, 1);
  text(img, p.title, width / 2, 32, 0, 0.62, 1);
  text(img, p.valueLabel, area.x + area.width / 2, height - 22, 0, 0.55);
  drawLegend(img, area, legend, {}, barPoints);
  writePng(file, img);
}

PlotWriter rasterPlotWriter() {
  return {[](const std::filesystem::path& file, const LinePlot& p) { saveLinePlot(file, p); },
          [](const std::filesystem::path& file, const BarPlot& p) { saveBarPlot(file, p); }};
}

}  // namespace ew
