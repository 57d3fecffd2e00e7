#include "ui/panels/profile_panel.h"

#include "ui/widgets/flow.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/render/palette.h"
#include "ui/widgets/plot.h"

namespace ew::ui {

namespace {

// Mode::Clip: where each start of the camera fit ended (azimuth, reprojection RMS): the
// image's ambiguities (depth reversal, mirror, facing) as separate minima, the best marked.
void drawClipStarts(const AppState& s, const FrameContext& ctx) {
  if (!s.clip.fit()) {
    ImGui::TextDisabled(s.clip.fits.running() ? "fitting…" : "no fit");
    return;
  }
  const auto& starts = s.clip.fit()->rec.fit.starts;
  std::vector<double> alpha, rms, bestAlpha, bestRms;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    auto& xs = i == 0 ? bestAlpha : alpha;
    auto& ys = i == 0 ? bestRms : rms;
    xs.push_back(starts[i].alphaDeg);
    ys.push_back(std::max(starts[i].reprojectionRmsPx, 1e-3));
  }
  const PlotSeries series[] = {
      {"where a start ended", alpha, rms, toImU32(palette::kOtherMinimum), 0.0f, false, true},
      {"the fit", bestAlpha, bestRms, toImU32(palette::kCameraEstimate), 0.0f, false, true}};
  PlotSpec spec;
  spec.xLabel = "camera azimuth α (°)";
  spec.yLabel = "reprojection RMS (px)";
  spec.xUnit = "°";
  spec.yLog = true;
  spec.yFromZero = false;
  spec.valueFormat = "%.2f";
  drawPlot("##starts", ImGui::GetContentRegionAvail(), spec, series, ctx.scale);
}

// Colours from the theme, so the curve reads on the light and projector themes as on the dark
// (a fixed near-white curve vanished on the light theme: issue 18).
ImU32 curveColour() { return ImGui::GetColorU32(ImGuiCol_Text, 0.9f); }
ImU32 gridColour() { return ImGui::GetColorU32(ImGuiCol_Border, 0.45f); }

// The view-angle axis both plots share: a faint frame from a to b, a line every 90° from
// −180° to 180° and labels under b (the labels kept inside [labelLeft, b.x]).
void drawCircleAxis(ImDrawList* dl, ImVec2 a, ImVec2 b, float labelLeft, float scale) {
  const auto X = [&](double deg) { return a.x + static_cast<float>((deg + 180.0) / 360.0) * (b.x - a.x); };
  dl->AddRectFilled(a, b, ImGui::GetColorU32(ImGuiCol_FrameBg));
  // A narrow panel labels every 180° only: five labels would run into each other.
  const bool everyQuarter = b.x - a.x > 6.0f * ImGui::CalcTextSize("-180°").x;
  for (int deg = -180; deg <= 180; deg += 90) {
    dl->AddLine(ImVec2(X(deg), a.y), ImVec2(X(deg), b.y), gridColour());
    if (!everyQuarter && deg % 180 != 0) continue;
    char buf[16];
    std::snprintf(buf, sizeof buf, "%d°", deg);
    const float tw = ImGui::CalcTextSize(buf).x;
    dl->AddText(ImVec2(std::clamp(X(deg) - tw * 0.5f, labelLeft, b.x - tw), b.y + 2.0f * scale),
                ImGui::GetColorU32(ImGuiCol_TextDisabled), buf);
  }
}

// The snippet engine over the circle: each snippet's own estimated α (a dot per snippet, in time
// order top to bottom), the clip's (their circular median) and the true α.
void drawSnippetAngles(const ReconBase& r, const FrameContext& ctx) {
  const SnippetSequence& seq = *r.snippets;
  ImGui::TextDisabled("each snippet's own est. α (dots, first at the top); the clip's: %.1f° (their median)",
                      r.alphaUsedDeg);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float textH = ImGui::GetTextLineHeight();
  const ImVec2 a{p0.x + 6.0f * ctx.scale, p0.y + 4.0f * ctx.scale};
  const ImVec2 b{p0.x + avail.x - 6.0f * ctx.scale, p0.y + avail.y - textH - 6.0f * ctx.scale};
  auto X = [&](double deg) { return a.x + static_cast<float>((deg + 180.0) / 360.0) * (b.x - a.x); };
  drawCircleAxis(dl, a, b, p0.x, ctx.scale);
  dl->AddLine(ImVec2(X(r.alphaTrueDeg), a.y), ImVec2(X(r.alphaTrueDeg), b.y), toImU32(palette::kCamera),
              1.5f * ctx.scale);
  dl->AddLine(ImVec2(X(r.alphaUsedDeg), a.y), ImVec2(X(r.alphaUsedDeg), b.y), toImU32(palette::kCameraEstimate),
              1.5f * ctx.scale);
  const std::size_t n = seq.freeAlphaDeg.size();
  for (std::size_t k = 0; k < n; ++k) {
    const float y = a.y + (b.y - a.y) * (static_cast<float>(k) + 0.5f) / static_cast<float>(std::max<std::size_t>(n, 1));
    dl->AddCircleFilled(ImVec2(X(seq.freeAlphaDeg[k]), y), 3.5f * ctx.scale, curveColour());
  }
  ImGui::Dummy(avail);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%zu snippets of %d frames; true α %.1f°, clip's est. α %.1f°", n,
                      seq.snippets.empty() ? 0 : static_cast<int>(seq.snippets.front().snippet.size() / 45),
                      r.alphaTrueDeg, r.alphaUsedDeg);
}

// Compare mode, over the J(α) plot: the snippet and skeleton engines' α̂ as lines in their
// colours, and each snippet's own α̂ as a dot in a band along the foot of the plot.
template <class XFn>
void drawOtherEngines(const CompareResult& compare, const XFn& X, ImVec2 a, ImVec2 b, float scale) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (const auto& e : compare.engines) {
    if (e.engine == EngineKind::Eigenwalker || !e.base) continue;
    const ImU32 colour = toImU32(palette::kEngineRight[static_cast<std::size_t>(e.engine)]);
    const float x = X(e.base->alphaUsedDeg);
    for (float y = a.y; y < b.y; y += 8.0f * scale)  // dashed: the eigenwalker's α̂ is the solid one
      dl->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 4.0f * scale, b.y)), colour, 2.0f * scale);
    if (!e.base->snippets) continue;
    const auto& alphas = e.base->snippets->freeAlphaDeg;
    const float band = 0.18f * (b.y - a.y);
    for (std::size_t k = 0; k < alphas.size(); ++k) {
      const float y = b.y - band + band * (static_cast<float>(k) + 0.5f) / static_cast<float>(alphas.size());
      dl->AddCircleFilled(ImVec2(X(alphas[k]), y), 2.5f * scale, colour);
    }
  }
}

// J(α) of the eigenwalker's unknown-view search on a log axis, its minima and the true α. In
// compare mode (`compare`) every other engine's α̂ over it: the skeleton engine's as a line,
// the snippet engine's clip α̂ as a line and each snippet's own α̂ as a dot along the foot.
void drawProfile(const ReconBase& r, const ViewSearch& vs, const FrameContext& ctx, const CompareResult* compare) {
  if (compare) {  // each engine's α̂ in its colour (the legend of the views names them)
    ImGui::TextDisabled("est. α");
    for (const auto& e : compare->engines) {
      sameLineOrWrap(ImGui::CalcTextSize("-000.0°").x);
      const ImVec4 colour = toImVec4(palette::kEngineRight[static_cast<std::size_t>(e.engine)]);
      if (e.base)
        ImGui::TextColored(colour, "%.1f°", e.base->alphaUsedDeg);
      else
        ImGui::TextColored(colour, "none");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", engineName(e.engine));
    }
    sameLineOrWrap(ImGui::CalcTextSize("true -000.0°").x);
    ImGui::TextDisabled("true %.1f°", r.alphaTrueDeg);
  }
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float textH = ImGui::GetTextLineHeight();
  const float left = ImGui::CalcTextSize("1e+00").x + 8.0f * ctx.scale;
  const ImVec2 a{p0.x + left, p0.y + 4.0f * ctx.scale};
  const ImVec2 b{p0.x + avail.x - 6.0f * ctx.scale, p0.y + avail.y - textH - 6.0f * ctx.scale};
  const Eigen::Index n = vs.scanObjective.size();
  double lo = vs.scanObjective.minCoeff(), hi = vs.scanObjective.maxCoeff();
  lo = std::log10(std::max(lo, 1e-3));
  hi = std::log10(std::max(hi, 1e-2));
  if (hi - lo < 0.5) hi = lo + 0.5;
  lo = std::floor(lo);
  hi = std::ceil(hi);
  auto X = [&](double deg) { return a.x + static_cast<float>((deg + 180.0) / 360.0) * (b.x - a.x); };
  auto Y = [&](double j) {
    const double t = (std::log10(std::max(j, 1e-3)) - lo) / (hi - lo);
    return b.y - static_cast<float>(t) * (b.y - a.y);
  };
  drawCircleAxis(dl, a, b, p0.x, ctx.scale);
  const ImU32 gridC = gridColour();
  const ImU32 labelC = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  for (int e = static_cast<int>(lo); e <= static_cast<int>(hi); ++e) {
    const float y = Y(std::pow(10.0, e));
    dl->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), gridC);
    char buf[16];
    std::snprintf(buf, sizeof buf, "1e%d", e);
    dl->AddText(ImVec2(p0.x, y - textH * 0.5f), labelC, buf);
  }
  // True α.
  const ImU32 trueC = toImU32(palette::kCamera);
  dl->AddLine(ImVec2(X(r.alphaTrueDeg), a.y), ImVec2(X(r.alphaTrueDeg), b.y), trueC, 1.5f * ctx.scale);
  // The curve.
  std::vector<ImVec2> pts(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    pts[static_cast<std::size_t>(i)] = ImVec2(X(vs.scanAlphaDeg(i)), Y(vs.scanObjective(i)));
  dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), curveColour(), 0, 1.8f * ctx.scale);
  // Minima.
  for (std::size_t m = 0; m < vs.minima.size(); ++m) {
    const auto& mn = vs.minima[m];
    const ImVec2 c{X(mn.alphaDeg), Y(mn.objective)};
    const ImU32 col = m == 0 ? toImU32(palette::kCameraEstimate) : toImU32(palette::kOtherMinimum);
    dl->AddCircleFilled(c, (m == 0 ? 5.5f : 4.0f) * ctx.scale, col);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.1f°%s%s", mn.alphaDeg, mn.mirrorOfBest && m ? " mirror" : "",
                  mn.facingOfBest && m ? " facing" : "");
    const float tw = ImGui::CalcTextSize(buf).x;
    // The best one's figure in the text's colour: its dot's red is too dark to read small on
    // the dark plot.
    dl->AddText(ImVec2(std::clamp(c.x - tw * 0.5f, a.x, b.x - tw), c.y - textH - 5.0f * ctx.scale),
                m == 0 ? ImGui::GetColorU32(ImGuiCol_Text) : col, buf);
  }
  if (compare) drawOtherEngines(*compare, X, a, b, ctx.scale);
  ImGui::Dummy(avail);
  if (ImGui::IsItemHovered()) {
    const double deg = std::clamp((ImGui::GetMousePos().x - a.x) / (b.x - a.x) * 360.0 - 180.0, -180.0, 180.0);
    const auto i = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::lround(deg + 179.0)), 0, n - 1);
    ImGui::SetTooltip("α = %.0f°: J = %.3g mm²\n%zu local minima; best est. α = %.2f°", vs.scanAlphaDeg(i),
                      vs.scanObjective(i), vs.minima.size(), vs.minima.front().alphaDeg);
  }
}

}  // namespace

void ProfilePanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  const bool snippets = s.derived.recon() && s.derived.recon()->engine == EngineKind::Snippet &&
                        !(s.doc.compareEngines && s.doc.mode == Mode::Reconstruct);
  const char* title = s.doc.mode == Mode::Clip ? fittingTitle("Camera fit: where each start ended###profile",
                                                             "Camera fit's starts###profile", rect.size.x)
                      : snippets             ? fittingTitle("View angle of each snippet###profile",
                                                            "Snippets' view angles###profile", rect.size.x)
                                             : fittingTitle("View-angle profile J(α)###profile", "J(α)###profile",
                                                            rect.size.x);
  if (beginPanel(ctx.backdrop, title, rect, ImGuiWindowFlags_NoScrollbar)) {
    const ReconBase* r = s.derived.recon();
    // Compare mode: the eigenwalker's J(α) with every engine's α̂ over it, whichever engine is selected.
    const CompareResult* compare =
        s.doc.compareEngines && s.doc.mode == Mode::Reconstruct ? s.derived.compare() : nullptr;
    const CompareEntry* compareEigen = compare ? compare->of(EngineKind::Eigenwalker) : nullptr;
    if (s.doc.mode == Mode::Clip) {
      drawClipStarts(s, ctx);
    } else if (s.doc.mode == Mode::Explore) {
      ImGui::TextDisabled("reconstruct mode only");
    } else if (!s.doc.recon.unknownAngle) {
      textDisabledWrapped("The view angle is known: J(α) is scanned when it is not.");
      const char* label = buttonWidth("Estimate it (unknown view angle)") <= ImGui::GetContentRegionAvail().x
                              ? "Estimate it (unknown view angle)"
                              : "Estimate α";
      if (ImGui::Button(label)) actions::setUnknownAngle(s, true);
    } else if (r && r->snippets) {
      drawSnippetAngles(*r, ctx);
    } else if (r && r->engine == EngineKind::Skeleton) {
      ImGui::TextWrapped("The skeleton engine has no J(α) to scan: it reads the view from the poses it "
                         "reconstructs (the body's forward, up × hip line, averaged over the clip's frames).");
      ImGui::TextWrapped("est. α = %.1f° · true α = %.1f° · error %.1f°", r->alphaUsedDeg, r->alphaTrueDeg,
                         viewAngleErrorDeg(r->alphaUsedDeg, r->alphaTrueDeg));
    } else if (compareEigen && compareEigen->base && compareEigen->base->search) {
      drawProfile(*compareEigen->base, *compareEigen->base->search, ctx, s.derived.compare());
    } else if (r && r->search) {
      drawProfile(*r, *r->search, ctx, nullptr);
    } else {
      ImGui::TextDisabled("no search yet");
    }
  }
  ImGui::End();
}

}  // namespace ew::ui
