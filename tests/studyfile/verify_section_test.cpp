// The study file's `verify` key: both forms load with their defaults, and
// every mistake is refused at its file:line:column with the key path.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/studyfile/study_loader.hpp"
#include "studyfile_test_support.hpp"

namespace rackopt::study {
namespace {

using test::load;
const std::string kEvaluateHead =
    "study: {kind: evaluate}\n"
    "problem: ../problems/gantry_axis.yaml\n";

// "t.yaml:line:column" of the first `needle` in `text`.
std::string mark_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  int line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "t.yaml:" + std::to_string(line) + ":" + std::to_string(column);
}

void expect_error_at_needle(const std::string& text, const std::string& needle, const std::string& key,
                            const std::string& says) {
  try {
    (void)load(text);
    ADD_FAILURE() << "no error for " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(to_string(e.mark()), mark_of(text, needle)) << e.what();
    EXPECT_EQ(e.key_path(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

TEST(VerifySection, AbsentMeansNoVerification) { EXPECT_FALSE(load(kEvaluateHead).verify_fe); }

TEST(VerifySection, TheWordFeTakesTheDefaults) {
  const StudySpec s = load(kEvaluateHead + "verify: fe\n");
  ASSERT_TRUE(s.verify_fe);
  EXPECT_EQ(s.verify_fe->positions, 4);
  EXPECT_EQ(s.verify_fe->level, 0);
  EXPECT_FALSE(s.verify_fe->extended_contact);
  EXPECT_FALSE(s.verify_fe->rack_supports);
  EXPECT_EQ(s.verify_fe->mark.line, 3);
}

TEST(VerifySection, TheMapSetsPositionsLevelAndContact) {
  const StudySpec s = load(kEvaluateHead + "verify: {method: fe, positions: 8, level: 2, extended_contact: on}\n");
  ASSERT_TRUE(s.verify_fe);
  EXPECT_EQ(s.verify_fe->positions, 8);
  EXPECT_EQ(s.verify_fe->level, 2);
  EXPECT_TRUE(s.verify_fe->extended_contact);
  EXPECT_FALSE(s.verify_fe->rack_supports);
  EXPECT_TRUE(load(kEvaluateHead + "verify: {rack_supports: on}\n").verify_fe->rack_supports);
  // method may be left out; --set reaches the keys.
  const StudySpec o = load(kEvaluateHead + "verify: {positions: 2}\n", {"verify.level=1"});
  EXPECT_EQ(o.verify_fe->positions, 2);
  EXPECT_EQ(o.verify_fe->level, 1);
}

TEST(VerifySection, MistakesAreRefusedWhereTheyAreWritten) {
  expect_error_at_needle(kEvaluateHead + "verify: fem\n", "fem", "verify", "'fem' is not allowed; allowed: fe");
  expect_error_at_needle(kEvaluateHead + "verify: [fe]\n", "[fe]", "verify", "found a list");
  expect_error_at_needle(kEvaluateHead + "verify: {method: abaqus}\n", "abaqus", "verify.method", "allowed: fe");
  expect_error_at_needle(kEvaluateHead + "verify: {positions: 0}\n", "0}", "verify.positions", "allowed: 1 <= positions <= 64");
  expect_error_at_needle(kEvaluateHead + "verify: {positions: 65}\n", "65", "verify.positions", "out of range");
  expect_error_at_needle(kEvaluateHead + "verify: {positions: 2.5}\n", "2.5", "verify.positions", "whole");
  expect_error_at_needle(kEvaluateHead + "verify: {level: 7}\n", "7}", "verify.level", "allowed: 0 <= level <= 6");
  expect_error_at_needle(kEvaluateHead + "verify: {extended_contact: maybe}\n", "maybe", "verify.extended_contact", "on");
  expect_error_at_needle(kEvaluateHead + "verify: {positons: 3}\n", "positons", "verify.positons", "did you mean 'positions'");
  expect_error_at_needle(kEvaluateHead + "verfy: fe\n", "verfy", "verfy", "did you mean 'verify'");
}

}  // namespace
}  // namespace rackopt::study
