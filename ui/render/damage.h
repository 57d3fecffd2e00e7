#pragma once
// Which parts of a frame must be painted again. A frame is a list of items painted in
// order (panel fills, the views' images, Dear ImGui's draw lists), each with the pixels
// it may touch and the data that decides what it paints. Compared with the previous
// frame, an item that changed (or moved, appeared, vanished) damages its old and new
// pixels; every item touching damaged pixels is repainted whole, which damages its
// pixels in turn, until nothing more is added. Clearing the damaged pixels and
// repainting those items in order then gives exactly the full redraw's pixels.
//
// Under llvmpipe most of a frame's time is Dear ImGui's triangles, and during playback
// only the views and the playback bar change: repainting only those is what brings the
// 1600×900 frame under 10 ms (docs/VIEWER_DESIGN.md, "Frame time"). No GL here (unit-tested).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ui/pixel_rect.h"

namespace ew::ui {

// One thing the frame paints. `key` names it across frames (unique within a frame);
// `content` is everything that decides its pixels besides `bounds`.
struct PaintItem {
  std::uint64_t key = 0;
  PixelRect bounds;
  std::vector<std::byte> content;
};

// Appends the bytes of a trivially copyable value or of a span to an item's content.
template <class T>
void appendBytes(std::vector<std::byte>& out, const T& value) {
  const auto* p = reinterpret_cast<const std::byte*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}
template <class T>
void appendBytes(std::vector<std::byte>& out, std::span<const T> values) {
  const auto* p = reinterpret_cast<const std::byte*>(values.data());
  out.insert(out.end(), p, p + values.size_bytes());
}

struct RepaintPlan {
  bool full = false;             // everything: clear the whole frame, repaint all items
  std::vector<PixelRect> clear;  // otherwise: the pixels to clear first…
  std::vector<bool> repaint;     // …then these items (same order as given), in order
  long long repaintedArea = 0;   // pixels cleared and repainted (the whole frame when full)
};

class DamageTracker {
 public:
  // What to paint for this frame's `items` (in paint order) on a width×height frame whose
  // pixels hold the previous frame; remembers the items for the next call.
  RepaintPlan plan(std::vector<PaintItem> items, int width, int height);
  // The next plan repaints everything (the pixels were lost, or something outside the
  // items changed them, e.g. the font texture).
  void invalidate() { valid_ = false; }
  // The items of the last plan (their bounds are where to paint them).
  const std::vector<PaintItem>& items() const { return previous_; }

 private:
  RepaintPlan fullPlan(std::size_t itemCount, int width, int height) const;
  bool orderChanged(const std::vector<PaintItem>& items) const;
  std::vector<PixelRect> seedDamage(const std::vector<PaintItem>& items) const;

  std::vector<PaintItem> previous_;
  int width_ = 0, height_ = 0;
  bool valid_ = false;
};

}  // namespace ew::ui
