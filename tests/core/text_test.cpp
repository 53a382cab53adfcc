// The shared text helpers (core/text.hpp) and FNV-1a (core/fnv1a.hpp):
// published test vectors for the hash, RFC 4180 for the CSV field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/core/fnv1a.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {
namespace {

TEST(Text, TrimLowerJoin) {
  EXPECT_EQ(trim("  a b \t\r\n"), "a b");
  EXPECT_EQ(trim(" \n\t "), "");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(lower("LN_COBYLA Grid"), "ln_cobyla grid");
  EXPECT_EQ(lower("\xC3\x89t\xC3\xA9"), "\xC3\x89t\xC3\xA9");  // bytes above ASCII unchanged
  EXPECT_EQ(join({"a", "b", "c"}), "a, b, c");
  EXPECT_EQ(join({"x", "y"}, " | "), "x | y");
  EXPECT_EQ(join({}), "");
  EXPECT_EQ(join({"", "b"}, ";"), ";b");  // an empty item keeps its place
}

TEST(Text, CsvFieldFollowsRfc4180) {
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field(""), "");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");  // kept inside the quotes
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
}

// A spreadsheet runs a text cell starting with = + - @ tab or CR as a
// formula: such a cell is written as quoted text behind an apostrophe.
TEST(Text, CsvFieldKeepsSpreadsheetsFromRunningTextAsAFormula) {
  EXPECT_EQ(csv_field("=HYPERLINK(\"http://x\",\"y\")"), "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(csv_field("+1+cmd|' /C calc'!A0"), "\"'+1+cmd|' /C calc'!A0\"");
  EXPECT_EQ(csv_field("-2+3"), "\"'-2+3\"");
  EXPECT_EQ(csv_field("@SUM(A1)"), "\"'@SUM(A1)\"");
  EXPECT_EQ(csv_field("\t=1"), "\"'\t=1\"");
  EXPECT_EQ(csv_field("\r=1"), "\"'\r=1\"");
  EXPECT_EQ(csv_field("-"), "\"'-\"");
  // numbers stay numbers
  EXPECT_EQ(csv_field("-1.5e-3"), "-1.5e-3");
  EXPECT_EQ(csv_field("-0"), "-0");
  EXPECT_EQ(csv_field("-inf"), "-inf");
  EXPECT_EQ(csv_field("-nan"), "-nan");
  EXPECT_EQ(csv_field("1e+05"), "1e+05");
  // only the first character counts
  EXPECT_EQ(csv_field("a=b"), "a=b");
}

TEST(Fnv1a, PublishedVectorsAndTheFingerprintBasis) {
  // Fowler-Noll-Vo test vectors for FNV-1a 64.
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
  EXPECT_EQ(kFnv1aOffsetBasis, 0xcbf29ce484222325ull);
  // The fingerprint's own basis stays what stored studies were made with.
  EXPECT_EQ(fnv1a64("", kStudyFingerprintBasis), 1469598103934665603ull);
  EXPECT_NE(fnv1a64("study", kStudyFingerprintBasis), fnv1a64("study"));
}

}  // namespace
}  // namespace rackopt
