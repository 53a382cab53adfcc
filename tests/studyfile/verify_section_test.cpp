// The study file's `verify` key: both forms load with their defaults, and
// every mistake is refused at its file:line:column with the key path.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/studyfile/study_loader.hpp"
#include "studyfile_test_support.hpp"
#include "support/input_error_expectations.hpp"
#include "support/text_position.hpp"

namespace rackopt::study {
namespace {

using test::load;
const std::string kEvaluateHead =
    "study: {kind: evaluate}\n"
    "problem: ../problems/gantry_axis.yaml\n";

void expect_error_at_needle(const std::string& text, const std::string& needle, const std::string& key,
                            const std::string& says) {
  test_support::expect_input_error([&] { (void)load(text); },
                                   {.mark = "t.yaml:" + test_support::position_of(text, needle), .key = key,
                                    .in_what = {says}});
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
