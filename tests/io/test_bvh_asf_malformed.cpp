// Malformed BVH and ASF/AMC input, generated in memory from the real CMU files:
// truncations at many offsets, seeded random byte flips, absurd counts, NaN text, empty
// and binary input. The readers must return or throw ew::Error, never anything else
// (run under ASan/UBSan, a crash, overflow or huge allocation fails the test too).

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "core/common/errors.h"
#include "core/io/asf_amc_reader.h"
#include "core/io/bvh_reader.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// [SECTION] Helpers

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

enum class Outcome { Loaded, EwError, OtherException };

template <typename Parse>
Outcome outcomeOf(Parse&& parse, std::string* message = nullptr) {
  try {
    parse();
    return Outcome::Loaded;
  } catch (const Error& e) {
    if (message) *message = e.what();
    return Outcome::EwError;
  } catch (const std::exception& e) {
    if (message) *message = e.what();
    return Outcome::OtherException;
  } catch (...) {
    return Outcome::OtherException;
  }
}

// The real 07_01.bvh cut to its first `frames` frames (header count adjusted), so the
// many corruptions below stay fast in a Debug ASan build.
std::string smallBvh(int frames) {
  const std::string full = readText(test::sharedDataDir() / "cmu-mocap-bvh/07/07_01.bvh");
  const size_t framesAt = full.find("Frames: 317");
  std::string out = full.substr(0, framesAt) + "Frames: " + std::to_string(frames);
  size_t pos = full.find('\n', framesAt);           // end of the Frames line
  pos = full.find('\n', pos + 1);                    // end of the Frame Time line
  out += full.substr(framesAt + 11, pos + 1 - (framesAt + 11));
  for (int f = 0; f < frames; ++f) {
    const size_t end = full.find('\n', pos + 1);
    out += full.substr(pos + 1, end - pos);
    pos = end;
  }
  return out;
}

// 35_01.amc up to (not including) frame `stopFrame`.
std::string smallAmc(int stopFrame) {
  const std::string full = readText(test::sharedDataDir() / "cmu-mocap-asfamc/35/35_01.amc");
  return full.substr(0, full.find("\r\n" + std::to_string(stopFrame) + "\r\n") + 2);
}

std::string asfText() { return readText(test::sharedDataDir() / "cmu-mocap-asfamc/35/35.asf"); }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void expectMalformedWithLine(const std::function<void()>& parse, const std::string& file,
                             const std::string& what) {
  SCOPED_TRACE(what);
  try {
    parse();
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_TRUE(e.kind() == ErrorKind::Malformed || e.kind() == ErrorKind::Unsupported)
        << e.what();
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.position().rfind("line ", 0), 0u) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an ew::Error: " << e.what();
  }
}

// [SECTION] BVH

TEST(BvhMalformed, TruncationAtManyOffsets) {
  EW_REQUIRE_SHARED_DATA();
  const std::string text = smallBvh(12);
  const size_t lastRow = text.rfind('\n', text.size() - 2) + 1;
  const size_t step = std::max<size_t>(1, text.size() / 250);
  for (size_t cut = 0; cut < text.size(); cut += step) {
    std::string message;
    const Outcome o = outcomeOf([&] { parseBvh(text.substr(0, cut), "cut.bvh"); }, &message);
    ASSERT_NE(o, Outcome::OtherException) << "cut at " << cut << ": " << message;
    if (cut < lastRow) {
      ASSERT_EQ(o, Outcome::EwError) << "truncated at byte " << cut << " accepted";
      EXPECT_NE(message.find("cut.bvh: line "), std::string::npos) << message;
    }
  }
}

TEST(BvhMalformed, TruncatedFullFile) {
  EW_REQUIRE_SHARED_DATA();
  const std::string text = readText(test::sharedDataDir() / "cmu-mocap-bvh/08/08_01.bvh");
  for (size_t cut : {size_t{0}, size_t{1}, size_t{9}, text.size() / 7, text.size() / 2,
                     text.size() - 2000}) {
    EXPECT_EQ(outcomeOf([&] { parseBvh(text.substr(0, cut), "08_01.bvh"); }), Outcome::EwError)
        << cut;
  }
}

TEST(BvhMalformed, SeededRandomByteFlips) {
  EW_REQUIRE_SHARED_DATA();
  const std::string text = smallBvh(6);
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<size_t> where(0, text.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255), count(1, 4);
  int errors = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string bad = text;
    for (int k = count(rng); k > 0; --k) bad[where(rng)] = static_cast<char>(byte(rng));
    std::string message;
    const Outcome o = outcomeOf([&] { parseBvh(bad, "flip.bvh"); }, &message);
    ASSERT_NE(o, Outcome::OtherException) << "trial " << trial << ": " << message;
    errors += o == Outcome::EwError ? 1 : 0;
  }
  EXPECT_GT(errors, 50);  // many flips break something; the rest still parse
}

TEST(BvhMalformed, AbsurdCountsAndBadNumbers) {
  EW_REQUIRE_SHARED_DATA();
  const std::string text = smallBvh(3);
  const std::vector<std::pair<std::string, std::string>> edits = {
      {"Frames: 3", "Frames: 999999999"},
      {"Frames: 3", "Frames: 99999999999999999999999"},
      {"Frames: 3", "Frames: -3"},
      {"Frames: 3", "Frames: 0"},
      {"Frames: 3", "Frames: nan"},
      {"Frames: 3", "Frames: 4"},
      {"Frames: 3", "Frames 3"},
      {"Frame Time: .0083333", "Frame Time: 0"},
      {"Frame Time: .0083333", "Frame Time: nan"},
      {"Frame Time: .0083333", "Frame Time: -1"},
      {"Frame Time: .0083333", "Frame Time: inf"},
      {"CHANNELS 6", "CHANNELS 1000000"},
      {"CHANNELS 6", "CHANNELS 7"},
      {"CHANNELS 6", "CHANNELS -1"},
      {"CHANNELS 3 Zrotation", "CHANNELS 3 Wrotation"},
      {"CHANNELS 3 Zrotation Yrotation Xrotation", "CHANNELS 3 Zrotation Zrotation Xrotation"},
      {"OFFSET 1.85590", "OFFSET nan"},
      {"OFFSET 1.85590", "OFFSET 1e999"},
      {"OFFSET 1.85590", "OFFSET 0x10"},
      {"8.8721 15.7511", "nan 15.7511"},
      {"8.8721 15.7511", "inf 15.7511"},
      {"8.8721 15.7511", "--8.8721 15.7511"},
      {"8.8721 15.7511", "8.8721,15.7511"},
      {"HIERARCHY", "HIERARCHX"},
      {"ROOT Hips", "JOINT Hips"},
      {"End Site", "End Sight"},
      {"MOTION", "MOTIONS"},
      {"}\nMOTION", "MOTION"},
  };
  for (const auto& [from, to] : edits) {
    expectMalformedWithLine([&, to = to, from = from] { parseBvh(replaced(text, from, to), "abs.bvh"); },
                            "abs.bvh", from + " -> " + to);
  }
}

TEST(BvhMalformed, EmptyBlankAndBinaryInput) {
  for (const std::string& text : {std::string(), std::string("\n\n  \r\n\t"), std::string("HIERARCHY"),
                                  std::string("HIERARCHY\nROOT"), std::string("HIERARCHY\nROOT A\n{")}) {
    expectMalformedWithLine([&] { parseBvh(text, "e.bvh"); }, "e.bvh", "'" + text + "'");
  }
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    std::string garbage(static_cast<size_t>(1 + trial * 80), '\0');
    for (char& c : garbage) c = static_cast<char>(rng());
    EXPECT_EQ(outcomeOf([&] { parseBvh(garbage, "g.bvh"); }), Outcome::EwError);
    EXPECT_EQ(outcomeOf([&] { parseBvh("HIERARCHY\nROOT " + garbage, "g.bvh"); }),
              Outcome::EwError);
  }
}

TEST(BvhMalformed, DeepNestingIsRefusedWithoutRecursingForever) {
  for (int depth : {300, 100000}) {
    std::ostringstream s;
    s << "HIERARCHY\nROOT J\n{\nOFFSET 0 0 0\nCHANNELS 3 Xrotation Yrotation Zrotation\n";
    for (int k = 0; k < depth; ++k) s << "JOINT J" << k << "\n{\nOFFSET 0 1 0\n";
    expectMalformedWithLine([&] { parseBvh(s.str(), "deep.bvh"); }, "deep.bvh",
                            std::to_string(depth));
  }
}

TEST(BvhMalformed, TooManyJointsIsRefused) {
  std::ostringstream s;
  s << "HIERARCHY\nROOT J\n{\nOFFSET 0 0 0\nCHANNELS 3 Xrotation Yrotation Zrotation\n";
  for (int k = 0; k < 5000; ++k) s << "JOINT J" << k << "\n{\nOFFSET 0 1 0\n}\n";
  s << "}\nMOTION\nFrames: 1\nFrame Time: 1\n0 0 0\n";
  expectMalformedWithLine([&] { parseBvh(s.str(), "wide.bvh"); }, "wide.bvh", "5000 joints");
}

// [SECTION] ASF/AMC

TEST(AsfAmcMalformed, TruncatedSkeleton) {
  EW_REQUIRE_SHARED_DATA();
  const std::string asf = asfText(), amc = smallAmc(4);
  const size_t lastEnd = asf.rfind("end");
  for (size_t cut = 0; cut < asf.size(); cut += 23) {
    std::string message;
    const Outcome o =
        outcomeOf([&] { parseAsfAmc(asf.substr(0, cut), amc, "35.asf", "35_01.amc"); }, &message);
    ASSERT_NE(o, Outcome::OtherException) << cut << ": " << message;
    if (cut <= lastEnd) {
      ASSERT_EQ(o, Outcome::EwError) << "skeleton truncated at byte " << cut << " accepted";
      EXPECT_NE(message.find("35.asf: line "), std::string::npos) << message;
    }
  }
}

TEST(AsfAmcMalformed, TruncatedMotion) {
  EW_REQUIRE_SHARED_DATA();
  const std::string asf = asfText(), amc = smallAmc(5);
  int errors = 0;
  for (size_t cut = 0; cut < amc.size(); cut += 19) {
    std::string message;
    const Outcome o =
        outcomeOf([&] { parseAsfAmc(asf, amc.substr(0, cut), "35.asf", "35_01.amc"); }, &message);
    ASSERT_NE(o, Outcome::OtherException) << cut << ": " << message;
    errors += o == Outcome::EwError ? 1 : 0;
  }
  EXPECT_GT(errors, 15);  // cuts at line ends are valid: AMC may omit bones
}

TEST(AsfAmcMalformed, SeededRandomByteFlips) {
  EW_REQUIRE_SHARED_DATA();
  const std::string asf = asfText(), amc = smallAmc(4);
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> byte(0, 255), count(1, 4);
  for (int trial = 0; trial < 300; ++trial) {
    const bool inAsf = trial % 2 == 0;
    std::string a = asf, m = amc;
    std::string& target = inAsf ? a : m;
    std::uniform_int_distribution<size_t> where(0, target.size() - 1);
    for (int k = count(rng); k > 0; --k) target[where(rng)] = static_cast<char>(byte(rng));
    std::string message;
    const Outcome o = outcomeOf([&] { parseAsfAmc(a, m, "35.asf", "35_01.amc"); }, &message);
    ASSERT_NE(o, Outcome::OtherException) << "trial " << trial << ": " << message;
  }
}

TEST(AsfAmcMalformed, AbsurdValues) {
  EW_REQUIRE_SHARED_DATA();
  const std::string asf = asfText(), amc = smallAmc(3);
  const std::vector<std::pair<std::string, std::string>> asfEdits = {
      {"length 0.45", "length 0"},
      {"length 0.45", "length nan"},
      {"length 2.63917", "length -1"},
      {"length 2.63917", "length 1e999"},
      {"direction 0.673618", "direction nan"},
      {"axis 0 0 20  XYZ", "axis 0 0 20  XYY"},
      {"axis 0 0 20  XYZ", "axis 0 0 20"},
      {"dof rx ry rz", "dof rx ry rz l"},
      {"dof rx ry rz", "dof rx rx"},
      {"limits (-160.0 20.0)", "limits (-160.0 20.0"},
      {"limits (-160.0 20.0)", "limits (nan 20.0)"},
      {"name lfemur", "name lhipjoint"},
      {"lfemur ltibia", "lfemur lfemur"},
      {"ltibia lfoot", "ltibia lfoot lfemur"},
      {"root lhipjoint", "lowerback lhipjoint"},
      {":hierarchy", ":hierarchz"},
      {"angle deg", "angle grad"},
  };
  for (const auto& [from, to] : asfEdits) {
    expectMalformedWithLine(
        [&, to = to, from = from] { parseAsfAmc(replaced(asf, from, to), amc, "35.asf", "35_01.amc"); },
        "35.asf", from + " -> " + to);
  }
  const std::vector<std::pair<std::string, std::string>> amcEdits = {
      {"\r\n2\r\n", "\r\n99999999999999999999999\r\n"},
      {"\r\n2\r\n", "\r\n7\r\n"},
      {"\r\n2\r\n", "\r\n1\r\n"},
      {"root 4.40047", "root nan"},
      {"root 4.40047", "root inf"},
      {"lradius 27.8853", "lradius 27.8853 1"},
      {"lradius 27.8853", "lradius"},
      {"lradius 27.8853", "lradiux 27.8853"},
      {"lradius 27.8853", "lradius 27.8853\r\nlradius 27.8853"},
      {":DEGREES\r\n1\r\n", ":DEGREES\r\nroot 0 0 0 0 0 0\r\n"},
      {"\r\n2\r\n", "\r\n2\r\n:RADIANS\r\n"},
  };
  for (const auto& [from, to] : amcEdits) {
    expectMalformedWithLine(
        [&, to = to, from = from] { parseAsfAmc(asf, replaced(amc, from, to), "35.asf", "35_01.amc"); },
        "35_01.amc", from + " -> " + to);
  }
}

TEST(AsfAmcMalformed, EmptyAndBinaryInput) {
  EW_REQUIRE_SHARED_DATA();
  const std::string asf = asfText(), amc = smallAmc(3);
  expectMalformedWithLine([&] { parseAsfAmc("", amc, "a.asf", "a.amc"); }, "a.asf", "empty asf");
  expectMalformedWithLine([&] { parseAsfAmc(asf, "", "a.asf", "a.amc"); }, "a.amc", "empty amc");
  std::mt19937 rng(3);
  for (int trial = 0; trial < 40; ++trial) {
    std::string garbage(static_cast<size_t>(1 + trial * 100), '\0');
    for (char& c : garbage) c = static_cast<char>(rng());
    EXPECT_EQ(outcomeOf([&] { parseAsfAmc(garbage, amc, "a.asf", "a.amc"); }), Outcome::EwError);
    EXPECT_EQ(outcomeOf([&] { parseAsfAmc(asf, garbage, "a.asf", "a.amc"); }), Outcome::EwError);
  }
}

TEST(AsfAmcMalformed, TooManyBonesAndCycles) {
  std::ostringstream many;
  many << ":bonedata\n";
  for (int k = 0; k < 1100; ++k) {
    many << "begin\nname b" << k << "\ndirection 0 1 0\nlength 1\naxis 0 0 0 XYZ\nend\n";
  }
  expectMalformedWithLine([&] { parseAsfAmc(many.str(), "1\n", "m.asf", "m.amc"); }, "m.asf",
                          "1100 bones");
  const std::string cycle =
      ":bonedata\nbegin\nname a\ndirection 0 1 0\nlength 1\naxis 0 0 0 XYZ\nend\n"
      "begin\nname b\ndirection 0 1 0\nlength 1\naxis 0 0 0 XYZ\nend\n"
      ":hierarchy\nbegin\na b\nb a\nend\n";
  expectMalformedWithLine([&] { parseAsfAmc(cycle, "1\n", "c.asf", "c.amc"); }, "c.asf", "cycle");
}

}  // namespace
}  // namespace ew
