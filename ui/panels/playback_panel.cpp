#include "ui/panels/playback_panel.h"

#include <algorithm>
#include <cstdio>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {

namespace {

// A frame step's tooltip: how long the frame is (a clip's or video's own, or 1/60 s).
void stepTooltip(const AppState& s, const char* way) {
  if (!ImGui::IsItemHovered()) return;
  const double stepS = actions::frameStepS(s);
  ImGui::SetTooltip("step %s one frame (1/%.0f s; %s)", way, 1.0 / stepS, way[0] == 'b' ? "←" : "→");
}

// A keypoint clip plays its frames: the slider picks one (the 3D view follows), counted from 1
// as the 2D view's caption counts them.
void clipFrameSlider(AppState& s, const ClipResult& c, bool narrow) {
  const int shown = clipFrameAt(c, s.view.playback.cycles);
  int frame = shown + 1;
  char format[64];
  std::snprintf(format, sizeof format, narrow ? "%%d / %d" : "frame %%d / %d (%.2f s)", c.rec.trial.frameCount,
                shown / c.rec.trial.rateHz);
  if (ImGui::SliderInt("##frame", &frame, 1, c.rec.trial.frameCount, format, ImGuiSliderFlags_AlwaysClamp))
    actions::setClipFrame(s, frame);
  if (narrow && ImGui::IsItemHovered()) ImGui::SetTooltip("frame (%.2f s)", shown / c.rec.trial.rateHz);
}

// A video is played in its own frame numbers (from 0, as the video's scrubber, the keyframe
// files and `track --first/--last` count them): over the tracked range when its track's fit
// is shown, else over the whole video.
void videoFrameSlider(AppState& s, bool narrow) {
  const VideoSession& v = *s.video.session;
  const bool tracked = !actions::stepsVideoFrames(s);
  int frame = actions::shownVideoFrame(s);
  const double seconds = v.fps() > 0.0 ? frame / v.fps() : 0.0;
  char format[64];
  std::snprintf(format, sizeof format, narrow ? "%%d of %d" : "frame %%d of %d (%.2f s)", v.frameCount(), seconds);
  const auto fit = actions::videoFitFrames(s);
  const int first = tracked && fit ? fit->first : 0;
  const int last = tracked && fit ? fit->second : std::max(v.frameCount() - 1, 0);
  if (ImGui::SliderInt("##frame", &frame, first, last, format, ImGuiSliderFlags_AlwaysClamp))
    actions::setVideoFrame(s, frame);
  if (narrow && ImGui::IsItemHovered()) ImGui::SetTooltip("video frame (%.2f s)", seconds);
}

}  // namespace

bool playsFrames(const AppState& s) {
  return actions::stepsVideoFrames(s) ||
         (s.doc.mode == Mode::Clip && s.clip.fit() && actions::playbackStrideHz(s) > 0.0);
}

void drawFrameSlider(AppState& s, bool narrow) {
  if (actions::stepsVideoFrames(s) || actions::showsVideoFit(s))
    videoFrameSlider(s, narrow);
  else if (s.clip.fit())
    clipFrameSlider(s, *s.clip.fit(), narrow);
}

void PlaybackPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  auto& p = s.view.playback;
  if (beginPanel(ctx.backdrop, "##playback", rect, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    const float bw = 36.0f * ctx.scale;
    if (ImGui::Button("|<", ImVec2(bw, 0))) actions::stepFrame(s, -1);
    stepTooltip(s, "back");
    ImGui::SameLine();
    if (ImGui::Button(p.playing ? "||" : ">", ImVec2(bw * 1.4f, 0))) p.playing = !p.playing;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("play / pause (space)");
    ImGui::SameLine();
    if (ImGui::Button(">|", ImVec2(bw, 0))) actions::stepFrame(s, 1);
    stepTooltip(s, "on");
    ImGui::SameLine();
    // A narrow row (a small window, a large UI scale) shares what is left between the two
    // sliders and shortens their labels rather than pushing the phase slider off the edge.
    const float rest = ImGui::GetContentRegionAvail().x;
    const bool narrow = rest < 360.0f * ctx.scale;
    ImGui::SetNextItemWidth(narrow ? 0.4f * rest : 150.0f * ctx.scale);
    ImGui::SliderFloat("##speed", &p.speed, 0.1f, 2.0f, narrow ? "%.2f×" : "speed %.2f×", ImGuiSliderFlags_AlwaysClamp);
    if (narrow && ImGui::IsItemHovered()) ImGui::SetTooltip("playback speed");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (playsFrames(s)) {
      drawFrameSlider(s, narrow);
    } else {
      float phase = static_cast<float>(p.phase());
      if (ImGui::SliderFloat("##phase", &phase, 0.0f, 1.0f, narrow ? "phase %.2f" : "gait phase %.3f",
                             ImGuiSliderFlags_AlwaysClamp)) {
        p.setPhase(phase);
        p.playing = false;
      }
    }
  }
  ImGui::End();
}

}  // namespace ew::ui
