// `eigenwalker-cli gait PATH… [--events auto|kinematics|file|both] [--out gait.csv]
// [--curves curves.csv] [--json]`: the spatiotemporal gait measures and the flexion curves over
// the gait cycle (core/gait/gait_measures.h) of each 3D trial — motion capture, a
// reconstruction's CSV or a synthetic walker. `--events both` measures a trial twice, from its
// file's events and from its kinematics, and prints how far apart the two are.
#include <cmath>
#include <optional>
#include <iomanip>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "app/cli/checks.h"
#include "app/cli/commands.h"
#include "app/cli/reconstruct_camera.h"
#include "app/cli/video_input.h"
#include "core/eigenwalker/default_model.h"
#include "core/common/errors.h"
#include "core/gait/dataset.h"
#include "core/gait/fourier_walker_gait.h"
#include "core/gait/gait_measures.h"
#include "core/gait/joint_angles.h"
#include "core/io/atomic_write.h"

namespace ew::cli {
namespace {

struct GaitArgs {
  std::vector<std::string> paths;
  std::string events = "auto", out, curves, units, mapping;
  std::optional<double> rateHz;  // given: checked by the reader (checkedRateOverrideHz)
  std::optional<double> statureM;  // a video's walker: its camera fit scaled to it
  bool json = false, wholeTrial = false;
};

// One SD of the speed and the stride length from a video walker's camera fit (CameraFit::sd);
// NaN for a 3D trial, whose lengths are measured, not fitted.
struct FitSds {
  double speedMps = std::numeric_limits<double>::quiet_NaN();
  double strideLengthM = std::numeric_limits<double>::quiet_NaN();
};

struct MeasuredTrial {
  std::string file, subject;
  GaitMeasures measures;
  std::vector<CycleCurve> curves;
  FootProgression footProgression;  // NaN without the feet
  FitSds fitSd;
};

std::string number(double v, int digits) {
  if (!std::isfinite(v)) return "nan";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::vector<GaitEventSet> eventSetsFor(const WalkingTrial& t, const std::string& choice) {
  const auto& m = t.joints.positionsMm;
  const double durationS = static_cast<double>(m.rows() - 1) / t.joints.rateHz;
  const GaitEventSet file = gaitEventsFromFile(t.joints.events, durationS);
  const bool hasFile = !file.right.strikesS.empty() || !file.left.strikesS.empty();
  if (choice == "file" && !hasFile)
    throwBadData(t.joints.file, "", "--events file: the file has no foot strike events");
  if (choice == "file" || (choice == "auto" && hasFile)) return {file};
  // The feet's heel and toe where the trial has them, else the ankle (gait_events.h).
  const GaitEventSet kinematic = gaitEventsFromFeet(m, t.joints.feetMm, t.joints.rateHz);
  if (choice == "both" && hasFile) return {file, kinematic};
  return {kinematic};
}

void addCurvesOf(const WalkingTrial& t, MeasuredTrial& out) {
  const JointAngles angles =
      jointAnglesWithFeet(t.joints.positionsMm, t.joints.feetMm, Eigen::Vector3d::UnitZ(), t.joints.file);
  const double rateHz = t.joints.rateHz;
  out.curves = flexionCycleCurves(angles.degrees, angles.names, rateHz, out.measures);
  if (!t.joints.hasFeet()) return;
  const auto ankle = footCycleCurves(angles.degrees, angles.names, rateHz, out.measures);
  out.curves.insert(out.curves.end(), ankle.begin(), ankle.end());
  out.footProgression = footProgressionDeg(angles.degrees, angles.names, rateHz, out.measures);
}

// Feet lifted from one view onto their ankles' sagittal planes (a camera reconstruction's:
// core/camera/lifted_feet.h, JointTrial::feetInSagittalPlanes): their events and ankle angle
// hold, their turn out of the plane is not in them.
void withoutFootProgression(MeasuredTrial& m) {
  m.footProgression = {};
  m.measures.notes.push_back("feet from the image, lifted onto the ankles' sagittal planes: no foot progression");
}

// A reconstruction's walk, in place: its progression as its camera fit found it, or (on a
// treadmill) its two-harmonic walker's stance feet (core/gait/fourier_walker_gait.h).
struct ReconstructedWalk {
  std::optional<double> progressionMps;  // unset: walking in place
};

// A video's walker: its 3D joints in place and the feet lifted from the image (a temporary C3D,
// core/camera/lifted_feet.h) and its walk over the floor.
struct VideoWalker {
  TrialFile file;
  ReconstructedWalk walk;
  FitSds sd;
};

// A video: the walker the built-in detector finds, reconstructed through the unknown camera as
// `reconstruct --input V.mp4` does (its summary on stderr), written beside the other outputs
// in a temporary C3D and measured like any reconstruction's, at its fit's progression.
VideoWalker reconstructedFromVideo(const std::filesystem::path& video, const std::filesystem::path& folder,
                                   std::optional<double> statureM) {
  CameraArgs c;
  c.input = video.string();
  c.out = (folder / (video.stem().string() + "_walk3d.c3d")).string();
  c.modelName = defaultRealModelName();
  c.statureM = statureM;
  c.seenFramesOnly = true;
  CameraFit fit;
  runReconstructCamera(defaultRealModel(), c, &fit);
  VideoWalker w;
  w.file.path = c.out;
  w.file.info.subject = video.stem().string();
  if (!fit.inPlace) w.walk.progressionMps = fit.speedMps;
  w.sd = {fit.sd.speedMps, fit.sd.strideLengthM};
  return w;
}

GaitMeasures measuredWalk(const WalkingTrial& t, const GaitEventSet& events, const std::string& name,
                          const std::optional<ReconstructedWalk>& reconstructed) {
  if (!reconstructed) return measureGait(t.joints.positionsMm, t.joints.rateHz, events, t.speedMps, name);
  if (reconstructed->progressionMps)
    return measureGait(t.joints.positionsMm, t.joints.rateHz, events, reconstructed->progressionMps, name);
  return measureTwoHarmonicGait(t.joints.positionsMm, t.joints.rateHz, events, name);
}

std::vector<MeasuredTrial> measureFile(const TrialFile& f, const GaitArgs& args,
                                       const std::optional<ReconstructedWalk>& reconstructed = std::nullopt) {
  LoadOptions options;
  if (args.rateHz) options.rateHzOverride = *args.rateHz;
  if (!args.units.empty()) options.unitsOverride = args.units;
  if (!args.mapping.empty()) options.mappingFile = args.mapping;
  PrepareOptions prepare;
  prepare.cropToSteadyWindow = !args.wholeTrial;
  const WalkingTrial t = loadWalkingTrial(f.path, options, prepare);
  std::vector<MeasuredTrial> out;
  // A reconstruction's C3D carries the events its own kinematics gave when it was written: the
  // same kinematics measured here, named as what they are.
  for (const auto& events : eventSetsFor(t, reconstructed ? "kinematics" : args.events)) {
    MeasuredTrial m{f.path.string(), f.info.subject, measuredWalk(t, events, f.path.string(), reconstructed), {}, {}, {}};
    addCurvesOf(t, m);
    if (t.joints.feetInSagittalPlanes) withoutFootProgression(m);
    out.push_back(std::move(m));
  }
  return out;
}

const std::vector<std::string>& columns() {
  static const std::vector<std::string> c = {
      "file", "subject", "events", "strides", "stride_time_s", "cadence_spm", "step_length_r_m",
      "step_length_l_m", "stride_length_m", "step_width_m", "speed_mps", "speed_source", "stance_foot_speed_mps",
      "stance_r_pct", "stance_l_pct", "stance_pct", "swing_pct", "double_support_pct", "stride_time_all_events_s",
      "notes", "foot_progression_r_deg", "foot_progression_l_deg", "ankle_flexion_range_deg", "speed_sd_mps",
      "stride_length_sd_m"};
  return c;
}

std::vector<std::string> row(const MeasuredTrial& t) {
  const GaitMeasures& g = t.measures;
  std::string notes;
  for (const auto& n : g.notes) notes += (notes.empty() ? "" : "; ") + n;
  return {t.file, t.subject, g.events.method, std::to_string(g.strides.size()),
          number(g.strideTimeS, 4), number(g.cadenceSpm, 2), number(g.stepLengthRightM, 4),
          number(g.stepLengthLeftM, 4), number(g.strideLengthM, 4), number(g.stepWidthM, 4),
          number(g.speedMps, 3), g.speedSource, number(g.stanceFootSpeedMps, 3), number(g.stanceRightPct, 2),
          number(g.stanceLeftPct, 2), number(g.stancePct, 2), number(g.swingPct, 2),
          number(g.doubleSupportPct, 2), number(g.strideTimeAllEventsS, 4), notes,
          number(t.footProgression.rightDeg, 2), number(t.footProgression.leftDeg, 2),
          number(flexionRangeDeg(t.curves, "ankle_angle"), 2), number(t.fitSd.speedMps, 3),
          number(t.fitSd.strideLengthM, 4)};
}

std::string csvCell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void writeRow(std::ostream& out, const std::vector<std::string>& cells) {
  for (size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << csvCell(cells[k]);
  out << "\n";
}

void writeMeasures(const std::string& file, const std::vector<MeasuredTrial>& trials) {
  writeFileAtomically(file, [&](std::ostream& out) {
    writeRow(out, columns());
    for (const auto& t : trials) writeRow(out, row(t));
  });
}

void writeCurves(const std::string& file, const std::vector<MeasuredTrial>& trials) {
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "file,events,curve,cycle_pct,mean_deg,sd_deg,strides\n";
    for (const auto& t : trials) {
      for (const auto& c : t.curves) {
        const auto n = c.meanDeg.size();
        for (Eigen::Index k = 0; k < n; ++k) {
          writeRow(out, {t.file, t.measures.events.method, c.name, number(100.0 * static_cast<double>(k) / static_cast<double>(n - 1), 1),
                         number(c.meanDeg[k], 3), number(c.sdDeg[k], 3), std::to_string(c.strides)});
        }
      }
    }
  });
}

nlohmann::json toJson(const MeasuredTrial& t) {
  nlohmann::json j;
  const auto cells = row(t);
  for (size_t k = 0; k < cells.size(); ++k) j[columns()[k]] = cells[k];
  auto times = [](const std::vector<double>& v) { return nlohmann::json(v); };
  const auto& e = t.measures.events;
  j["events_s"] = {{"right_strikes", times(e.right.strikesS)}, {"right_offs", times(e.right.offsS)},
                   {"left_strikes", times(e.left.strikesS)}, {"left_offs", times(e.left.offsS)}};
  return j;
}

// With --events both: each trial's kinematic measures against its file's, and the largest gaps.
void printEventAgreement(const std::vector<MeasuredTrial>& all) {
  double worstStride = 0, worstCadence = 0, worstStance = 0;
  int pairs = 0;
  for (size_t k = 0; k + 1 < all.size(); ++k) {
    const auto& a = all[k].measures;
    const auto& b = all[k + 1].measures;
    if (all[k].file != all[k + 1].file || a.events.method != "file events") continue;
    const std::string from = b.events.method;
    const double dStride = 100.0 * (b.strideTimeS - a.strideTimeS) / a.strideTimeS;
    const double dCadence = 100.0 * (b.cadenceSpm - a.cadenceSpm) / a.cadenceSpm;
    const double dStance = b.stancePct - a.stancePct;
    const double dAll = 100.0 * (b.strideTimeAllEventsS - a.strideTimeAllEventsS) / a.strideTimeAllEventsS;
    std::cerr << all[k].file << ": " << from << " − file events: stride time " << number(dStride, 2)
              << " % (from every event " << number(dAll, 2) << " %), cadence " << number(dCadence, 2)
              << " %, stance " << number(dStance, 2) << " points\n";
    worstStride = std::max(worstStride, std::abs(dStride));
    worstCadence = std::max(worstCadence, std::abs(dCadence));
    worstStance = std::isfinite(dStance) ? std::max(worstStance, std::abs(dStance)) : worstStance;
    ++pairs;
  }
  if (pairs > 0)
    std::cerr << "kinematics vs file events over " << pairs << " trials: largest |difference| stride time "
              << number(worstStride, 2) << " %, cadence " << number(worstCadence, 2) << " %, stance "
              << number(worstStance, 2) << " points\n";
}

// Each row named by its trial's file name: a subject's several trials (a folder of them) would
// otherwise be rows alike but for their numbers.
void printTable(const std::vector<MeasuredTrial>& all) {
  const std::vector<size_t> shown = {2, 3, 5, 8, 9, 10, 12, 15, 17};
  std::cout << "trial";
  for (size_t c : shown) std::cout << "\t" << columns()[c];
  std::cout << "\n";
  for (const auto& t : all) {
    const auto cells = row(t);
    std::cout << std::filesystem::path(t.file).filename().string();
    for (size_t c : shown) std::cout << "\t" << cells[c];
    std::cout << "\n";
  }
}

int runGait(const GaitArgs& args) {
  std::vector<std::filesystem::path> paths, videos;
  for (const auto& p : args.paths) (isVideoFile(p) ? videos : paths).emplace_back(p);
  if (args.statureM && videos.empty())
    throw Error(ErrorKind::BadArgument, "--stature", "",
                "it scales a video's camera fit; a 3D trial's lengths are its own");
  std::vector<std::string> warnings;
  std::vector<MeasuredTrial> all;
  int failed = 0;
  std::vector<TrialFile> files;
  std::error_code ec;
  const auto scratch = std::filesystem::temp_directory_path() / ("eigenwalker_gait_" + std::to_string(::getpid()));
  for (const auto& v : videos) {
    try {
      std::filesystem::create_directories(scratch, ec);
      const VideoWalker walker = reconstructedFromVideo(v, scratch, args.statureM);
      for (auto& m : measureFile(walker.file, args, walker.walk)) {
        m.file = v.string();
        m.fitSd = walker.sd;
        all.push_back(std::move(m));
      }
    } catch (const Error& e) {
      std::cerr << "error: " << e.what() << "\n";
      ++failed;
    }
  }
  std::filesystem::remove_all(scratch, ec);
  if (!paths.empty()) files = collectTrialFiles(paths, warnings);
  for (const auto& f : files) {
    try {
      for (auto& m : measureFile(f, args)) all.push_back(std::move(m));
    } catch (const Error& e) {
      std::cerr << "error: " << e.what() << "\n";
      ++failed;
    }
  }
  for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";
  if (all.empty() && failed == 0) std::cerr << "error: no trial files found in the given paths\n";
  if (!args.out.empty()) writeMeasures(args.out, all);
  if (!args.curves.empty()) writeCurves(args.curves, all);
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& t : all) out.push_back(toJson(t));
    std::cout << out.dump(2) << "\n";
  } else {
    printTable(all);
  }
  if (args.events == "both") printEventAgreement(all);
  return failed > 0 || all.empty() ? kExitDataError : 0;
}

}  // namespace

void addGaitCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<GaitArgs>();
  auto* cmd = app.add_subcommand(
      "gait", "Gait measures of 3D trials: cadence, stride and step length, step width, speed, stance, "
              "swing and double support, and hip/knee/shoulder/elbow flexion over the gait cycle (with the "
              "ankle's and the foot progression where the trial has heel and toe points). Exit 1 if "
              "any trial cannot be measured.");
  cmd->add_option("paths", args->paths, "3D trials (.c3d .bvh .amc .trc .csv .tsv), folders or manifest CSVs; or a video (.mp4 .mov .avi…): "
                  "the walker the built-in detector finds, reconstructed through the unknown camera")->required();
  cmd->add_option("--events", args->events,
                  "Foot strikes and offs from: auto (the file's events when it has them, else the kinematics), "
                  "kinematics, file, both (one row each, and their differences on stderr)")
      ->check(CLI::IsMember({"auto", "kinematics", "file", "both"}));
  cmd->add_option("--out", args->out, "CSV of the measures, one row per trial and event source");
  cmd->add_option("--curves", args->curves, "CSV of the flexion curves over the gait cycle (mean, SD over strides)");
  cmd->add_flag("--json", args->json, "One JSON object per trial (with the event times) instead of a table");
  cmd->add_flag("--whole-trial", args->wholeTrial,
                "Measure the whole trial, not only its steady straight-walking window");
  cmd->add_option("--rate", args->rateHz, "Frame rate in Hz, overriding the file's");
  cmd->add_option("--units", args->units, "Length unit overriding the file's: mm, cm, m, in, cmu");
  cmd->add_option("--mapping", args->mapping, "Joint mapping file (JSON, docs/FORMATS.md)");
  cmd->add_option("--stature", args->statureM,
                  "A video's walker's stature in metres: the camera fit is scaled to it (without it the scale, and "
                  "every length and speed, is the model's prior on body size)")
      ->check(finiteIn(0.5, 2.5));
  cmd->callback([args, &exitCode] { exitCode = runGait(*args); });
}

}  // namespace ew::cli
