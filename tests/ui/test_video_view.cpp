// The video view's magnification (ui/panels/video_view.h): zoom 1 is the whole picture; a
// zoomed view has the chosen pixel at its middle and magnifies by the factor; the wheel's zoom
// keeps the pixel under the cursor where it was.

#include <gtest/gtest.h>

#include "ui/panels/video_view.h"

namespace ew::ui {
namespace {

constexpr float kAspect = 1.6f;

TEST(VideoView, ZoomOneIsTheWholePicture) {
  const VideoViewFrame whole = videoViewFrame(1768, 994, kAspect);
  const VideoViewFrame same = zoomedFrame(whole, 1.0, {100.0f, 100.0f});
  EXPECT_EQ(same.heightPx, whole.heightPx);
  EXPECT_EQ(same.centre, whole.centre);
}

TEST(VideoView, AZoomedViewHasItsPixelAtTheMiddleMagnified) {
  const VideoViewFrame whole = videoViewFrame(1768, 994, kAspect);
  const VideoViewFrame zoomed = zoomedFrame(whole, 4.0, {817.0f, 747.0f});
  const glm::vec2 middle = zoomed.toVideoPx({0.5f, 0.5f}, kAspect);
  EXPECT_NEAR(middle.x, 817.0f, 1e-3f);
  EXPECT_NEAR(middle.y, 747.0f, 1e-3f);
  const auto span = [&](const VideoViewFrame& f) {
    return f.toViewShare({110.0f, 0.0f}, kAspect).x - f.toViewShare({100.0f, 0.0f}, kAspect).x;
  };
  EXPECT_NEAR(span(zoomed), 4.0f * span(whole), 1e-5f) << "ten pixels four times as wide";
  EXPECT_EQ(videoViewMiddle(zoomed), glm::vec2(817.0f, 747.0f));
}

TEST(VideoView, TheWheelZoomsAboutThePixelUnderTheCursor) {
  const VideoViewFrame whole = videoViewFrame(1768, 994, kAspect);
  const glm::vec2 cursorShare{0.3f, 0.65f};
  VideoViewFrame view = whole;
  double zoom = 1.0;
  for (double next : {1.25, 2.0, 7.5, 3.0}) {
    const glm::vec2 under = view.toVideoPx(cursorShare, kAspect);
    const glm::vec2 middle = zoomMiddleKeeping(videoViewMiddle(view), under, zoom, next);
    view = zoomedFrame(whole, next, middle);
    zoom = next;
    const glm::vec2 after = view.toVideoPx(cursorShare, kAspect);
    EXPECT_NEAR(after.x, under.x, 1e-2f) << "zoom " << next;
    EXPECT_NEAR(after.y, under.y, 1e-2f) << "zoom " << next;
  }
}

}  // namespace
}  // namespace ew::ui
