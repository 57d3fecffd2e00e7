// Damage tracking (ui/render/damage.h): which items a frame repaints and which pixels it
// clears, given what changed since the previous frame. The pixel-exact end-to-end check
// is the viewer's --check-repaint (tests/gui/test_gui_default.cpp).

#include "ui/render/damage.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ew::ui {
namespace {

PaintItem item(std::uint64_t key, PixelRect bounds, const std::string& look = "a") {
  PaintItem it{key, bounds, {}};
  for (char c : look) it.content.push_back(static_cast<std::byte>(c));
  return it;
}

// Two panels side by side, each a fill plus its draw list, and a popup over both.
std::vector<PaintItem> frame(const std::string& leftLook = "a",
                             const std::string& rightLook = "a") {
  return {item(1, {0, 0, 100, 100}), item(2, {100, 0, 200, 100}),  // fills, touching edges
          item(3, {5, 5, 95, 95}, leftLook), item(4, {105, 5, 195, 95}, rightLook)};
}

constexpr int kW = 200, kH = 100;

TEST(DamageTracker, FirstFrameAndNewSizeRepaintEverything) {
  DamageTracker t;
  RepaintPlan p = t.plan(frame(), kW, kH);
  EXPECT_TRUE(p.full);
  EXPECT_EQ(p.repaint, std::vector<bool>(4, true));
  EXPECT_EQ(p.repaintedArea, kW * kH);
  p = t.plan(frame(), kW + 1, kH);
  EXPECT_TRUE(p.full);
}

TEST(DamageTracker, NothingChangedRepaintsNothing) {
  DamageTracker t;
  t.plan(frame(), kW, kH);
  const RepaintPlan p = t.plan(frame(), kW, kH);
  EXPECT_FALSE(p.full);
  EXPECT_TRUE(p.clear.empty());
  EXPECT_EQ(p.repaint, std::vector<bool>(4, false));
  EXPECT_EQ(p.repaintedArea, 0);
}

TEST(DamageTracker, AChangedItemRepaintsWhatItTouchesAndNothingElse) {
  DamageTracker t;
  t.plan(frame(), kW, kH);
  const RepaintPlan p = t.plan(frame("a", "b"), kW, kH);
  EXPECT_FALSE(p.full);
  // The right list changed: it and the fill beneath it; the left panel only shares an
  // edge (half-open rectangles), so it stays.
  EXPECT_EQ(p.repaint, (std::vector<bool>{false, true, false, true}));
  ASSERT_EQ(p.clear.size(), 1u);
  EXPECT_EQ(p.clear[0], (PixelRect{100, 0, 200, 100}));
  EXPECT_EQ(p.repaintedArea, 100 * 100);
}

TEST(DamageTracker, AMovedItemDamagesWhereItWasAndWhereItIs) {
  DamageTracker t;
  // A background on the left half, another on the right; the item moves from one to the other.
  const auto make = [](PixelRect where) {
    return std::vector<PaintItem>{item(1, {0, 0, 100, 50}), item(2, {100, 0, 200, 50}),
                                  item(3, where), item(4, {0, 60, 200, 100})};
  };
  t.plan(make({10, 10, 20, 20}), kW, kH);
  const RepaintPlan p = t.plan(make({150, 10, 160, 20}), kW, kH);
  EXPECT_FALSE(p.full);
  EXPECT_EQ(p.repaint, (std::vector<bool>{true, true, true, false}));
  EXPECT_EQ(p.repaintedArea, 200 * 50);
}

TEST(DamageTracker, AVanishedPopupRepaintsWhatWasUnderIt) {
  DamageTracker t;
  std::vector<PaintItem> withPopup = frame();
  withPopup.push_back(item(9, {90, 40, 110, 60}));
  t.plan(withPopup, 2 * kW, kH);  // the panels fill half of the frame
  const RepaintPlan p = t.plan(frame(), 2 * kW, kH);
  EXPECT_FALSE(p.full) << "everything repainted: popup bounds spread too far";
  EXPECT_EQ(p.repaint, std::vector<bool>(4, true));  // it overlapped both panels
}

TEST(DamageTracker, ChainsThroughOverlapsToAFixedPoint) {
  // 1 changes; 2 overlaps 1; 3 overlaps only 2; 4 is apart.
  const auto make = [](const std::string& look) {
    return std::vector<PaintItem>{item(1, {0, 0, 10, 10}, look), item(2, {5, 5, 30, 15}),
                                  item(3, {25, 0, 40, 10}), item(4, {100, 50, 110, 60})};
  };
  DamageTracker t;
  t.plan(make("a"), kW, kH);
  const RepaintPlan p = t.plan(make("b"), kW, kH);
  EXPECT_EQ(p.repaint, (std::vector<bool>{true, true, true, false}));
  // Pixels: 100 + 250 + 150 minus the overlaps (25 + 25) = 450.
  EXPECT_EQ(p.repaintedArea, 450);
}

TEST(DamageTracker, ItemsPaintedLaterThanTheDamageAreRepaintedToo) {
  // The changed item is painted first (a fill); the list above it must be repainted.
  DamageTracker t;
  t.plan({item(1, {0, 0, 50, 50}, "red"), item(2, {10, 10, 20, 20})}, kW, kH);
  const RepaintPlan p =
      t.plan({item(1, {0, 0, 50, 50}, "blue"), item(2, {10, 10, 20, 20})}, kW, kH);
  EXPECT_EQ(p.repaint, (std::vector<bool>{true, true}));
}

TEST(DamageTracker, ANewOrderOrARepeatedKeyRepaintsEverything) {
  DamageTracker t;
  t.plan(frame(), kW, kH);
  std::vector<PaintItem> swapped = frame();
  std::swap(swapped[2], swapped[3]);
  EXPECT_TRUE(t.plan(swapped, kW, kH).full);
  std::vector<PaintItem> repeated = frame();
  repeated[3].key = repeated[2].key;
  EXPECT_TRUE(t.plan(repeated, kW, kH).full);
}

TEST(DamageTracker, InvalidateAndLargeDamageRepaintEverything) {
  DamageTracker t;
  t.plan(frame(), kW, kH);
  t.invalidate();
  EXPECT_TRUE(t.plan(frame(), kW, kH).full);
  // Both panels changed: all of the frame, so one full clear.
  const RepaintPlan p = t.plan(frame("b", "b"), kW, kH);
  EXPECT_TRUE(p.full);
  EXPECT_EQ(p.repaintedArea, kW * kH);
}

TEST(DamageTracker, DamageOutsideTheFrameIsClipped) {
  DamageTracker t;
  t.plan({item(1, {0, 0, 400, 100}), item(2, {190, 40, 260, 60})}, kW, kH);
  const RepaintPlan p =
      t.plan({item(1, {0, 0, 400, 100}), item(2, {190, 40, 260, 60}, "b")}, kW, kH);
  // The background is repainted (it lies under the item) and cleared within the frame.
  EXPECT_TRUE(p.full);
  t.plan({item(1, {0, 0, 100, 100}), item(2, {150, 40, 260, 60})}, kW, kH);
  const RepaintPlan q =
      t.plan({item(1, {0, 0, 100, 100}), item(2, {150, 40, 260, 60}, "c")}, kW, kH);
  EXPECT_FALSE(q.full);
  ASSERT_EQ(q.clear.size(), 1u);
  EXPECT_EQ(q.clear[0], (PixelRect{150, 40, 200, 60}));
}

TEST(PixelRect, HalfOpenIntersectionAndUnion) {
  const PixelRect a{0, 0, 10, 10}, b{10, 0, 20, 10}, c{5, 5, 15, 15};
  EXPECT_FALSE(a.intersects(b));
  EXPECT_TRUE(a.intersects(c));
  EXPECT_EQ(a.intersected(c), (PixelRect{5, 5, 10, 10}));
  EXPECT_EQ(a.united(b), (PixelRect{0, 0, 20, 10}));
  EXPECT_EQ(PixelRect{}.united(a), a);
  EXPECT_TRUE(a.intersected(b).empty());
  EXPECT_EQ(a.intersected(b).area(), 0);
}

}  // namespace
}  // namespace ew::ui
