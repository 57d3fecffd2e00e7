#include "ui/app/layout.h"

#include <algorithm>

namespace ew::ui {

float noticeRowHeight(float scale) { return 34.0f * scale; }

Layout computeLayout(float width, float height, float scale, bool noticeRow) {
  Layout l;
  const float headerH = 46.0f * scale;
  const float noticeH = noticeRow ? noticeRowHeight(scale) : 0.0f;
  const float sideW = std::clamp(width * 0.19f, 250.0f * scale, 360.0f * scale);
  const float rightW = std::clamp(width * 0.18f, 240.0f * scale, 340.0f * scale);
  const float metricsH = 66.0f * scale;
  const float playbackH = 44.0f * scale;
  const float bottomH = std::clamp(height * 0.24f, 170.0f * scale, 300.0f * scale);
  const float centreX = sideW;
  const float centreW = std::max(100.0f, width - sideW - rightW);
  const float bodyY = headerH + noticeH;
  const float bodyH = height - bodyY;

  l.header = {{0, 0}, {width, headerH}};
  l.notice = {{0, headerH}, {width, noticeH}};
  const float subjectsH = bodyH * 0.46f;
  l.subjects = {{0, bodyY}, {sideW, subjectsH}};
  l.controls = {{0, bodyY + subjectsH}, {sideW, bodyH - subjectsH}};
  l.coefficients = {{width - rightW, bodyY}, {rightW, bodyH - bottomH}};
  l.log = {{width - rightW, height - bottomH}, {rightW, bottomH}};

  l.metrics = {{centreX, bodyY}, {centreW, metricsH}};
  const float viewsY = bodyY + metricsH;
  const float viewsH = std::max(60.0f, bodyH - metricsH - playbackH - bottomH);
  const float halfW = centreW * 0.5f;
  l.input = {{centreX, viewsY}, {halfW, viewsH}};
  l.reconstruction = {{centreX + halfW, viewsY}, {centreW - halfW, viewsH}};
  l.playback = {{centreX, viewsY + viewsH}, {centreW, playbackH}};
  const float bottomY = height - bottomH;
  const float errorsW = centreW * 0.42f;
  l.jointErrors = {{centreX, bottomY}, {errorsW, bottomH}};
  l.profile = {{centreX + errorsW, bottomY}, {centreW - errorsW, bottomH}};
  return l;
}

}  // namespace ew::ui
