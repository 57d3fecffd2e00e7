// libFuzzer harness: the whole open-a-file path, as `eigenwalker-cli info` / `build` and
// the viewer run it on a trial, from bytes in memory:
//   reader -> ew::toJointTrial -> ew::prepareWalkingTrial -> ew::fitFourierMeasured
//   (-> ew::completeWalkingTrial with the default model when joints are missing)
//   -> ew::measureGait from the file's events and from the kinematics (`eigenwalker-cli gait`)
// The first input byte picks the format (value % 5: C3D, BVH, ASF+AMC, TRC, CSV: the 15-joint CSV or a Vicon Nexus export); the rest
// is the file (for ASF+AMC: skeleton, a line "%%AMC%%", motion). The fit gets the stride
// frequency of the gait cycles as its ω hint, as a trial becomes a walker in
// core/eigenwalker/walker_set.cpp. A typed ew::Error at any stage is the correct outcome;
// anything else is a finding (fuzz_common.h), and so is a fit that succeeds with a
// non-finite Fourier vector or frequency (it would poison every model built from it).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/gait/gait_measures.h"
#include "core/gait/prepare.h"
#include "core/io/asf_amc_reader.h"
#include "core/io/bvh_reader.h"
#include "core/io/c3d_reader.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "core/io/trc_reader.h"
#include "core/mapping/joint_mapping.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

ew::RawTrial parseAs(std::uint8_t selector, const std::uint8_t* data, std::size_t size) {
  const std::string_view text = ew::fuzz::asText(data, size);
  switch (selector % 5) {
    case 0:
      return ew::parseC3d(ew::fuzz::asBytes(data, size), "fuzz.c3d");
    case 1:
      return ew::parseBvh(text, "fuzz.bvh");
    case 2: {
      const auto [asf, amc] = ew::fuzz::splitAtLine(text, ew::fuzz::kAmcSeparator);
      return ew::parseAsfAmc(asf, amc, "fuzz.asf", "fuzz.amc");
    }
    case 3:
      return ew::parseTrc(text, "fuzz.trc");
    default:
      return ew::parseCsvTrial(text, "fuzz.csv");
  }
}

// What `gait` does with a trial: a measured stride time must be finite and positive.
void measureGaitBothWays(const ew::WalkingTrial& walking) {
  const auto& m = walking.joints.positionsMm;
  const double rate = walking.joints.rateHz;
  const double durationS = static_cast<double>(m.rows() - 1) / rate;
  for (const ew::GaitEventSet& events :
       {ew::gaitEventsFromFile(walking.joints.events, durationS), ew::gaitEventsFromKinematics(m, rate)}) {
    try {
      const ew::GaitMeasures g = ew::measureGait(m, rate, events, walking.speedMps, "fuzz");
      if (!(g.strideTimeS > 0.0) || !std::isfinite(g.cadenceSpm)) {
        std::fprintf(stderr, "fuzz_pipeline: gait measures with stride time %g s\n", g.strideTimeS);
        std::abort();
      }
    } catch (const ew::Error&) {
      // no complete stride, a joint missing: the typed error `gait` reports
    }
  }
}

void openTrial(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const ew::RawTrial raw = parseAs(data[0], data + 1, size - 1);
  const ew::JointTrial joints = ew::toJointTrial(raw);
  const ew::WalkingTrial walking = ew::prepareWalkingTrial(joints);
  ew::FourierFitOptions options;
  options.file = raw.file;
  if (walking.cycles.strideHz > 0.0)
    options.omegaHintRadS = 2.0 * std::numbers::pi * walking.cycles.strideHz;
  // Joints the file lacks are fitted around and then estimated from the default model.
  const ew::FourierFit fit = ew::fitFourierMeasured(
      walking.joints.positionsMm, walking.joints.rateHz, walking.joints.missing, options);
  if (ew::anyJoint(walking.joints.missing)) {
    const ew::CompletedTrial completed = ew::completeWalkingTrial(walking, ew::defaultRealModel());
    if (!completed.trial.joints.positionsMm.allFinite()) {
      std::fprintf(stderr, "fuzz_pipeline: the completed joints of %s are not finite\n",
                   raw.file.c_str());
      std::abort();
    }
  }
  if (!fit.w.allFinite() || !std::isfinite(fit.omegaRadS) || !std::isfinite(fit.phaseRad)) {
    std::fprintf(stderr,
                 "fuzz_pipeline: the Fourier fit of %s succeeded with a non-finite "
                 "result (omega %g, phase %g)\n",
                 raw.file.c_str(), fit.omegaRadS, fit.phaseRad);
    std::abort();
  }
  measureGaitBothWays(walking);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors([&] { openTrial(data, size); });
}
