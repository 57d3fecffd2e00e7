#include "ui/panels/clip_controls.h"

#include <imgui.h>

#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include "core/camera/focal_length.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/section_title.h"

namespace ew::ui {

namespace {

// Runs an action; a value it refuses goes to the log (the widgets keep values in range).
template <class F>
void apply(AppState& s, F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    s.log.error(e.what());
  }
}

void layoutCombo(AppState& s, const ClipSettings& c, const ClipResult* r) {
  const std::string guessed = r ? "guess (" + r->rec.trial.layout->name + ")" : std::string("guess");
  const std::string preview = c.layout.empty() ? guessed : c.layout;
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo("##layout", preview.c_str())) {
    if (ImGui::Selectable(guessed.c_str(), c.layout.empty())) apply(s, [&] { actions::setClipLayout(s, ""); });
    for (const auto& l : keypointLayouts()) {
      // Only layouts with the file's point count can read it.
      const bool fits = !r || static_cast<int>(l.points.size()) == static_cast<int>(r->rec.trial.layout->points.size());
      if (!fits) continue;
      if (ImGui::Selectable(l.name.c_str(), c.layout == l.name)) apply(s, [&] { actions::setClipLayout(s, l.name); });
    }
    ImGui::EndCombo();
  }
}

void personCombo(AppState& s, const ClipSettings& c, const ClipResult& r) {
  const auto& people = r.rec.trial.people;
  if (people.size() < 2) return;
  char preview[64];
  std::snprintf(preview, sizeof preview, c.person < 0 ? "the walker (track %d)" : "track %d", r.rec.trial.chosen + 1);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo("##person", preview)) {
    if (ImGui::Selectable("the walker (who crosses the image)", c.person < 0))
      apply(s, [&] { actions::setClipPerson(s, -1); });
    for (std::size_t i = 0; i < people.size(); ++i) {
      char label[96];
      std::snprintf(label, sizeof label, "track %zu: %zu frames, moves %.0f px", i + 1, people[i].frames.size(),
                    people[i].travelPx);
      if (ImGui::Selectable(label, c.person == static_cast<int>(i)))
        apply(s, [&] { actions::setClipPerson(s, static_cast<int>(i)); });
    }
    ImGui::EndCombo();
  }
}

// The image's size: typed as 1920x1080 (Enter); empty takes the file's or the video's again.
// Shown with where it came from; a clip whose points are fractions of the image waits for it.
void imageSizeField(AppState& s, const ClipSettings& c, const ClipResult* r) {
  textDisabledWrapped("image size (WxH, Enter)");
  static char text[32] = "";
  std::string shown;
  if (c.imageSize) {
    shown = std::to_string(c.imageSize->width) + "x" + std::to_string(c.imageSize->height);
  } else if (r && r->rec.trial.imageSize) {
    const auto& size = *r->rec.trial.imageSize;
    shown = std::to_string(size.width) + "x" + std::to_string(size.height) + " (" + r->rec.trial.imageSizeSource + ")";
  }
  ImGui::SetNextItemWidth(-1.0f);
  const char* hint = shown.empty() ? "unknown: e.g. 1920x1080" : shown.c_str();
  if (ImGui::InputTextWithHint("##imagesize", hint, text, sizeof text, ImGuiInputTextFlags_EnterReturnsTrue)) {
    const std::string typed = text;
    apply(s, [&] {
      actions::setClipImageSize(s, typed.empty() ? std::nullopt
                                                 : std::optional(parseKeypointImageSize(typed, "image size")));
    });
    text[0] = '\0';
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The picture's size in pixels: what a MediaPipe CSV's or YOLO labels' coordinates are "
                      "fractions of, and where the camera's principal point is expected. Empty + Enter: the "
                      "file's, else the video's found beside the keypoints");
}

// A camera value: "fix" holds it (starting from the estimate); unfixed, the estimate shows.
template <class Setter>
void heldValue(AppState& s, const char* id, const char* label, std::optional<double> held, double estimate,
               float lo, float hi, const char* format, bool typed, Setter set) {
  ImGui::PushID(id);
  bool fixed = held.has_value();
  if (ImGui::Checkbox("##fix", &fixed)) apply(s, [&] { set(fixed ? std::optional<double>(estimate) : std::nullopt); });
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Hold %s at the value you set (unticked: estimated)", label);
  ImGui::SameLine();
  float v = static_cast<float>(held.value_or(estimate));
  ImGui::BeginDisabled(!fixed);
  ImGui::SetNextItemWidth(-1.0f);
  const bool changed = typed ? ImGui::InputFloat("##v", &v, 0.0f, 0.0f, format, ImGuiInputTextFlags_EnterReturnsTrue)
                             : ImGui::SliderFloat("##v", &v, lo, hi, format, ImGuiSliderFlags_AlwaysClamp);
  if (changed && fixed) apply(s, [&] { set(std::optional<double>(v)); });
  ImGui::EndDisabled();
  ImGui::PopID();
}

}  // namespace

// The file's choices (layout, rate, person), for a pose estimator's clip.
static void drawClipSource(AppState& s, const ClipSettings& c, const ClipResult* r);
// The camera values the fit may hold, and how the last fit went.
static void drawCameraHolds(AppState& s, const ClipSettings& c, const ClipResult* r);

void drawClipControls(AppState& s) {
  if (!s.clip.settings) return;
  const ClipSettings c = *s.clip.settings;
  const ClipResult* r = s.clip.fit().get();
  if (c.detected) {
    // The detector's clip: its source is the video above; who walks can be picked.
    if (r && r->rec.trial.people.size() > 1) {
      sectionTitle("Walker");
      personCombo(s, c, *r);
      textDisabledWrapped(r->rec.trial.chosenReason.c_str());
    }
  } else if (!c.tracked) {
    drawClipSource(s, c, r);
  }
  drawCameraHolds(s, c, r);
  if (!c.tracked && !c.detected && ImGui::Button("Close the clip")) actions::closeClip(s);
}

static void drawClipSource(AppState& s, const ClipSettings& c, const ClipResult* r) {
  sectionTitle("Keypoint clip");
  ImGui::TextWrapped("%s", c.path.filename().string().c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.path.string().c_str());
  if (r) {
    const auto& t = r->rec.trial;
    char summary[160];
    std::snprintf(summary, sizeof summary, "%s · %d frames · %d %s", t.format.c_str(), t.frameCount, t.maxPeople,
                  t.maxPeople == 1 ? "person" : "people at most");
    textDisabledWrapped(summary);
  }
  textDisabledWrapped("layout");
  layoutCombo(s, c, r);
  float fps = static_cast<float>(c.fps);
  ImGui::SetNextItemWidth(-1.0f);
  const char* fpsFormat = c.fps > 0.0                                       ? "%.2f fps"
                          : !r || r->rec.trial.rateAssumed                   ? "30 fps (assumed)"
                          : r->rec.trial.rateSource.starts_with("the video") ? "%.2f fps (the video's)"
                                                                             : "the file's rate";
  if (c.fps <= 0.0 && r && !r->rec.trial.rateAssumed) fps = static_cast<float>(r->rec.trial.rateHz);
  if (ImGui::InputFloat("##fps", &fps, 0.0f, 0.0f, fpsFormat, ImGuiInputTextFlags_EnterReturnsTrue))
    apply(s, [&] { actions::setClipFps(s, fps); });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The video's frame rate (JSON stores none; 0 = the file's, else the video's beside "
                      "the keypoints, else 30)");
  imageSizeField(s, c, r);
  if (r) personCombo(s, c, *r);
}

// A calibration file gives the focal length, the principal point and the lens: said instead of
// the focal length's field, with a way back to estimating it.
static void drawCalibration(AppState& s, const ClipSettings& c) {
  std::string text = "calibration " + c.calibrationFile.filename().string();
  if (!c.calibrationCamera.empty()) text += " (" + c.calibrationCamera + ")";
  ImGui::TextWrapped("%s: focal length, principal point and lens", text.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.calibrationFile.string().c_str());
  if (ImGui::SmallButton("Estimate the camera instead"))
    apply(s, [&] { actions::setClipCalibration(s, {}, ""); });
}

static void drawCameraHolds(AppState& s, const ClipSettings& c, const ClipResult* r) {
  sectionTitle("Camera (tick to hold a value)");
  const WalkCamera* cam = r ? &r->rec.fit.camera : nullptr;
  if (!c.calibrationFile.empty()) {
    drawCalibration(s, c);
  } else if (!cam || cam->model == CameraModel::Pinhole) {
    textDisabledWrapped("focal length (type, Enter; or drop a calibration .toml)");
    heldValue(s, "focal", "the focal length", c.focalPx, cam ? cam->focalPx : 1500.0, static_cast<float>(kMinFocalPx),
              static_cast<float>(kMaxFocalPx), "%.0f px", true,
              [&](std::optional<double> v) { actions::setClipFocal(s, v); });
  }
  textDisabledWrapped("elevation (looking down)");
  heldValue(s, "elevation", "the elevation", c.elevationDeg, cam ? cam->elevationDeg : 10.0, -10.0f, 60.0f, "%.1f°",
            false, [&](std::optional<double> v) { actions::setClipElevation(s, v); });
  if (c.horizonRowPx && !c.elevationDeg) {
    bool hold = c.holdToHorizon;
    if (ImGui::Checkbox("hold to the horizon", &hold))
      apply(s, [&] { actions::setClipHoldToHorizon(s, hold); });
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The horizon the video's level lines give (row %.0f px, the dashed line).\n"
                        "Held, the fit keeps its camera's height over the walker near it, as it does\n"
                        "for a detected walker. A track's noisier joints held to it gave a camera\n"
                        "farther off, so a track's fit is only checked against it unless this is ticked\n"
                        "(docs/CAMERA.md, \"The scene's horizon\").",
                        *c.horizonRowPx);
  }
  textDisabledWrapped("azimuth α");
  heldValue(s, "azimuth", "the azimuth", c.alphaDeg, cam ? cam->alphaDeg : 0.0, -180.0f, 180.0f, "%.1f°", false,
            [&](std::optional<double> v) { actions::setClipAzimuth(s, v); });

  if (s.clip.fits.running()) {
    ImGui::TextDisabled("fitting…");
  } else if (!s.clip.fits.error().empty() && s.clip.settings && s.clip.fits.failed(*s.clip.settings)) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.55f, 1.0f));
    ImGui::TextWrapped("These settings do not fit: %s", s.clip.fits.error().c_str());
    ImGui::PopStyleColor();
  } else if (r) {
    ImGui::TextDisabled("fitted in %.0f ms", 1000.0 * r->seconds);
  }
}

}  // namespace ew::ui
