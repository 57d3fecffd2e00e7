// libFuzzer harness: a .csv's text -> ew::parseCsvTrial (core/io/load_trial.h): our 15-joint
// CSV (core/io/joint_csv.h) or a Vicon Nexus export (core/io/nexus_csv.h), as the first line says.
// A typed ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include "core/io/load_trial.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors(
      [&] { ew::parseCsvTrial(ew::fuzz::asText(data, size), "fuzz.csv"); });
}
