#include "ui/panels/view_captions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/panels/camera_text.h"
#include "ui/panels/clip_view.h"
#include "ui/render/palette.h"

namespace ew::ui {
namespace {

// The 3D view's legend: what it draws, in its colours.
std::vector<LegendItem> walkerReconstructionLegend(const AppState& s) {
  const auto& o = s.view.overlays;
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const ReconBase* r = s.derived.recon();
  std::vector<LegendItem> legend;
  const bool compare = reconstruct && s.doc.compareEngines && s.derived.compare();
  if (o.pointLights) {
    legend.push_back({palette::kInputPoint, reconstruct ? "reconstructed joints (point-lights)" : "joints (point-lights)", false});
  } else if (compare) {
    for (const auto& e : s.derived.compare()->engines) {
      const auto k = static_cast<std::size_t>(e.engine);
      if (!s.doc.compareShown[k]) continue;
      char label[96];
      if (e.display)
        std::snprintf(label, sizeof label, "%s: MPJPE %.1f mm", engineName(e.engine), e.display->mpjpeMm);
      else
        std::snprintf(label, sizeof label, "%s: no answer", engineName(e.engine));
      legend.push_back({palette::kEngineRight[k], label, false});
    }
    if (o.ghost) legend.push_back({palette::kGhostRight, "ground truth (ghost)", false});
  } else if (reconstruct) {
    legend.push_back({palette::kReconRight, "reconstruction (right side darker)", false});
    if (o.ghost) legend.push_back({palette::kGhostRight, "ground truth (ghost)", false});
    if (o.errorLines) legend.push_back({palette::kError, "3D error per joint", true});
    if (reconstruct && r &&
        std::any_of(r->modelEstimated.begin(), r->modelEstimated.end(),
                    [](bool b) { return b; }))
      legend.push_back(
          {palette::kModelEstimated, "model-estimated joint (not measured)", false});
  } else {
    legend.push_back({palette::kReconRight, "synthesised walker", false});
  }
  if (o.cameraGlyph) {
    legend.push_back({palette::kCamera, "camera of the 2D view", true});
    // Compare mode draws no estimated camera: each engine has its own α̂ (the profile panel
    // shows them all).
    if (reconstruct && !compare && s.doc.recon.unknownAngle)
      legend.push_back({palette::kCameraEstimate, "estimated camera (est. α)", true});
  }
  return legend;
}

}  // namespace

std::string quizMessage(const AppState& s) {
  if (!s.quiz.running()) return "";
  return "Which way is it walking? Trial " + std::to_string(s.quiz.staircase->trials().size() + 1) +
         " · answer ← or →";
}

ViewCaption stageInputCaption(const AppState& s) {
  if (s.quiz.running()) return {"2D input", quizMessage(s), {{palette::kInputPoint, "dots", false}}};
  const std::optional<StageWalker> walker = stageWalker2d(s);
  const StageFeature& stage = s.stage;
  std::vector<LegendItem> legend{{palette::kInputPoint, stage.display.maskDots > 0 ? "the walker's dots and the noise dots (alike)" : "the walker's dots", false}};
  if (stage.depthReversed)
    legend.push_back({palette::kOtherMinimum, "depth-reversed walker: the same image at α, seen level", true});
  char sub[200];
  std::snprintf(sub, sizeof sub, "%s at α = %.0f°: %s", walker ? walker->name.c_str() : "the walker",
                walker ? stageAzimuthDeg(s, walker->alphaDeg) : 0.0, stageDescription(stage).c_str());
  return {"2D input", sub, std::move(legend)};
}

ViewCaption stageReconstructionCaption(const AppState& s) {
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const char* title = reconstruct ? "3D reconstruction" : "Gait space";
  if (s.quiz.running()) return {title, "hidden during the quiz", {}};
  const StageFeature& stage = s.stage;
  const bool figure = displayKeepsTheForm(stage.display) && !s.view.overlays.pointLights;
  std::vector<LegendItem> legend{
      {figure ? palette::kReconRight : palette::kInputPoint, reconstruct ? "the reconstruction" : "the synthesised walker", false}};
  if (stage.depthReversed)
    legend.push_back({figure ? palette::kEngineRight[1] : palette::kOtherMinimum,
                      "depth-reversed beside it: the same level image at α", false});
  if (s.view.overlays.cameraGlyph) legend.push_back({palette::kCamera, "camera of the 2D view", true});
  return {title, stageDescription(stage), std::move(legend)};
}

ViewCaption walkerInputCaption(const AppState& s) {
  if (stageDrawsViews(s)) return stageInputCaption(s);
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const auto& o = s.view.overlays;
  const ReconBase* r = s.derived.recon();
  std::vector<LegendItem> legend{{palette::kInputPoint, "input joints (u, v)", false}};
  const bool anyEstimated =
      reconstruct && r && std::any_of(r->modelEstimated.begin(), r->modelEstimated.end(), [](bool b) { return b; });
  if (anyEstimated) legend.push_back({palette::kModelEstimated, "model-estimated (not measured)", false});
  if (reconstruct && o.reprojection && !o.pointLights) {
    legend.push_back({palette::kReconRight,
                      s.doc.recon.unknownAngle ? "reconstruction seen at est. α" : "reconstruction seen at α", true});
    legend.push_back({palette::kError, "2D residual", true});
  }
  char sub[160];
  if (reconstruct) {
    if (r && r->engine == EngineKind::Snippet)
      std::snprintf(sub, sizeof sub, "orthographic, α = %.1f°, walking across at %.2f m/s",
                    s.doc.recon.alphaDeg, r->speedMps);
    else if (r && r->engine == EngineKind::Skeleton)
      std::snprintf(sub, sizeof sub, "orthographic, α = %.1f°, walking in place", s.doc.recon.alphaDeg);
    else
      std::snprintf(sub, sizeof sub, "orthographic view at α = %.1f°, as the reconstruction sees it",
                    s.doc.recon.alphaDeg);
  } else {
    std::snprintf(sub, sizeof sub, "the synthesised walker projected at α = %.1f°", s.doc.recon.alphaDeg);
  }
  return {"2D input", sub, std::move(legend)};
}

ViewCaption clipInputCaption(const AppState& s, int shown, bool onScreen) {
  const ClipReconstruction& rec = s.clip.fit()->rec;
  char zoom[48] = "";
  if (onScreen && s.clip.zoom > 1.0) std::snprintf(zoom, sizeof zoom, " · zoom %.1f×", s.clip.zoom);
  char sub[260];
  std::snprintf(sub, sizeof sub, "%s · %s · frame %d / %d (%.2f s) · pixels, y down%s",
                rec.trial.format.c_str(), rec.trial.layout->name.c_str(), shown + 1, rec.trial.frameCount,
                shown / rec.trial.rateHz, zoom);
  // The largest residual of this frame, named.
  int worst = -1;
  double worstPx = 0.0;
  for (int j = 0; j < kJointCount; ++j) {
    const double du = rec.reprojectedPx(shown, 2 * j) - rec.trial.jointsPx(shown, 2 * j);
    const double dv = rec.reprojectedPx(shown, 2 * j + 1) - rec.trial.jointsPx(shown, 2 * j + 1);
    const double d = std::hypot(du, dv);
    if (std::isfinite(d) && d > worstPx) worst = j, worstPx = d;
  }
  std::vector<LegendItem> legend{{palette::kInputPoint, "keypoints (u, v px)", false},
                                 {palette::kCamera, "principal point (est.)", true}};
  if (!s.view.overlays.pointLights && !otherPeopleAt(rec.trial, shown).empty())
    legend.push_back({palette::kOtherPerson, "other people (Clip: person)", true});
  if (s.view.overlays.reprojection && !s.view.overlays.pointLights) {
    legend.push_back({palette::kReconRight, "3D walker through the est. camera", true});
    char residual[96];
    if (worst >= 0) {
      const std::string name(jointName(static_cast<Joint>(worst)));
      std::snprintf(residual, sizeof residual, "residual (largest: %s %.1f px)", name.c_str(), worstPx);
    } else {
      std::snprintf(residual, sizeof residual, "residual");
    }
    legend.push_back({palette::kError, residual, true});
  }
  return {"2D input (keypoints)", sub, std::move(legend)};
}

ViewCaption videoInputCaption(const AppState& s, int frame, bool decoding, bool onScreen) {
  const VideoSession& v = *s.video.session;
  const VideoInfo& info = v.frames->info();
  char zoom[48] = "";
  if (onScreen && v.zoom > 1.0) std::snprintf(zoom, sizeof zoom, " · zoom %.1f×", v.zoom);
  char sub[280];
  std::snprintf(sub, sizeof sub, "%s · %d×%d · frame %d of %d (%.2f s)%s%s",
                v.path.filename().string().c_str(), info.widthPx, info.heightPx, frame,
                v.frameCount(), frame / std::max(info.fps, 1e-9), zoom, decoding ? " · decoding…" : "");
  std::vector<LegendItem> legend;
  if (v.keyframeAt(frame))
    legend.push_back({palette::kCamera, onScreen ? "marked by hand (keyframe; drag to correct)" : "marked by hand (keyframe)", false});
  const bool fitted = actions::showsVideoFit(s) && !v.marking;
  if (v.detecting && onScreen) {
    // The subtitle says how far the detection has come; the points' colours what they mean.
    const std::size_t len = std::strlen(sub);
    std::snprintf(sub + len, sizeof sub - len, " · detecting: %.0f %%",
                  100.0 * s.video.detect.fraction());
  }
  if (fitted) {
    legend.push_back({palette::kInputPoint, actions::showsDetectionFit(s) ? "detected joints" : "tracked joints", false});
    legend.push_back({palette::kCamera, "principal point (est.)", true});
    if (s.view.overlays.reprojection) {
      legend.push_back({palette::kReconRight, "3D walker through the est. camera", true});
      legend.push_back({palette::kError, "residual", true});
    }
  } else if (v.detecting || (v.detected && v.detected->people > 0 && !v.tracked)) {
    legend.push_back({palette::confidenceColour(1.0f), "detected: visible", false});
    legend.push_back({palette::confidenceColour(0.0f), "detected: hidden", false});
  } else if (v.tracked) {
    legend.push_back({palette::confidenceColour(1.0f), "tracked: sure", false});
    legend.push_back({palette::confidenceColour(0.0f), "tracked: lost", false});
  }
  // The horizons video_view.cpp draws (addHorizons).
  if (v.horizon() && v.horizon()->scene && !v.marking) {
    legend.push_back({palette::kSceneHorizon, "horizon (the scene's level lines)", true});
    if (fitted && actions::showsVideoFit(s)) legend.push_back({palette::kCamera, "horizon (est. camera)", true});
  }
  return {"2D input (video)", sub, std::move(legend)};
}

ViewCaption walkerReconstructionCaption(const AppState& s) {
  if (stageDrawsViews(s)) return stageReconstructionCaption(s);
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const ReconBase* r = s.derived.recon();
  char sub[200];
  if (reconstruct && r) {
    const char* est = s.doc.recon.estimator == Estimator::Lsq ? "LSQ" : "MAP";
    if (s.doc.recon.unknownAngle) {
      std::snprintf(sub, sizeof sub, "%s, view angle unknown: est. α = %.1f° (true %.1f°)", est, r->alphaUsedDeg,
                    r->alphaTrueDeg);
    } else {
      std::snprintf(sub, sizeof sub, "%s at the known view angle α = %.1f°", est, r->alphaTrueDeg);
    }
    if (r->engine == EngineKind::Snippet) {
      const std::size_t n = r->snippets ? r->snippets->starts.size() : 0;
      if (s.doc.recon.unknownAngle)
        std::snprintf(sub, sizeof sub, "snippets, α unknown: est. %.1f° (true %.1f°), %zu snippets",
                      r->alphaUsedDeg, r->alphaTrueDeg, n);
      else
        std::snprintf(sub, sizeof sub, "snippets at the known α = %.1f°, %zu snippets",
                      r->alphaTrueDeg, n);
    } else if (r->engine == EngineKind::Skeleton) {
      if (s.doc.recon.unknownAngle)
        std::snprintf(sub, sizeof sub, "geometry alone, α unknown: est. %.1f° (true %.1f°)", r->alphaUsedDeg,
                      r->alphaTrueDeg);
      else
        std::snprintf(sub, sizeof sub, "geometry alone at the known α = %.1f°", r->alphaTrueDeg);
    } else if (s.doc.recon.estimator == Estimator::Map) {
      const std::size_t len = std::strlen(sub);
      std::snprintf(sub + len, sizeof sub - len, ", σ² = %.0f mm²", s.doc.recon.sigma2Mm2);
    }
  } else {
    std::snprintf(sub, sizeof sub, "walker synthesised from the eigenwalker coefficients");
  }
  if (reconstruct && r && s.doc.compareEngines)
    std::snprintf(sub, sizeof sub, "compare: the three engines %s α = %.1f°",
                  s.doc.recon.unknownAngle ? "with α unknown, true" : "at the known", r->alphaTrueDeg);
  return {reconstruct ? "3D reconstruction" : "Gait space", sub, walkerReconstructionLegend(s)};
}

ViewCaption clipReconstructionCaption(const AppState& s) {
  const CameraFit& fit = s.clip.fit()->rec.fit;
  const WalkCamera& c = fit.camera;
  char sub[240];
  if (c.model == CameraModel::Pinhole) {
    const ClipWorld w = clipWorld(*s.clip.fit(), 0);
    // The camera's distance to the walker's path (the line x = 0 of the walk).
    // A weak azimuth says so where it is read (the log has the whole sentence).
    const bool weak = inPlaceAzimuthIsWeak(fit, s.clip.fit()->settings.alphaDeg.has_value());
    std::snprintf(sub, sizeof sub, "camera %s, %.1f m from the %s, azimuth %.1f°%s%s, %s%s",
                  heightOverAnklesText(w.eye.z).c_str(), std::abs(w.eye.x) / 1000.0,
                  fit.inPlace ? "treadmill's line (walking in place)" : "walking line", c.alphaDeg,
                  degreesSdText(fit.sd.alphaDeg).c_str(), weak ? " (weak: level camera)" : "",
                  tiltText(c.elevationDeg).c_str(), degreesSdText(fit.sd.elevationDeg).c_str());
  } else {
    std::snprintf(sub, sizeof sub, "scaled orthography: azimuth %.1f°, %s (distance not estimated; drawn at 5 m)",
                  c.alphaDeg, tiltText(c.elevationDeg).c_str());
  }
  std::vector<LegendItem> legend{{palette::kReconRight, "reconstruction (right side darker)", false},
                                 {palette::kCamera, "estimated camera, its view of the walk", true}};
  // Walking in place the walker covers no ground: there is no line to draw.
  if (!fit.inPlace) legend.push_back({palette::kReconMid, "walking line over the clip", true});
  if (!fit.unseenJoints.empty()) legend.push_back({palette::kModelEstimated, "never seen: from the model", false});
  return {"3D reconstruction and the estimated camera", sub, std::move(legend)};
}

ViewCaption inputCaption(const AppState& s, int clipFrame) {
  if (s.doc.mode == Mode::Clip && s.video.session) {
    const VideoSession& v = *s.video.session;
    const auto fit = actions::videoFitFrames(s);
    return videoInputCaption(s, fit ? fit->first + clipFrame : v.frame, false, false);
  }
  return s.doc.mode == Mode::Clip && s.clip.fit() ? clipInputCaption(s, clipFrame) : walkerInputCaption(s);
}

ViewCaption reconstructionCaption(const AppState& s) {
  return s.doc.mode == Mode::Clip && s.clip.fit() ? clipReconstructionCaption(s) : walkerReconstructionCaption(s);
}

}  // namespace ew::ui
