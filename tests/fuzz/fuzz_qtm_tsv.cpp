// libFuzzer harness: a Qualisys TSV export's text -> ew::parseQtmTsv (core/io/qtm_tsv.h), then
// what parses to the 15 joints by the marker-set tables (ew::toJointTrial). A typed ew::Error
// is the correct outcome; anything else is a finding (fuzz_common.h).

#include "core/io/qtm_tsv.h"
#include "core/mapping/joint_mapping.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors([&] {
    const ew::RawTrial raw = ew::parseQtmTsv(ew::fuzz::asText(data, size), "fuzz.tsv");
    (void)ew::toJointTrial(raw);
  });
}
