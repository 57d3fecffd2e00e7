#include "ui/render/compositor.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

namespace ew::ui {
namespace {

// Keys of the three kinds of item, told apart in the top bits.
enum class Kind : std::uint64_t { Fill = 1, Image = 2, DrawList = 3 };
std::uint64_t itemKey(Kind kind, std::uint64_t id) {
  return (static_cast<std::uint64_t>(kind) << 60) | (id & ((std::uint64_t{1} << 60) - 1));
}
std::uint64_t pointerId(const void* p) {
  return static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p));
}

// The pixels a rectangle in ImGui's coordinates can touch (rounded outwards).
PixelRect toPixels(float x0, float y0, float x1, float y1, ImVec2 origin, ImVec2 scale) {
  return {static_cast<int>(std::floor((x0 - origin.x) * scale.x)),
          static_cast<int>(std::floor((y0 - origin.y) * scale.y)),
          static_cast<int>(std::ceil((x1 - origin.x) * scale.x)),
          static_cast<int>(std::ceil((y1 - origin.y) * scale.y))};
}

// Pixels of a backdrop fill: the rounding Backdrop has always used.
PixelRect fillPixels(const Backdrop::Fill& f, ImVec2 scale) {
  return {static_cast<int>(std::lround(f.pos.x * scale.x)),
          static_cast<int>(std::lround(f.pos.y * scale.y)),
          static_cast<int>(std::lround((f.pos.x + f.size.x) * scale.x)),
          static_cast<int>(std::lround((f.pos.y + f.size.y) * scale.y))};
}

// Pixels of a view's image: the target was sized from the same position (truncated).
PixelRect imagePixels(const Backdrop::Image& im, ImVec2 scale) {
  const int x = static_cast<int>(im.pos.x * scale.x), top = static_cast<int>(im.pos.y * scale.y);
  return {x, top, x + im.target->width(), top + im.target->height()};
}

// What a draw command can touch: its clip rectangle and its triangles' bounding box.
PixelRect commandPixels(const ImDrawList& list, const ImDrawCmd& cmd, ImVec2 origin, ImVec2 scale) {
  float x0 = FLT_MAX, y0 = FLT_MAX, x1 = -FLT_MAX, y1 = -FLT_MAX;
  for (unsigned i = cmd.IdxOffset; i < cmd.IdxOffset + cmd.ElemCount; ++i) {
    const ImVec2 p =
        list.VtxBuffer[static_cast<int>(cmd.VtxOffset + list.IdxBuffer[static_cast<int>(i)])].pos;
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  if (x1 < x0) return {};
  const ImVec4& c = cmd.ClipRect;
  return toPixels(x0, y0, x1, y1, origin, scale)
      .intersected(toPixels(c.x, c.y, c.z, c.w, origin, scale));
}

PaintItem drawListItem(const ImDrawList& list, ImVec2 origin, ImVec2 scale,
                       const PixelRect& frame) {
  PaintItem item{itemKey(Kind::DrawList, pointerId(&list)), {}, {}};
  auto& c = item.content;
  c.reserve(
      static_cast<std::size_t>(list.VtxBuffer.size_in_bytes() + list.IdxBuffer.size_in_bytes()) +
      static_cast<std::size_t>(list.CmdBuffer.Size) * 64);
  appendBytes(c, std::span<const ImDrawVert>(list.VtxBuffer.Data,
                                             static_cast<std::size_t>(list.VtxBuffer.Size)));
  appendBytes(c, std::span<const ImDrawIdx>(list.IdxBuffer.Data,
                                            static_cast<std::size_t>(list.IdxBuffer.Size)));
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    appendBytes(c, cmd.ClipRect);
    appendBytes(c, cmd.TextureId);
    appendBytes(c, cmd.VtxOffset);
    appendBytes(c, cmd.IdxOffset);
    appendBytes(c, cmd.ElemCount);
    appendBytes(c, cmd.UserCallback);
    appendBytes(c, cmd.UserCallbackData);
    // A callback may draw anywhere.
    item.bounds =
        item.bounds.united(cmd.UserCallback ? frame : commandPixels(list, cmd, origin, scale));
  }
  item.bounds = item.bounds.intersected(frame);
  return item;
}

// This frame's items in paint order: fills, images, then ImGui's draw lists.
std::vector<PaintItem> paintItems(const Backdrop& backdrop, const ImDrawData& ui,
                                  const PixelRect& frame) {
  std::vector<PaintItem> items;
  const ImVec2 scale = ui.FramebufferScale;
  for (std::size_t i = 0; i < backdrop.fills().size(); ++i) {
    const auto& f = backdrop.fills()[i];
    PaintItem item{itemKey(Kind::Fill, i), fillPixels(f, scale), {}};
    appendBytes(item.content, f.colour);
    items.push_back(std::move(item));
  }
  for (const auto& im : backdrop.images()) {
    PaintItem item{itemKey(Kind::Image, pointerId(im.target)), imagePixels(im, scale), {}};
    appendBytes(item.content, im.target->generation());
    items.push_back(std::move(item));
  }
  for (int n = 0; n < ui.CmdListsCount; ++n)
    items.push_back(drawListItem(*ui.CmdLists[n], ui.DisplayPos, scale, frame));
  return items;
}

// Pixels with the origin top-left to GL's bottom-left.
void fillPixelRect(const PixelRect& r, int fbHeight, const glm::vec4& colour) {
  gl::fillRect(r.x0, fbHeight - r.y1, r.x1 - r.x0, r.y1 - r.y0, colour);
}

bool containedInAny(const PixelRect& r, const std::vector<PixelRect>& rects) {
  return std::any_of(rects.begin(), rects.end(),
                     [&](const PixelRect& o) { return o.intersected(r) == r; });
}

}  // namespace

void Compositor::draw(Backdrop& backdrop, const ImDrawData& ui, glm::vec4 background, int fbWidth,
                      int fbHeight) {
  if (target_ == Target::Layer) layer_.ensure(fbWidth, fbHeight, 1, false);
  if (background != background_ || target_ == Target::FullRedraw) damage_.invalidate();
  background_ = background;
  const PixelRect frame{0, 0, fbWidth, fbHeight};
  const RepaintPlan plan = damage_.plan(paintItems(backdrop, ui, frame), fbWidth, fbHeight);
  lastShare_ =
      static_cast<double>(plan.repaintedArea) / static_cast<double>(std::max(frame.area(), 1LL));
  changed_ = plan.full ? std::vector<PixelRect>{frame} : plan.clear;
  gl::RenderTarget* into = target_ == Target::Layer ? &layer_ : nullptr;
  paint(plan, backdrop, ui, into, fbWidth, fbHeight);
  if (checking_) check(plan, backdrop, ui, into, fbWidth, fbHeight);
  if (into) into->blitToDefault(0, 0);
  backdrop.reset();
}

void Compositor::paint(const RepaintPlan& plan, const Backdrop& backdrop, const ImDrawData& ui,
                       gl::RenderTarget* into, int fbWidth, int fbHeight) {
  const auto bind = [&] {
    if (into)
      into->begin();
    else
      gl::bindDefaultFramebuffer(fbWidth, fbHeight);
  };
  // Item i's pixels, as planned (fills first, then images, then ImGui's lists).
  const auto& items = damage_.items();
  const std::size_t fills = backdrop.fills().size(), images = backdrop.images().size();
  bind();
  if (plan.full) {
    gl::clearColour(background_);
  } else {
    // Fills and images replace their pixels (a clear, a blit: no blending), so clearing
    // beneath a repainted one first would be wasted work.
    std::vector<PixelRect> replaced;
    for (std::size_t k = 0; k < fills + images; ++k)
      if (plan.repaint[k]) replaced.push_back(items[k].bounds);
    for (const PixelRect& r : plan.clear)
      if (!containedInAny(r, replaced)) fillPixelRect(r, fbHeight, background_);
  }
  std::size_t i = 0;
  for (const auto& f : backdrop.fills()) {
    if (plan.repaint[i]) fillPixelRect(items[i].bounds, fbHeight, f.colour);
    ++i;
  }
  for (const auto& im : backdrop.images()) {
    const PixelRect r = items[i].bounds;
    if (!plan.repaint[i++]) continue;
    if (into)
      im.target->blitInto(*into, r.x0, fbHeight - r.y1);
    else
      im.target->blitToDefault(r.x0, fbHeight - r.y1);
  }
  std::vector<ImDrawList*> lists;
  int vertices = 0, indices = 0;
  for (int n = 0; n < ui.CmdListsCount; ++n) {
    if (!plan.repaint[i++]) continue;
    lists.push_back(ui.CmdLists[n]);
    vertices += ui.CmdLists[n]->VtxBuffer.Size;
    indices += ui.CmdLists[n]->IdxBuffer.Size;
  }
  if (lists.empty()) return;
  ImDrawData part = ui;
  part.CmdLists = lists.data();
  part.CmdListsCount = static_cast<int>(lists.size());
  part.TotalVtxCount = vertices;
  part.TotalIdxCount = indices;
  bind();  // the blits left the default framebuffer bound
  ImGui_ImplOpenGL3_RenderDrawData(&part);
}

// Repaints the frame whole over what was painted (the same framebuffer: another format
// could round colours differently) and compares the two.
void Compositor::check(const RepaintPlan& plan, const Backdrop& backdrop, const ImDrawData& ui,
                       gl::RenderTarget* into, int fbWidth, int fbHeight) {
  const auto read = [&] {
    if (into) return into->readPixelsRgb();
    gl::bindDefaultFramebuffer(fbWidth, fbHeight);
    return gl::readPixelsRgb(fbWidth, fbHeight);
  };
  const std::vector<unsigned char> shown = read();
  RepaintPlan everything;
  everything.full = true;
  everything.repaint.assign(plan.repaint.size(), true);
  paint(everything, backdrop, ui, into, fbWidth, fbHeight);
  const std::vector<unsigned char> expected = read();
  changed_ = {PixelRect{0, 0, fbWidth, fbHeight}};

  ++checks_.frames;
  if (!plan.full) ++checks_.partialFrames;
  long long differing = 0;
  for (std::size_t p = 0; p + 2 < shown.size() && p + 2 < expected.size(); p += 3) {
    if (shown[p] == expected[p] && shown[p + 1] == expected[p + 1] &&
        shown[p + 2] == expected[p + 2])
      continue;
    if (differing++ == 0 && !checks_.firstMismatch) {
      const auto pixel = static_cast<int>(p / 3);
      // Rows were read bottom first.
      checks_.firstMismatch = "frame " + std::to_string(checks_.frames) + ": pixel (" +
                              std::to_string(pixel % fbWidth) + ", " +
                              std::to_string(fbHeight - 1 - pixel / fbWidth) +
                              ") differs from a full redraw";
    }
  }
  if (differing > 0) ++checks_.mismatchedFrames;
}

}  // namespace ew::ui
