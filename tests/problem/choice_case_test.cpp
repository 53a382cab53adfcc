// Choice values (effects.hertz, rack.supports, a relief's shape, ...) are
// compared without case, like the study file's (docs/yaml.md): `Linear` and
// `PARABOLIC` give the same Drive as `linear` and `parabolic`; a value that is
// none of the choices still names them and a near miss.
#include <gtest/gtest.h>

#include <string>

#include "problem_test_support.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

// A problem that sets every choice key of the file, each value spelled as given.
std::string problem_with_every_choice(const std::string& linear, const std::string& parabolic,
                                      const std::string& pin_roller, const std::string& per_pair,
                                      const std::string& rack, const std::string& spall, const std::string& sobol,
                                      const std::string& case_hardened, const std::string& normal,
                                      const std::string& load) {
  return "pinion:\n  teeth: 20\n  module: 10 mm\n  face_width: 50 mm\n"
         "  tip_relief: {amount: 20 um, length: 0.3, shape: " +
         parabolic +
         "}\n"
         "rack:\n  body_height: 80 mm\n  span: 2 m\n  supports: " +
         pin_roller +
         "\n"
         "load:\n  force: 10 kN\n"
         "effects: {hertz: " +
         linear + ", rack_span: " + per_pair +
         "}\n"
         "faults:\n  - {type: " +
         spall + ", member: " + rack +
         ", tooth: 1, start: 1 mm, length: 4 mm, width: 5 mm, depth: 0.1 mm}\n"
         "wear:\n  coefficient: 1e-6\n"
         "  hardness: {kind: " +
         case_hardened +
         ", surface: 600 HB, core: 300 HB, case_depth: 2 mm}\n"
         "reliability:\n  sampling: " +
         sobol +
         "\n"
         "  random:\n    - {input: " +
         load + ", distribution: " + normal + ", cv: 0.05}\n";
}

TEST(ChoiceCase, AnyCaseGivesTheSameDriveAsLowerCase) {
  const Drive lower =
      load_problem_text(problem_with_every_choice("linear", "parabolic", "pin-roller", "per_pair", "rack", "spall",
                                                  "sobol", "case_hardened", "normal", "load"),
                        "t.yaml");
  const Drive mixed =
      load_problem_text(problem_with_every_choice("Linear", "PARABOLIC", "Pin-Roller", "Per_Pair", "RACK", "Spall",
                                                  "Sobol", "Case_Hardened", "Normal", "LOAD"),
                        "t.yaml");
  EXPECT_EQ(lower.effects.hertz, HertzModel::kLinear);
  EXPECT_EQ(lower.pinion.tip_relief.shape, ProfileRelief::Shape::kParabolic);
  EXPECT_EQ(lower.rack.supports, Supports::kPinRoller);
  EXPECT_EQ(lower.effects.rack_span, RackSpanModel::kPerPair);
  EXPECT_EQ(lower.spalls.at(0).member, Member::kRack);
  EXPECT_TRUE(lower.reliability.sobol);
  EXPECT_EQ(lower.wear.rack_hardness.kind, HardnessProfile::Kind::kCaseHardened);
  ASSERT_EQ(lower.reliability.inputs.size(), 1u);

  EXPECT_EQ(mixed.effects.hertz, lower.effects.hertz);
  EXPECT_EQ(mixed.pinion.tip_relief.shape, lower.pinion.tip_relief.shape);
  EXPECT_EQ(mixed.rack.supports, lower.rack.supports);
  EXPECT_EQ(mixed.effects.rack_span, lower.effects.rack_span);
  EXPECT_EQ(mixed.spalls.at(0).member, lower.spalls.at(0).member);
  EXPECT_EQ(mixed.reliability.sobol, lower.reliability.sobol);
  EXPECT_EQ(mixed.wear.pinion_hardness.kind, lower.wear.pinion_hardness.kind);
  EXPECT_EQ(mixed.wear.rack_hardness.kind, lower.wear.rack_hardness.kind);
  EXPECT_EQ(mixed.wear.rack_hardness.limit, lower.wear.rack_hardness.limit);
  ASSERT_EQ(mixed.reliability.inputs.size(), 1u);
  EXPECT_EQ(mixed.reliability.inputs[0].key, lower.reliability.inputs[0].key);
  EXPECT_EQ(mixed.reliability.inputs[0].distribution, lower.reliability.inputs[0].distribution);
  EXPECT_EQ(mixed.reliability.inputs[0].cv, lower.reliability.inputs[0].cv);
}

TEST(ChoiceCase, OverridesTakeAnyCaseToo) {
  const Drive d =
      load_problem_text(test::kMinimal, "t.yaml", {"effects.hertz=Weber_Banaschek", "rack.supports=PIN-PIN"});
  EXPECT_EQ(d.effects.hertz, HertzModel::kWeberBanaschek);
  EXPECT_EQ(d.rack.supports, Supports::kPinPin);
}

TEST(ChoiceCase, AWrongValueNamesTheChoicesAndANearMiss) {
  const std::string text = std::string(test::kMinimal) +
                           "effects:\n"          // 10
                           "  hertz: Linaer\n";  // 11
  test::expect_error(text,
                     {11, 10, "effects.hertz", "'Linaer' is not allowed; allowed: off | linear | weber_banaschek"});
  test::expect_error(text, {11, 10, "effects.hertz", "did you mean 'linear'?"});
  test::expect_error(test::kMinimal, {0, 0, "rack.supports", "did you mean 'pin-roller'?", "<command line>"},
                     {"rack.supports=Pin-Rollr"});
  test::expect_error(test::kMinimal, {0, 0, "rack.supports", "allowed: pin-pin | pin-roller", "<command line>"},
                     {"rack.supports=Pin-Rollr"});
}

}  // namespace
}  // namespace rackopt
