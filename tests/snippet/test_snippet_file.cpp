// Snippet prior files (core/snippet/snippet_file.h, docs/SNIPPET_FORMAT.md): exact round
// trip, atomic writes that refuse an invalid prior, typed errors naming the file for
// damaged, truncated, newer and hostile files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/errors.h"
#include "core/snippet/snippet_file.h"
#include "core/snippet/snippet_prior.h"
#include "core/synth/random.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using nlohmann::json;

// A prior over one frame (D = 45) fitted to 200 random snippets around 3 centres.
SnippetPrior samplePrior() {
  Rng rng(11);
  Eigen::MatrixXd x(45, 200);
  for (Eigen::Index i = 0; i < x.cols(); ++i)
    for (Eigen::Index r = 0; r < x.rows(); ++r)
      x(r, i) = 40.0 * static_cast<double>(i % 3) * (r % 2 == 0 ? 1.0 : -1.0) + 5.0 * rng.normal();
  SnippetPriorOptions o;
  o.frames = 1;
  o.clusters = 3;
  o.components = 5;
  o.emIterations = 2;
  SnippetPrior prior = fitSnippetMixture(x, o);
  prior.subjects = {"Sü1", "walker \"two\""};  // non-ASCII and quotes survive
  return prior;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// FNV-1a 64 as docs/SNIPPET_FORMAT.md defines it, written independently of core.
std::string fnvHex(std::string_view s) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

// A saved file split into its parts, to be edited and put back together with every
// checksum made right, so that only the loader's other checks can catch the edit.
struct FileParts {
  std::string line1;
  json meta;
  std::string payload;

  explicit FileParts(const std::string& bytes) {
    const size_t l1 = bytes.find('\n'), l2 = bytes.find('\n', l1 + 1),
                 l3 = bytes.find('\n', l2 + 1);
    line1 = bytes.substr(0, l1);
    meta = json::parse(bytes.substr(l1 + 1, l2 - l1 - 1));
    payload = bytes.substr(l3 + 1);
  }

  // The payload offset of a cluster's array (its arrays in order, clusters in order).
  size_t arrayOffset(size_t cluster, size_t array) const {
    size_t offset = 0;
    for (size_t j = 0; j < meta["clusters"].size(); ++j)
      for (size_t a = 0; a < 3; ++a) {
        if (j == cluster && a == array) return offset;
        const json& spec = meta["clusters"][j]["arrays"][a];
        offset += spec["rows"].get<size_t>() * spec["cols"].get<size_t>() * 8;
      }
    return offset;
  }

  // Recomputes the checksum of array `array` of `cluster` from the payload.
  void fixArrayChecksum(size_t cluster, size_t array) {
    const json& spec = meta["clusters"][cluster]["arrays"][array];
    const size_t size = spec["rows"].get<size_t>() * spec["cols"].get<size_t>() * 8;
    meta["clusters"][cluster]["arrays"][array]["fnv1a64"] =
        fnvHex(std::string_view(payload).substr(arrayOffset(cluster, array), size));
  }

  std::string bytes() const {
    const std::string line2 = meta.dump();
    return line1 + "\n" + line2 + "\nfnv1a64 " + fnvHex(line2) + "\n" + payload;
  }
};

// The file's bytes after `edit` changed a copy of its parts.
std::string edited(const FileParts& clean, const std::function<void(FileParts&)>& edit) {
  FileParts parts = clean;
  edit(parts);
  return parts.bytes();
}

class SnippetFile : public ::testing::Test {
 protected:
  std::filesystem::path dir = test::makeTempDir("snippet_file");
  std::filesystem::path file = dir / "prior.ewsp";
  void TearDown() override { std::filesystem::remove_all(dir); }

  // loadSnippetPrior on `bytes` written to `name`, expecting Error(kind) whose message
  // names the file and holds every part.
  ::testing::AssertionResult refuses(const std::string& bytes, ErrorKind kind,
                                     std::initializer_list<std::string_view> parts,
                                     const std::string& name = "bad.ewsp") {
    test::writeBinaryFile(dir / name, bytes);
    const auto result = test::throwsError([&] { loadSnippetPrior(dir / name); }, kind, parts);
    if (!result) return result;
    return test::throwsError([&] { loadSnippetPrior(dir / name); }, kind, {name});
  }
};

// [SECTION] Round trip

TEST_F(SnippetFile, RoundTripIsBitwiseExact) {
  const SnippetPrior prior = samplePrior();
  ASSERT_EQ(prior.frames, 1);
  ASSERT_EQ(prior.components.size(), 3u);
  ASSERT_EQ(prior.components[0].basis.cols(), 5);
  saveSnippetPrior(prior, file);
  const SnippetPrior back = loadSnippetPrior(file);
  EXPECT_EQ(back.frames, prior.frames);
  EXPECT_TRUE(sameBits(back.rateHz, prior.rateHz));
  EXPECT_EQ(back.subjects, prior.subjects);
  EXPECT_EQ(back.trainingSnippets, 200);
  EXPECT_EQ(back.emIterations, prior.emIterations);
  ASSERT_EQ(back.components.size(), prior.components.size());
  for (size_t j = 0; j < prior.components.size(); ++j) {
    const PpcaComponent &a = prior.components[j], &b = back.components[j];
    EXPECT_TRUE(sameBits(b.weight, a.weight)) << j;
    EXPECT_EQ(b.members, a.members);
    EXPECT_TRUE(sameBits(b.noiseVariance, a.noiseVariance)) << j;
    EXPECT_TRUE(test::bitwiseEqual(b.mean, a.mean)) << j;
    EXPECT_TRUE(test::bitwiseEqual(b.basis, a.basis)) << j;
    EXPECT_TRUE(test::bitwiseEqual(b.variances, a.variances)) << j;
  }
  const Eigen::VectorXd x = prior.components[1].mean + Eigen::VectorXd::Constant(45, 3.0);
  EXPECT_EQ(logDensity(back, x), logDensity(prior, x));
  // Saving the loaded prior gives the same bytes; no temporary file is left behind.
  saveSnippetPrior(back, dir / "again.ewsp");
  EXPECT_EQ(test::readTextFile(file), test::readTextFile(dir / "again.ewsp"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 2);
}

TEST_F(SnippetFile, LayoutIsTheDocumentedOne) {
  const SnippetPrior prior = samplePrior();
  saveSnippetPrior(prior, file);
  const std::string bytes = test::readTextFile(file);
  ASSERT_EQ(bytes.rfind("EIGENWALKER-SNIPPET-PRIOR 1\n", 0), 0u);
  const FileParts parts(bytes);
  EXPECT_EQ(parts.bytes(), bytes);  // line 3 is FNV-1a 64 of line 2, lower-case hex
  EXPECT_EQ(parts.meta["dimension"], 45);
  EXPECT_EQ(parts.meta["frames"], 1);
  EXPECT_EQ(parts.meta["clusters"].size(), 3u);
  EXPECT_EQ(parts.meta["clusters"][0]["components"], 5);
  EXPECT_EQ(parts.meta["payload_bytes"].get<size_t>(), parts.payload.size());
  EXPECT_EQ(parts.payload.size(), 3u * (45 + 45 * 5 + 5) * 8);
  // Cluster 1's basis, column-major little-endian float64: element (2, 1) at 8 · (2 + 45).
  const size_t at = parts.arrayOffset(1, 1) + 8 * (2 + 45);
  std::uint64_t bits = 0;
  for (int b = 0; b < 8; ++b)
    bits |= static_cast<std::uint64_t>(
                static_cast<unsigned char>(parts.payload[at + static_cast<size_t>(b)]))
            << (8 * b);
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  EXPECT_TRUE(sameBits(value, prior.components[1].basis(2, 1)));
}

TEST_F(SnippetFile, PriorOfAnyDimensionRoundTrips) {
  // frames 0: low-dimensional data (D = 3), as fitSnippetMixture makes for tests.
  Rng rng(5);
  Eigen::MatrixXd x(3, 60);
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = rng.normal() + (i % 2 ? 10.0 : 0.0);
  SnippetPriorOptions o;
  o.clusters = 2;
  o.components = 1;
  const SnippetPrior prior = fitSnippetMixture(x, o);
  ASSERT_EQ(prior.frames, 0);
  saveSnippetPrior(prior, file);
  const SnippetPrior back = loadSnippetPrior(file);
  EXPECT_EQ(back.frames, 0);
  ASSERT_EQ(back.components.size(), prior.components.size());
  EXPECT_TRUE(test::bitwiseEqual(back.components[1].basis, prior.components[1].basis));
  EXPECT_TRUE(back.subjects.empty());
}

TEST_F(SnippetFile, ParseNamesTheGivenName) {
  EXPECT_TRUE(test::throwsError([] { parseSnippetPrior("", "memory:prior"); }, ErrorKind::Malformed,
                                {"memory:prior", "line 1", "truncated"}));
  saveSnippetPrior(samplePrior(), file);
  EXPECT_EQ(parseSnippetPrior(test::readTextFile(file), "x").components.size(), 3u);
}

// [SECTION] Damaged files

TEST_F(SnippetFile, UnreadableFileIsAnIoError) {
  EXPECT_TRUE(test::throwsError([&] { loadSnippetPrior(dir / "absent.ewsp"); }, ErrorKind::Io,
                                {"absent.ewsp"}));
  EXPECT_TRUE(test::throwsError([&] { loadSnippetPrior(dir); }, ErrorKind::Io, {"directory"}));
}

TEST_F(SnippetFile, WrongMagicIsMalformedAtByteZero) {
  EXPECT_TRUE(refuses("EIGENWALKER-MODEL 1\n{}\n", ErrorKind::Malformed,
                      {"byte 0", "not an eigenwalker snippet prior file"}));
  EXPECT_TRUE(refuses("PLY\nformat ascii\n", ErrorKind::Malformed, {"byte 0"}));
  EXPECT_TRUE(
      refuses("EIGENWALKER-SNIPPET-PRIOR x1\n", ErrorKind::Malformed, {"line 1", "bad version"}));
}

TEST_F(SnippetFile, EveryTruncationIsMalformed) {
  saveSnippetPrior(samplePrior(), file);
  const std::string bytes = test::readTextFile(file);
  const size_t l1 = bytes.find('\n'), l2 = bytes.find('\n', l1 + 1), l3 = bytes.find('\n', l2 + 1);
  for (const size_t size : {size_t{0}, size_t{10}, l1, l1 + 1, l1 + 40, l2 + 1, l2 + 10, l3 + 1,
                            l3 + 9, bytes.size() / 2, bytes.size() - 8, bytes.size() - 1}) {
    test::writeBinaryFile(dir / "cut.ewsp", bytes.substr(0, size));
    std::string message;
    try {
      loadSnippetPrior(dir / "cut.ewsp");
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Malformed) << "size " << size << ": " << e.what();
      message = e.what();
    }
    EXPECT_NE(message.find("cut.ewsp"), std::string::npos) << "size " << size << ": " << message;
    EXPECT_TRUE(message.find("byte") != std::string::npos ||
                message.find("line") != std::string::npos)
        << message;
    if (size > l3) {
      EXPECT_NE(message.find("truncated"), std::string::npos) << message;
    }
  }
}

TEST_F(SnippetFile, FlippedBytesFailTheChecksums) {
  saveSnippetPrior(samplePrior(), file);
  const std::string bytes = test::readTextFile(file);
  const size_t l1 = bytes.find('\n');
  std::string damaged = bytes;
  damaged[l1 + 30] = static_cast<char>(damaged[l1 + 30] ^ 0x01);  // in the metadata
  EXPECT_TRUE(refuses(damaged, ErrorKind::Malformed, {"line 2", "metadata checksum mismatch"}));
  damaged = bytes;
  damaged[bytes.size() - 3] = static_cast<char>(damaged[bytes.size() - 3] ^ 0x01);  // last array
  EXPECT_TRUE(refuses(damaged, ErrorKind::Malformed,
                      {"checksum mismatch in cluster 2 array 'variances'", "bytes "}));
  // A flip anywhere (magic, metadata, line 3, every array) is caught.
  for (size_t at = 0; at < bytes.size(); at += 61) {
    damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    test::writeBinaryFile(dir / "flipped.ewsp", damaged);
    try {
      loadSnippetPrior(dir / "flipped.ewsp");
      ADD_FAILURE() << "flip at byte " << at << " went unnoticed";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("flipped.ewsp"), std::string::npos) << e.what();
    }
  }
}

TEST_F(SnippetFile, NewerVersionIsUnsupported) {
  saveSnippetPrior(samplePrior(), file);
  std::string bytes = test::readTextFile(file);
  bytes.replace(0, bytes.find('\n'), "EIGENWALKER-SNIPPET-PRIOR 2");
  EXPECT_TRUE(refuses(bytes, ErrorKind::Unsupported, {"line 1", "version 2", "reads version 1"}));
}

TEST_F(SnippetFile, TrailingBytesAreMalformed) {
  saveSnippetPrior(samplePrior(), file);
  const std::string bytes = test::readTextFile(file);
  EXPECT_TRUE(refuses(bytes + "xyz", ErrorKind::Malformed,
                      {"byte " + std::to_string(bytes.size()), "3 unexpected bytes"}));
}

TEST_F(SnippetFile, NonFiniteValuesAreMalformedEvenWithRightChecksums) {
  saveSnippetPrior(samplePrior(), file);
  const FileParts clean(test::readTextFile(file));
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    FileParts parts = clean;
    const size_t at = parts.arrayOffset(1, 1) + 8 * 7;  // cluster 1's basis, index 7
    std::memcpy(parts.payload.data() + at, &bad, 8);    // (a little-endian host)
    parts.fixArrayChecksum(1, 1);
    const size_t headerSize = parts.bytes().size() - parts.payload.size();
    EXPECT_TRUE(refuses(parts.bytes(), ErrorKind::Malformed,
                        {"cluster 1 array 'basis'", "index 7", "must be finite",
                         "byte " + std::to_string(headerSize + at)}));
  }
  // Metadata numbers must be numbers (JSON has no NaN; an overflowing 1e999 is bad JSON).
  FileParts parts = clean;
  parts.meta["rate_hz"] = "fast";
  EXPECT_TRUE(refuses(parts.bytes(), ErrorKind::Malformed, {"line 2", "rate_hz"}));
  parts = clean;
  parts.meta["clusters"][0]["noise_variance_mm2"] = nullptr;
  EXPECT_TRUE(refuses(parts.bytes(), ErrorKind::Malformed,
                      {"line 2", "cluster 0 has no finite number 'noise_variance_mm2'"}));
}

TEST_F(SnippetFile, InconsistentMetadataIsMalformed) {
  saveSnippetPrior(samplePrior(), file);
  const FileParts clean(test::readTextFile(file));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["dimension"] = 46; }), ErrorKind::Malformed,
                      {"line 2", "dimension 46 is not frames · 45"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][1]["components"] = 4; }),
                      ErrorKind::Malformed,
                      {"line 2", "should be 'basis' 45 x 4, cluster 1 says"}));
  EXPECT_TRUE(
      refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][0]["arrays"][0]["name"] = "mu"; }),
              ErrorKind::Malformed, {"line 2", "should be 'mean'"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["payload_bytes"] = 8; }),
                      ErrorKind::Malformed, {"line 2", "payload_bytes says 8"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta.erase("subjects"); }), ErrorKind::Malformed,
                      {"line 2", "no list 'subjects'"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][2] = 7; }), ErrorKind::Malformed,
                      {"line 2", "cluster 2 is not a JSON object"}));
  // Sound sizes and checksums, but a prior checkSnippetPrior refuses.
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][0]["weight"] = 0.5; }),
                      ErrorKind::Malformed, {"snippet prior: weights do not sum to 1"}));
  EXPECT_TRUE(
      refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][2]["noise_variance_mm2"] = 1e12; }),
              ErrorKind::Malformed, {"cluster 2: a variance is not above σ²"}));
  // Not JSON at all (with a right checksum).
  const std::string junk = "{\"frames\": [";
  EXPECT_TRUE(refuses(clean.line1 + "\n" + junk + "\nfnv1a64 " + fnvHex(junk) + "\n",
                      ErrorKind::Malformed, {"line 2", "bad metadata JSON"}));
  EXPECT_TRUE(refuses(clean.line1 + "\n[]\nfnv1a64 " + fnvHex("[]") + "\n", ErrorKind::Malformed,
                      {"line 2", "not a JSON object"}));
}

TEST_F(SnippetFile, HostileSizesAreRefusedWithoutAllocating) {
  saveSnippetPrior(samplePrior(), file);
  const FileParts clean(test::readTextFile(file));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["frames"] = 1'000'000; }),
                      ErrorKind::Malformed, {"line 2", "'frames' must be 0…301"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) {
                        p.meta["frames"] = 0;
                        p.meta["dimension"] = 4'000'000'000'000LL;
                      }),
                      ErrorKind::Malformed, {"line 2", "'dimension' must be 1…13545"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][0]["components"] = 46; }),
                      ErrorKind::Malformed, {"line 2", "'components' must be 0…45"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][0]["components"] = -1; }),
                      ErrorKind::Malformed, {"line 2", "'components' must be 0…45"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][0]["members"] = 1LL << 40; }),
                      ErrorKind::Malformed, {"line 2", "'members'"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) { p.meta["training_snippets"] = -3; }),
                      ErrorKind::Malformed, {"line 2", "'training_snippets'"}));
  EXPECT_TRUE(
      refuses(edited(clean, [](FileParts& p) { p.meta["clusters"][0]["arrays"][1]["rows"] = -45; }),
              ErrorKind::Malformed, {"line 2", "absurd size for array 'basis'"}));
  EXPECT_TRUE(refuses(edited(clean, [](FileParts& p) {
                        json many = json::array();
                        for (int j = 0; j < 257; ++j) many.push_back(p.meta["clusters"][0]);
                        p.meta["clusters"] = many;
                      }),
                      ErrorKind::Malformed, {"line 2", "1…256 'clusters'"}));
  // The largest prior the bounds allow, declared consistently: 256 clusters of D = q =
  // 13,545 (about 376 GB). The loader must find the payload missing before allocating.
  const std::string huge = edited(clean, [](FileParts& p) {
    const long long d = 301 * 45;
    json cluster = p.meta["clusters"][0];
    cluster["components"] = d;
    cluster["arrays"][0]["rows"] = d;
    cluster["arrays"][1]["rows"] = d;
    cluster["arrays"][1]["cols"] = d;
    cluster["arrays"][2]["rows"] = d;
    json many = json::array();
    for (int j = 0; j < 256; ++j) many.push_back(cluster);
    p.meta["clusters"] = many;
    p.meta["frames"] = 301;
    p.meta["dimension"] = d;
    p.meta["payload_bytes"] = 256LL * (d + d * d + d) * 8;
  });
  EXPECT_TRUE(refuses(huge, ErrorKind::Malformed, {"truncated: payload has"}));
}

// [SECTION] Saving

TEST_F(SnippetFile, InvalidPriorIsNotWritten) {
  const SnippetPrior good = samplePrior();
  const auto refusesToSave = [&](const SnippetPrior& prior, std::string_view problem) {
    const auto target = dir / "refused.ewsp";
    const auto result = test::throwsError([&] { saveSnippetPrior(prior, target); },
                                          ErrorKind::BadArgument, {"refused.ewsp", problem});
    EXPECT_FALSE(std::filesystem::exists(target));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 0);
    return result;
  };
  SnippetPrior p = good;
  p.components[0].weight *= 0.5;
  EXPECT_TRUE(refusesToSave(p, "weights do not sum to 1"));
  p = good;
  p.components[1].basis(3, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(refusesToSave(p, "non-finite"));
  p = good;
  p.components.clear();
  EXPECT_TRUE(refusesToSave(p, "no clusters"));
  p = good;
  p.rateHz = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(refusesToSave(p, "rate"));
  p = good;
  p.emIterations = -1;
  EXPECT_TRUE(refusesToSave(p, "negative"));
  p = good;
  p.subjects.push_back("\xff\xfe");  // not UTF-8: JSON cannot hold it
  EXPECT_TRUE(refusesToSave(p, "cannot save"));

  // Over an existing file: the old file is left as it was.
  saveSnippetPrior(good, file);
  const std::string before = test::readTextFile(file);
  p = good;
  p.components[2].noiseVariance = -1.0;
  EXPECT_TRUE(test::throwsError([&] { saveSnippetPrior(p, file); }, ErrorKind::BadArgument,
                                {"prior.ewsp", "σ² must be positive"}));
  EXPECT_EQ(test::readTextFile(file), before);
}

TEST_F(SnippetFile, UnwritableTargetIsAnIoError) {
  EXPECT_TRUE(test::throwsError([&] { saveSnippetPrior(samplePrior(), dir / "no" / "p.ewsp"); },
                                ErrorKind::Io, {"p.ewsp"}));
}

}  // namespace
}  // namespace ew
