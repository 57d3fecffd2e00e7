// The text formats' shared helpers (core/io/text_table.h): what the BVH, ASF/AMC, TRC and CSV
// readers split and parse their lines with, and how they show a hostile word in an error.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/text_table.h"

namespace ew {
namespace {

using Words = std::vector<std::string_view>;

TEST(TextTable, WordsAreSplitOnRunsOfBlanks) {
  EXPECT_EQ(splitWords("  ROOT\tHips \r"), (Words{"ROOT", "Hips"}));
  EXPECT_EQ(splitWords("a\v\fb"), (Words{"a", "b"}));
  EXPECT_TRUE(splitWords(" \t\r ").empty());
  EXPECT_TRUE(splitWords("").empty());
}

TEST(TextTable, AWordInAnErrorIsQuotedCutAndFreeOfControlBytes) {
  EXPECT_EQ(shownWord("Hips"), "'Hips'");
  EXPECT_EQ(shownWord("a\x1b[2Jb\x7f"), "'a?[2Jb?'");
  const std::string longWord(100, 'x');
  EXPECT_EQ(shownWord(longWord), "'" + std::string(40, 'x') + "...'");
}

TEST(TextTable, OnlyWholeFiniteNumbersParse) {
  double v = 0.0;
  EXPECT_TRUE(parseFinite("+1.5e2", v));
  EXPECT_EQ(v, 150.0);
  EXPECT_TRUE(parseFinite("-0.25", v));
  EXPECT_EQ(v, -0.25);
  for (const char* bad : {"", "+", "nan", "inf", "-inf", "1e999", "1.5x", "1 2", " 1"})
    EXPECT_FALSE(parseFinite(bad, v)) << bad;
}

}  // namespace
}  // namespace ew
