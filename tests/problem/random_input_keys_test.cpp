// reliability.random around the design (the default) and absolute (opt-in),
// and the one map of problem keys -> the random inputs whose design value
// they change: an override of such a key next to an absolute input is an
// InputError naming both keys.
#include "problem_test_support.hpp"
#include "support/text_position.hpp"
#include "rackopt/problem/random_input_keys.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

using test::kHB;  // Pa per Brinell number

std::string ship_lift() { return std::string(RACKOPT_SOURCE_DIR) + "/problems/ship_lift.yaml"; }

const std::string kWearWithRandom =
    "pinion: {teeth: 20, module: 10 mm, face_width: 50 mm}\n"  // 1
    "rack: {body_height: 80 mm, span: 2 m}\n"                    // 2
    "load: {force: 10 kN}\n"                                     // 3
    "wear: {coefficient: 1e-6, hardness: 600 HB}\n"              // 4
    "reliability:\n"                                             // 5
    "  random:\n";                                               // 6; items from line 7

void expect_error_located_at(const std::string& text, const std::string& at, const std::string& key,
                             const std::vector<std::string>& parts) {
  const auto [line, column] = test_support::line_column_of(text, at);
  test_support::expect_input_error([&] { (void)load_problem_text(text, "t.yaml"); },
                                   {.line = line, .column = column, .key = key, .in_what = parts});
}

TEST(RandomInputForms, AroundTheDesignIsTheDefault) {
  const Drive d = load_problem_text(kWearWithRandom +
                                        "    - {input: contact_ratio, distribution: normal, shift: -0.1, sd: 0.03}\n"
                                        "    - {input: wear_coefficient, distribution: lognormal, sigma: 0.3}\n"
                                        "    - {input: load, distribution: normal, cv: 0.05}\n"
                                        "    - {input: surface_hardness, distribution: uniform, half_width: 20 HB, "
                                        "shift: -5 HB}\n",
                                    "t.yaml");
  const auto& in = d.reliability.inputs;
  ASSERT_EQ(in.size(), 4u);
  for (const auto& i : in) EXPECT_FALSE(i.absolute) << i.key;
  EXPECT_DOUBLE_EQ(in[0].a, -0.1);  // shift
  EXPECT_DOUBLE_EQ(in[0].b, 0.03);  // sd
  EXPECT_EQ(in[1].distribution, RandomInput::Distribution::kLognormal);
  EXPECT_DOUBLE_EQ(in[1].a, 1.0);   // median factor: the design's value
  EXPECT_DOUBLE_EQ(in[1].b, 0.3);
  EXPECT_DOUBLE_EQ(in[2].cv, 0.05);
  EXPECT_DOUBLE_EQ(in[2].a, 0.0);   // no shift
  EXPECT_EQ(in[3].distribution, RandomInput::Distribution::kUniform);
  EXPECT_DOUBLE_EQ(in[3].a, -25 * kHB);  // shift - half width
  EXPECT_DOUBLE_EQ(in[3].b, 15 * kHB);
}

TEST(RandomInputForms, AbsoluteParametersNeedTheOptIn) {
  const std::string mean = kWearWithRandom + "    - {input: contact_ratio, distribution: normal, mean: 1.44, sd: 0.038}\n";
  expect_error_located_at(mean, "mean:", "reliability.random[0].mean",
                          {"gives an absolute distribution", "absolute: true", "shift", "sd", "cv"});
  const std::string weibull = kWearWithRandom + "    - {input: load, distribution: weibull, shape: 3}\n";
  expect_error_located_at(weibull, "weibull", "reliability.random[0].distribution", {"absolute: true", "lognormal"});
  const std::string both = kWearWithRandom + "    - {input: load, distribution: normal, sd: 1 kN, cv: 0.1}\n";
  expect_error_located_at(both, "cv:", "reliability.random[0].cv", {"not both"});
  const std::string cv = kWearWithRandom + "    - {input: load, distribution: normal, cv: 1.5}\n";
  expect_error_located_at(cv, "1.5", "reliability.random[0].cv", {"0 < cv < 1"});
  const std::string foreign = kWearWithRandom + "    - {input: load, distribution: lognormal, sigma: 0.1, sd: 1 kN}\n";
  expect_error_located_at(foreign, "sd:", "reliability.random[0].sd",
                          {"not a parameter of a lognormal distribution around the design", "sigma, median_factor"});
  const std::string shift_abs = kWearWithRandom + "    - {input: load, distribution: normal, absolute: true, mean: 1 kN, "
                                        "sd: 1 kN, shift: 1 kN}\n";
  expect_error_located_at(shift_abs, "shift:", "reliability.random[0].shift", {"absolute normal", "mean, sd"});
}

TEST(RandomInputKeys, OneMapOfKeysToInputs) {
  const Drive force = load_problem_text(kWearWithRandom, "t.yaml");         // load given as a force
  const Drive torque = load_problem(ship_lift());                  // load given as a torque
  using V = std::vector<std::string>;
  EXPECT_EQ(random_inputs_changed_by("mounting.clearance", force), V{"contact_ratio"});
  EXPECT_EQ(random_inputs_changed_by(" pinion.profile_shift ", force), V{"contact_ratio"});
  EXPECT_EQ(random_inputs_changed_by("rack.addendum", force), V{"contact_ratio"});
  EXPECT_EQ(random_inputs_changed_by("effects.interference_limit", force), V{"contact_ratio"});
  EXPECT_EQ(random_inputs_changed_by("pinion.module", force), V{"contact_ratio"});
  EXPECT_EQ(random_inputs_changed_by("pinion.module", torque), (V{"contact_ratio", "load"}));  // F = T / r_b
  EXPECT_EQ(random_inputs_changed_by("pinion", force), V{"contact_ratio"});  // the whole section
  EXPECT_EQ(random_inputs_changed_by("wear.coefficient", force), V{"wear.coefficient"});
  EXPECT_EQ(random_inputs_changed_by("wear", force), (V{"wear.coefficient", "surface_hardness"}));
  EXPECT_EQ(random_inputs_changed_by("load.torque", force), V{"load"});
  EXPECT_EQ(random_inputs_changed_by("wear.hardness.coefficients[0]", force), V{"surface_hardness"});
  EXPECT_EQ(random_inputs_changed_by("wear.rack_hardness", force), V{"surface_hardness"});
  for (const char* none : {"pinion.face_width", "materials.steel.E", "rack.span", "load.application_factor",
                           "wear.hardness.case_depth", "wear.hardness.valid_depth", "duty.rack_meshes_per_year",
                           "reliability.random[0].sd", "variant", "mountingx"}) {
    EXPECT_TRUE(random_inputs_changed_by(none, torque).empty()) << none;
  }
}

// The clearance case of the ship lift: its contact ratio made absolute, a
// --set of the clearance would be ignored by the life at R: refused.
TEST(RandomInputKeys, OverrideOfAKeyThatMovesAnAbsoluteInputNamesBoth) {
  const std::string absolute =
      "reliability.random[0]={input: contact_ratio, distribution: normal, absolute: true, mean: 1.44, sd: 0.038}";
  try {
    (void)load_problem(ship_lift(), {absolute, "mounting.clearance=4 mm"});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.mark().file, "<command line>");
    EXPECT_EQ(e.key_path(), "mounting.clearance");
    EXPECT_NE(std::string(e.what()).find("reliability.random[0]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contact_ratio"), std::string::npos) << e.what();
  }
  // The torque load moves with the module: an absolute load is refused too.
  EXPECT_THROW((void)load_problem(ship_lift(), {"reliability.random[1]={input: load, distribution: normal, "
                                                "absolute: true, mean: 956 kN, sd: 10 kN}",
                                                "pinion.module=60 mm"}),
               InputError);
  // Keys that change nothing random, or an input around the design: fine.
  EXPECT_NO_THROW((void)load_problem(ship_lift(), {absolute, "rack.span=2 m", "wear.coefficient=1e-6"}));
  EXPECT_NO_THROW((void)load_problem(ship_lift(), {"mounting.clearance=4 mm"}));
}

}  // namespace
}  // namespace rackopt
