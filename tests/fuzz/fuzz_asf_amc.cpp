// libFuzzer harness: an ASF skeleton and its AMC motion in one input, separated by a line
// "%%AMC%%" (ew::fuzz::kAmcSeparator; without it the input is all skeleton and the
// motion is empty) -> ew::parseAsfAmc (core/io/asf_amc_reader.h). A typed ew::Error is the
// correct outcome; anything else is a finding (fuzz_common.h).

#include "core/io/asf_amc_reader.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto files = ew::fuzz::splitAtLine(ew::fuzz::asText(data, size), ew::fuzz::kAmcSeparator);
  return ew::fuzz::acceptTypedErrors(
      [&] { ew::parseAsfAmc(files.first, files.second, "fuzz.asf", "fuzz.amc"); });
}
