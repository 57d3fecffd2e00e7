// libFuzzer harness: joint mapping file text -> ew::parseJointMapping
// (core/mapping/mapping_file.h), and every mapping that parses applied to a small marker
// trial with ew::applyJointMapping (labels present or not, too few joints, NaN markers).
// A typed ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include <limits>

#include "core/mapping/mapping_file.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

// Eight markers, four frames, one marker never seen (NaN throughout).
const ew::RawTrial& smallTrial() {
  static const ew::RawTrial trial = [] {
    ew::RawTrial raw;
    raw.file = "fuzz.c3d";
    raw.format = "C3D";
    raw.rateHz = 100.0;
    raw.labels = {"LASI", "RASI", "LKNE", "RKNE", "LANK", "RANK", "HEAD", "GONE"};
    raw.positionsMm = Eigen::MatrixXd::Zero(4, 24);
    for (int f = 0; f < 4; ++f) {
      for (int c = 0; c < 21; ++c) raw.positionsMm(f, c) = 10.0 * c + f;
    }
    raw.positionsMm.rightCols(3).setConstant(std::numeric_limits<double>::quiet_NaN());
    return raw;
  }();
  return trial;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = ew::fuzz::asText(data, size);
  ew::fuzz::acceptTypedErrors([&] {
    const ew::JointMapping mapping = ew::parseJointMapping(text, "fuzz.json");
    // What the viewer writes must read back as the same mapping.
    const ew::JointMapping back =
        ew::parseJointMapping(ew::jointMappingToJson(mapping), "back.json");
    if (back.joints != mapping.joints) std::abort();
    ew::applyJointMapping(smallTrial(), mapping, "fuzz.json");
  });
  return 0;
}
