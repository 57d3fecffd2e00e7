// libFuzzer harness: C3D bytes -> ew::parseC3d (core/io/c3d_reader.h). A typed ew::Error is
// the correct outcome for bad bytes; anything else is a finding (fuzz_common.h).

#include "core/io/c3d_reader.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors(
      [&] { ew::parseC3d(ew::fuzz::asBytes(data, size), "fuzz.c3d"); });
}
