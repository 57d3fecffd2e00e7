// The C3D parser on broken input, generated in memory from the real files: truncations,
// random byte flips, absurd parameter counts and dimensions, NaN floats, empty and text
// input. The contract: parseC3d either returns a consistent trial or throws ew::Error
// whose message names the file; never another exception, a crash or a hang (this suite
// runs under ASan + UBSan in CI, which turns out-of-bounds reads into failures).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/io/c3d_reader.h"
#include "core/io/file_bytes.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using Bytes = std::vector<std::uint8_t>;

const std::string kName = "broken_input.c3d";

// [SECTION] The contract ------------------------------------------------------------------

enum class Outcome { Parsed, Rejected };

Outcome parseOrReject(std::span<const std::uint8_t> bytes, const std::string& what) {
  try {
    const RawTrial t = parseC3d(bytes, kName);
    EXPECT_EQ(t.positionsMm.cols(), 3 * t.pointCount()) << what;
    EXPECT_EQ(t.format, "C3D") << what;
    return Outcome::Parsed;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(kName), std::string::npos) << what << ": " << message;
    EXPECT_TRUE(e.kind() == ErrorKind::Malformed || e.kind() == ErrorKind::Unsupported)
        << what << ": " << message;
    EXPECT_FALSE(e.position().empty()) << what << ": no position in '" << message << "'";
    return Outcome::Rejected;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": non-ew exception: " << e.what();
  } catch (...) {
    ADD_FAILURE() << what << ": unknown exception";
  }
  return Outcome::Rejected;
}

Bytes loadSample(const std::string& relative) {
  return readFileBytes(test::sharedDataDir() / relative);
}

// Small files, every processor type and storage format, events, header pointers.
const std::vector<std::string>& fuzzSources() {
  static const std::vector<std::string> files = {
      "c3d-samples/sample02_vicon370_encodings/pc_int.c3d",
      "c3d-samples/sample02_vicon370_encodings/dec_real.c3d",
      "c3d-samples/sample02_vicon370_encodings/sgi_real.c3d",
      "c3d-samples/sample16_simi_invalid_residuals/basketball.c3d",
      "c3d-samples/sample08_header_pointers/TESTBPI.c3d",
      "schreiber-moissenet-2019/2015026/2015026_ST.c3d",
  };
  return files;
}

// [SECTION] Degenerate inputs ---------------------------------------------------------------

TEST(C3dMalformed, EmptyTextAndTinyInputsAreRejectedWithTheName) {
  EXPECT_EQ(parseOrReject({}, "empty"), Outcome::Rejected);
  const std::string text = "frame,x,y,z\n1,2,3,4\nThis is a text file named .c3d\n";
  Bytes textBytes(text.begin(), text.end());
  EXPECT_EQ(parseOrReject(textBytes, "short text"), Outcome::Rejected);
  while (textBytes.size() < 4096) textBytes.insert(textBytes.end(), text.begin(), text.end());
  EXPECT_EQ(parseOrReject(textBytes, "long text"), Outcome::Rejected);
  EXPECT_EQ(parseOrReject(Bytes(512, 0x50), "all 0x50"), Outcome::Rejected);
  EXPECT_EQ(parseOrReject(Bytes(2048, 0x00), "all zero"), Outcome::Rejected);
  EXPECT_EQ(parseOrReject(Bytes(2048, 0xFF), "all 0xFF"), Outcome::Rejected);
  try {
    parseC3d({}, kName);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
}

// [SECTION] Truncation ----------------------------------------------------------------------

TEST(C3dMalformed, TruncatedFilesNeverCrash) {
  EW_REQUIRE_SHARED_DATA();
  for (const auto& file : fuzzSources()) {
    const Bytes bytes = loadSample(file);
    std::vector<std::size_t> cuts;
    for (std::size_t n = 0; n < std::min<std::size_t>(4096, bytes.size()); n += 7) cuts.push_back(n);
    for (std::size_t k = 1; k < 64; ++k) cuts.push_back(bytes.size() * k / 64);
    cuts.push_back(bytes.size() - 1);
    int rejected = 0;
    for (std::size_t n : cuts) {
      const auto outcome = parseOrReject(std::span(bytes).first(n), file + " cut at " + std::to_string(n));
      rejected += outcome == Outcome::Rejected;
    }
    // Cuts inside the header or parameters must be caught; cuts inside the trailing
    // padding of the last data block may legitimately still parse.
    EXPECT_GE(rejected, static_cast<int>(cuts.size()) * 3 / 4) << file;
  }
}

TEST(C3dMalformed, TruncationMessageGivesTheByte) {
  EW_REQUIRE_SHARED_DATA();
  const Bytes bytes = loadSample(fuzzSources()[0]);
  try {
    parseC3d(std::span(bytes).first(bytes.size() / 2), kName);
    ADD_FAILURE() << "half a file parsed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_NE(e.position().find("byte "), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("truncated"), std::string::npos) << e.what();
  }
}

// [SECTION] Random byte flips ---------------------------------------------------------------

TEST(C3dMalformed, RandomByteFlipsNeverCrash) {
  EW_REQUIRE_SHARED_DATA();
  std::mt19937 rng(20240611);
  for (const auto& file : fuzzSources()) {
    const Bytes original = loadSample(file);
    // Most of a file is data; flips that matter hit the first blocks, so bias there.
    const std::size_t hot = std::min<std::size_t>(original.size(), 6 * kC3dBlockBytes);
    for (int trial = 0; trial < 50; ++trial) {
      Bytes bytes = original;
      const int flips = 1 + static_cast<int>(rng() % 8);
      for (int k = 0; k < flips; ++k) {
        const std::size_t limit = (rng() % 4 == 0) ? bytes.size() : hot;
        bytes[rng() % limit] ^= static_cast<std::uint8_t>(1 + rng() % 255);
      }
      parseOrReject(bytes, file + " flip trial " + std::to_string(trial));
    }
  }
}

// [SECTION] Targeted parameter damage -------------------------------------------------------

// Where each parameter record of an Intel file lies, found by walking the record chain the
// way the C3D guide describes it (test-side, independent of the reader's internals).
struct RecordSpot {
  std::string name;
  std::size_t typeAt = 0;  // the data-type byte; dims follow
  std::size_t offsetAt = 0;
};

std::vector<RecordSpot> intelParameterRecords(const Bytes& b) {
  std::vector<RecordSpot> spots;
  std::size_t pos = (std::size_t{b.at(0)} - 1) * kC3dBlockBytes + 4;
  while (pos + 2 < b.size()) {
    const int nameLen = std::abs(static_cast<std::int8_t>(b[pos]));
    const int id = static_cast<std::int8_t>(b[pos + 1]);
    if (nameLen == 0 || id == 0) break;
    const std::size_t offsetAt = pos + 2 + static_cast<std::size_t>(nameLen);
    if (offsetAt + 4 > b.size()) break;
    const std::size_t offset = b[offsetAt] | (std::size_t{b[offsetAt + 1]} << 8);
    if (id > 0) {
      spots.push_back({std::string(reinterpret_cast<const char*>(&b[pos + 2]), nameLen),
                       offsetAt + 2, offsetAt});
    }
    if (offset == 0) break;
    pos = offsetAt + offset;
  }
  return spots;
}

TEST(C3dMalformed, AbsurdParameterCountsAndDimensionsAreCaught) {
  EW_REQUIRE_SHARED_DATA();
  // Every record of two small files; of a 320 KB walking trial (with the EVENT group),
  // only the records the reader uses, to keep the suite fast under sanitizers.
  const std::vector<std::string> used = {"USED",   "LABELS", "LABELS2",    "CONTEXTS",
                                         "TIMES",  "SCALE",  "RATE",       "FRAMES",
                                         "UNITS",  "DATA_START", "Y_SCREEN"};
  for (const char* file : {"c3d-samples/sample02_vicon370_encodings/pc_real.c3d",
                           "schreiber-moissenet-2019/2015026/2015026_ST.c3d",
                           "schreiber-moissenet-2019/2014001/2014001_C4_05.c3d"}) {
    const Bytes original = loadSample(file);
    const bool onlyUsed = original.size() > 100000;
    const auto spots = intelParameterRecords(original);
    ASSERT_GT(spots.size(), 20u) << file;
    for (const auto& spot : spots) {
      if (onlyUsed && std::find(used.begin(), used.end(), spot.name) == used.end()) continue;
      const std::size_t nDims = original[spot.typeAt + 1];
      const std::size_t dataAt = spot.typeAt + 2 + nDims;
      auto damaged = [&](const char* how, auto&& edit) {
        Bytes bytes = original;
        edit(bytes);
        parseOrReject(bytes, std::string(file) + " " + spot.name + " " + how);
      };
      damaged("dims 255", [&](Bytes& b) {
        for (std::size_t d = 0; d < nDims; ++d) b[spot.typeAt + 2 + d] = 255;
      });

      damaged("200 dims", [&](Bytes& b) { b[spot.typeAt + 1] = 200; });
      damaged("type 3", [&](Bytes& b) { b[spot.typeAt] = 3; });
      damaged("type char", [&](Bytes& b) { b[spot.typeAt] = 0xFF; });

      damaged("values 0xFF", [&](Bytes& b) {
        for (std::size_t k = 0; k < 4 && dataAt + k < b.size(); ++k) b[dataAt + k] = 0xFF;
      });

      damaged("NaN value", [&](Bytes& b) {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        if (dataAt + 4 <= b.size()) std::memcpy(&b[dataAt], &nan, 4);
      });
      damaged("offset 0", [&](Bytes& b) { b[spot.offsetAt] = 0; b[spot.offsetAt + 1] = 0; });
      damaged("offset max", [&](Bytes& b) { b[spot.offsetAt] = 0xFF; b[spot.offsetAt + 1] = 0xFF; });
    }
  }
}

TEST(C3dMalformed, AbsurdHeaderFieldsAreCaught) {
  EW_REQUIRE_SHARED_DATA();
  const Bytes original = loadSample("c3d-samples/sample02_vicon370_encodings/pc_int.c3d");
  // Header words (Intel, little-endian): points, analog, first, last, gap, scale, data block.
  for (std::size_t at : {2, 4, 6, 8, 12, 14, 16, 20, 22}) {
    for (std::uint8_t v : std::initializer_list<std::uint8_t>{0x00, 0x7F, 0x80, 0xFF}) {
      Bytes bytes = original;
      bytes[at] = v;
      bytes[at + 1] = v;
      parseOrReject(bytes, "header byte " + std::to_string(at) + " = " + std::to_string(v));
    }
  }
  for (std::uint8_t block : std::initializer_list<std::uint8_t>{0, 1, 3, 85, 255}) {
    Bytes bytes = original;
    bytes[0] = block;
    EXPECT_EQ(parseOrReject(bytes, "parameter block " + std::to_string(block)), Outcome::Rejected);
  }
  Bytes badProcessor = original;
  badProcessor[kC3dBlockBytes + 3] = 99;
  try {
    parseC3d(badProcessor, kName);
    ADD_FAILURE() << "processor 99 accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Unsupported);
    EXPECT_NE(std::string(e.what()).find("processor"), std::string::npos) << e.what();
  }
}

// [SECTION] Non-finite data -----------------------------------------------------------------

TEST(C3dMalformed, NaNAndInfinityInFloatDataBecomeMissingSamples) {
  EW_REQUIRE_SHARED_DATA();
  const Bytes original = loadSample("c3d-samples/sample02_vicon370_encodings/pc_real.c3d");
  const RawTrial clean = parseC3d(original, kName);
  Bytes bytes = original;
  // Data starts at the header's block (word 9); overwrite the whole first frame's points.
  const std::size_t dataAt = (std::size_t{bytes[16]} | (std::size_t{bytes[17]} << 8)) - 1;
  const std::size_t start = dataAt * kC3dBlockBytes;
  const float values[] = {std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity()};
  for (int p = 0; p < clean.pointCount(); ++p) {
    std::memcpy(&bytes[start + 16 * static_cast<std::size_t>(p)], &values[p % 2], 4);
  }
  const RawTrial t = parseC3d(bytes, kName);
  EXPECT_TRUE(t.positionsMm.row(0).array().isNaN().all());
  EXPECT_EQ(t.positionsMm.bottomRows(t.frameCount() - 1).array().isNaN().count(),
            clean.positionsMm.bottomRows(clean.frameCount() - 1).array().isNaN().count());
}

}  // namespace
}  // namespace ew
