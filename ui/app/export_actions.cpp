// Exports: PNG, video, motion, model, state JSON, the gait report.
#include "ui/app/export_actions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/model_file.h"
#include "core/gait/joint_angles.h"
#include "core/io/atomic_write.h"
#include "core/io/bvh_writer.h"
#include "core/io/joint_csv.h"
#include "core/io/c3d_writer.h"
#include "core/io/trc_writer.h"
#include "core/keypoints/keypoint_frames.h"
#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"
#include "ui/app/held_model.h"
#include "ui/app/state_json.h"

namespace ew::ui::actions {

// [SECTION] Export

void requestPng(AppState& s, std::filesystem::path path, CaptureView view) {
  if (path.empty()) throw std::invalid_argument("no file name for the PNG");
  s.exports.png = PngRequest{std::move(path), view, 2};
}

CaptureView captureViewFromName(const std::string& name) {
  if (name == "window") return CaptureView::Window;
  if (name == "input") return CaptureView::Input;
  if (name == "reconstruction") return CaptureView::Reconstruction;
  throw std::invalid_argument("unknown view \"" + name +
                              "\" (known: window, input, reconstruction)");
}

void startVideoExport(AppState& s, const VideoSettings& settings) {
  requireLoaded(s);
  if (s.exports.video) throw std::invalid_argument("a video export is already running");
  if (s.doc.mode == Mode::Reconstruct ? !s.derived.display() : !s.derived.explore())
    throw std::invalid_argument("nothing to export yet");
  s.exports.video = std::make_unique<VideoExport>(settings, playbackStrideHz(s));
  s.log.info("Exporting " + std::to_string(s.exports.video->frameCount()) + " frames to " +
             settings.path.string());
}

void cancelVideoExport(AppState& s) {
  if (!s.exports.video) return;
  s.log.warning("Video export cancelled: " + s.exports.video->settings().path.string());
  s.exports.video.reset();
}

void reportExportError(AppState& s, const std::string& message) {
  ++s.exports.failures;
  s.exports.lastError = message;
  s.log.error(message);
}

void exportCsv(AppState& s, const std::filesystem::path& path, std::optional<double> cycles) {
  requireLoaded(s);
  const WalkerMotion m = displayedWalkerMotion(s, cycles);
  writeJointCsv(path, m.framesX45, m.rateHz,
                {"eigenwalker viewer: " + m.description, "cycles=" + std::to_string(m.cycles)});
  s.log.info("Wrote " + path.string() + " (" + std::to_string(m.framesX45.rows()) + " frames, " +
             m.description + ")");
}

void exportBvh(AppState& s, const std::filesystem::path& path, std::optional<double> cycles) {
  requireLoaded(s);
  const WalkerMotion m = displayedWalkerMotion(s, cycles);
  writeBvh(path, m.framesX45, m.rateHz);
  s.log.info("Wrote " + path.string() + " (" + std::to_string(m.framesX45.rows()) + " frames, " +
             m.description + ")");
}

void exportModel(AppState& s, const std::filesystem::path& path) {
  requireLoaded(s);
  const EigenwalkerModel* held = s.doc.heldModel();
  if (!held) throw std::invalid_argument("models not built yet");
  EigenwalkerModel model = *held;
  std::string what = "the model of every walker";
  if (s.doc.mode == Mode::Reconstruct) {
    WalkerModel used;
    try {
      used = modelForWalker(s.doc, s.doc.walker);
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(e.what());
    }
    model = std::move(used.model);
    what = used.member ? "the model without " + used.heldOutSubject : "the model held";
  }
  saveModel(model, path);
  s.log.info("Wrote " + path.string() + " (" + what + ", " + std::to_string(model.walkerCount()) +
             " walkers)");
}

void exportState(AppState& s, const std::filesystem::path& path) {
  if (path.empty()) throw std::invalid_argument("no file name for the state");
  const std::string text = stateJson(s).dump(2) + "\n";
  writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
  s.log.info("Wrote " + path.string() + " (viewer state)");
}

// [SECTION] Gait report

namespace {

// The reconstruction's frames carried forward at its own measured speed: what OpenSim shows
// walking over the floor.
Eigen::MatrixXd walkedOverTheFloor(const GaitSummary& g) {
  Eigen::MatrixXd frames = g.framesMm;
  const double speed = g.measures && std::isfinite(g.measures->speedMps) ? g.measures->speedMps : 0.0;
  for (Eigen::Index f = 0; f < frames.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j) frames(f, 3 * j + 1) += speed * 1000.0 * static_cast<double>(f) / kReportRateHz;
  return frames;
}

}  // namespace

namespace {

// What the gait report's JSON says it measured: the walker (or clip) and how it was made.
GaitReportText gaitReportSubject(const AppState& s) {
  if (s.doc.mode == Mode::Explore) return {"explore", "synthesised"};
  if (s.doc.mode == Mode::Clip)
    return {s.clip.fit() ? s.clip.fit()->settings.path.filename().string() : std::string(),
            "eigenwalker through the estimated camera"};
  const Walker* w = s.doc.selectedWalker();
  return {w ? w->id : std::string(), engineName(s.doc.recon.engine)};
}

}  // namespace

void exportGaitReport(AppState& s, const std::filesystem::path& path) {
  GaitPanel& p = s.panels.gait;
  s.derived.update(s.doc);  // a script may have changed the document since the last frame
  p.update(s);
  const GaitSummary& recon = p.recon();
  if (!recon.measures) throw std::invalid_argument("no measured walker to export (" + recon.error + ")");
  const std::string ext = path.extension().string();
  const GaitBand empty;
  const GaitBand& band = p.band ? *p.band : empty;
  if (ext == ".csv") {
    writeGaitReportCsv(path.string(), p.mocap, p.exportColumns(), band);
  } else if (ext == ".json") {
    writeGaitReportJson(path.string(), gaitReportSubject(s), p.mocap, p.exportColumns(), band);
  } else if (ext == ".trc") {
    const Eigen::MatrixXd frames = walkedOverTheFloor(recon);
    writeTrc(path, frames, kReportRateHz);
    std::filesystem::path mot = path;
    mot.replace_extension(".mot");
    writeJointAngles(mot.string(), jointAngles(frames, Eigen::Vector3d::UnitZ(), path.string()), kReportRateHz,
                     {"gait report: the reconstruction's joint angles (eigenwalker)"});
  } else if (ext == ".c3d") {
    // For gait labs' tools (Visual3D, Mokka): the joints and the gait events of its own kinematics.
    writeWalkerC3d(path, walkedOverTheFloor(recon), kReportRateHz,
                   {"gait report: the reconstruction walked over the floor at its measured speed"});
  } else {
    throw std::invalid_argument("gait report: export to .csv, .json, .trc (with its .mot) or .c3d, not '" + ext +
                                "'");
  }
  p.status = "wrote " + path.filename().string() + (ext == ".trc" ? " and its .mot" : "");
  s.log.info("Wrote " + path.string() + " (gait report)");
}

}  // namespace ew::ui::actions
