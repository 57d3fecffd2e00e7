#include "ui/render/damage.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace ew::ui {

namespace {

bool touchesAny(const PixelRect& r, const std::vector<PixelRect>& rects) {
  return std::any_of(rects.begin(), rects.end(),
                     [&](const PixelRect& o) { return r.intersects(o); });
}

// Drops empty rectangles and those inside another one (clearing them again is wasted).
std::vector<PixelRect> withoutContained(const std::vector<PixelRect>& rects) {
  std::vector<PixelRect> out;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const PixelRect& r = rects[i];
    if (r.empty()) continue;
    bool inside = false;
    for (std::size_t j = 0; j < rects.size() && !inside; ++j) {
      const PixelRect& o = rects[j];
      if (j == i || o.empty()) continue;
      const bool contained = o.intersected(r) == r;
      // Of two equal rectangles keep the first.
      inside = contained && (o != r || j < i);
    }
    if (!inside) out.push_back(r);
  }
  return out;
}

// The area of the union (a few dozen rectangles at most: a grid over their edges).
long long unionArea(const std::vector<PixelRect>& rects) {
  std::vector<int> xs, ys;
  for (const auto& r : rects) {
    xs.insert(xs.end(), {r.x0, r.x1});
    ys.insert(ys.end(), {r.y0, r.y1});
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  long long area = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      const PixelRect cell{xs[i], ys[j], xs[i + 1], ys[j + 1]};
      if (touchesAny(cell, rects)) area += cell.area();
    }
  return area;
}

// Beyond this share of the frame, one full clear is cheaper than many partial ones.
constexpr double kFullRepaintShare = 0.75;

}  // namespace

RepaintPlan DamageTracker::fullPlan(std::size_t itemCount, int width, int height) const {
  RepaintPlan p;
  p.full = true;
  p.repaint.assign(itemCount, true);
  p.repaintedArea = PixelRect{0, 0, width, height}.area();
  return p;
}

bool DamageTracker::orderChanged(const std::vector<PaintItem>& items) const {
  std::unordered_set<std::uint64_t> now, before;
  for (const auto& it : items)
    if (!now.insert(it.key).second) return true;  // a repeated key: no safe matching
  for (const auto& it : previous_) before.insert(it.key);
  std::vector<std::uint64_t> a, b;
  for (const auto& it : previous_)
    if (now.count(it.key)) a.push_back(it.key);
  for (const auto& it : items)
    if (before.count(it.key)) b.push_back(it.key);
  return a != b;
}

std::vector<PixelRect> DamageTracker::seedDamage(const std::vector<PaintItem>& items) const {
  std::unordered_map<std::uint64_t, const PaintItem*> before;
  for (const auto& it : previous_) before[it.key] = &it;
  std::vector<PixelRect> damaged;
  for (const auto& it : items) {
    const auto found = before.find(it.key);
    if (found == before.end()) {
      damaged.push_back(it.bounds);
      continue;
    }
    const PaintItem& old = *found->second;
    if (old.bounds != it.bounds || old.content != it.content) {
      damaged.push_back(old.bounds);
      damaged.push_back(it.bounds);
    }
    before.erase(found);
  }
  for (const auto& [key, old] : before) damaged.push_back(old->bounds);  // gone this frame
  return damaged;
}

RepaintPlan DamageTracker::plan(std::vector<PaintItem> items, int width, int height) {
  RepaintPlan p;
  if (!valid_ || width != width_ || height != height_ || orderChanged(items)) {
    p = fullPlan(items.size(), width, height);
  } else {
    std::vector<PixelRect> damaged = seedDamage(items);
    p.repaint.assign(items.size(), false);
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (p.repaint[i] || !touchesAny(items[i].bounds, damaged)) continue;
        p.repaint[i] = true;
        damaged.push_back(items[i].bounds);
        grew = true;
      }
    }
    const PixelRect frame{0, 0, width, height};
    for (auto& r : damaged) r = r.intersected(frame);
    p.clear = withoutContained(damaged);
    p.repaintedArea = unionArea(p.clear);
    if (static_cast<double>(p.repaintedArea) >
        kFullRepaintShare * static_cast<double>(frame.area()))
      p = fullPlan(items.size(), width, height);
  }
  previous_ = std::move(items);
  width_ = width;
  height_ = height;
  valid_ = true;
  return p;
}

}  // namespace ew::ui
