// StudyProblem's mapping (study_problem.hpp), checked against the rules its
// header states, computed here by hand: the unit box of the continuous
// variables, objectives minimized and scaled, each constraint bound one
// normalized inequality or equality, the discrete combinations in order with
// their labels.
#include "rackopt/study/study_problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "study_test_support.hpp"

namespace rackopt::study {
namespace {

using namespace rackopt::study::testing;

constexpr double kLowA = 17 * kDeg, kHighA = 25 * kDeg;

// Two continuous variables (one with a start) and two discrete ones
// (module in mm, teeth as a count).
StudySpec mapped_spec() {
  StudySpec s = railway_spec(StudyKind::kOptimize);
  DesignVariable module = discrete("pinion.module", {0.020, 0.025, 0.032});
  module.unit = "mm";
  s.variables = {continuous("pinion.pressure_angle", kLowA, kHighA, 20 * kDeg), module,
                 continuous("rack.span", 1.2, 3.0), discrete("pinion.teeth", {20, 22})};
  s.objectives = {objective("stiffness_fluctuation")};
  return s;
}

TEST(StudyProblem, OnlyTheContinuousVariablesOnTheUnitBox) {
  const StudyProblem p(mapped_spec());
  ASSERT_EQ(p.dimension(), 2u);
  EXPECT_EQ(p.continuous_indices(), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(p.discrete_indices(), (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(p.lower_bounds(), (std::vector<double>{0, 0}));
  EXPECT_EQ(p.upper_bounds(), (std::vector<double>{1, 1}));
  EXPECT_EQ(p.variable_keys(),
            (std::vector<std::string>{"pinion.pressure_angle", "pinion.module", "rack.span", "pinion.teeth"}));
}

TEST(StudyProblem, ToDesignScalesClampsAndHitsTheBoundsExactly) {
  const StudyProblem p(mapped_spec());
  const std::vector<double> ends = p.to_design(std::vector<double>{0.0, 1.0});
  ASSERT_EQ(ends.size(), 4u);
  EXPECT_EQ(ends[0], kLowA);
  EXPECT_EQ(ends[2], 3.0);
  // Discrete variables come from the view's combination (0: the first values).
  EXPECT_EQ(ends[1], 0.020);
  EXPECT_EQ(ends[3], 20.0);
  const std::vector<double> inside = p.to_design(std::vector<double>{0.25, 0.5});
  EXPECT_NEAR(inside[0], kLowA + 0.25 * (kHighA - kLowA), 1e-15);
  EXPECT_NEAR(inside[2], 1.2 + 0.5 * 1.8, 1e-15);
  const std::vector<double> outside = p.to_design(std::vector<double>{-0.5, 1.5});
  EXPECT_EQ(outside[0], kLowA);
  EXPECT_EQ(outside[2], 3.0);
}

TEST(StudyProblem, StartIsTheGivenStartElseTheMidpoint) {
  const StudyProblem p(mapped_spec());
  const std::vector<double> u = p.start_unit();
  ASSERT_EQ(u.size(), 2u);
  EXPECT_NEAR(u[0], (20.0 - 17.0) / (25.0 - 17.0), 1e-14);
  EXPECT_NEAR(u[1], 0.5, 1e-15);
  const std::vector<double> x = p.start_design();
  EXPECT_NEAR(x[0], 20 * kDeg, 1e-15);
  EXPECT_NEAR(x[2], 2.1, 1e-15);
  EXPECT_EQ(x[1], 0.020);
  EXPECT_EQ(x[3], 20.0);
  // A discrete start wins over the combination's value.
  StudySpec s = mapped_spec();
  s.variables[3].start = 22;
  EXPECT_EQ(StudyProblem(s).for_combination(0).start_design()[3], 22.0);
}

TEST(StudyProblem, CombinationsEnumerateTheLastDiscreteVariableFastest) {
  const StudyProblem p(mapped_spec());
  ASSERT_EQ(p.num_combinations(), 6u);
  const std::vector<std::vector<double>> want = {{0.020, 20}, {0.020, 22}, {0.025, 20},
                                                 {0.025, 22}, {0.032, 20}, {0.032, 22}};
  for (std::size_t c = 0; c < want.size(); ++c) {
    const StudyProblem v = p.for_combination(c);
    EXPECT_EQ(v.combination(), c);
    const std::vector<double> x = v.to_design(std::vector<double>{0.5, 0.5});
    EXPECT_EQ(x[1], want[c][0]) << c;
    EXPECT_EQ(x[3], want[c][1]) << c;
  }
  // The documented form of a label, in the variables' display units.
  EXPECT_EQ(p.for_combination(3).combination_label(), "pinion.module=25 mm, pinion.teeth=22");
  // Without discrete variables there is one combination and no label.
  StudySpec continuous_only = mapped_spec();
  continuous_only.variables = {continuous_only.variables[0], continuous_only.variables[2]};
  const StudyProblem c(continuous_only);
  EXPECT_EQ(c.num_combinations(), 1u);
  EXPECT_EQ(c.combination_label(), "");
}

// Objectives: (maximize ? -v : v) / scale. Constraints in spec order, min
// before max: (min - v)/s <= 0, (v - max)/s <= 0, (v - equals)/s == 0 with
// s = the spec's scale, else |bound|, else 1.
TEST(StudyProblem, MapMetricsMinimizesScalesAndNormalizesTheBounds) {
  StudySpec s = mapped_spec();
  s.objectives = {objective("stiffness_fluctuation"), objective("min_stiffness", true)};
  s.objectives[0].scale = 2;
  s.objectives[1].scale = 4;
  s.constraints = {constraint("contact_ratio", 1.3, 2.0), constraint("supports_per_metre", std::nullopt, 0.0)};
  ConstraintSpec eq = constraint("pinion_mass", std::nullopt);
  eq.equals = 5;
  eq.scale = 0.5;
  s.constraints.push_back(eq);
  const StudyProblem p(s);
  ASSERT_EQ(p.metric_labels(), (std::vector<std::string>{"stiffness_fluctuation", "min_stiffness", "contact_ratio",
                                                         "supports_per_metre", "pinion_mass"}));
  EXPECT_EQ(p.num_objectives(), 2u);
  EXPECT_EQ(p.num_inequality(), 3u);
  EXPECT_EQ(p.num_equality(), 1u);

  const double fluct = 0.3, kmin = 2e8, cr = 1.5, spm = 0.25, mass = 6;
  const std::vector<double> values = {fluct, kmin, cr, spm, mass};
  const solvers::Evaluation e = p.map_metrics(values, std::vector<bool>(5, true), "");
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_EQ(e.objectives.size(), 2u);
  EXPECT_DOUBLE_EQ(e.objectives[0], fluct / 2);
  EXPECT_DOUBLE_EQ(e.objectives[1], -kmin / 4);
  ASSERT_EQ(e.inequality.size(), 3u);
  EXPECT_DOUBLE_EQ(e.inequality[0], (1.3 - cr) / 1.3);
  EXPECT_DOUBLE_EQ(e.inequality[1], (cr - 2.0) / 2.0);
  EXPECT_DOUBLE_EQ(e.inequality[2], (spm - 0.0) / 1.0);  // a bound of 0: scale 1
  ASSERT_EQ(e.equality.size(), 1u);
  EXPECT_DOUBLE_EQ(e.equality[0], (mass - 5) / 0.5);

  // A metric that failed fails the evaluation with the message given.
  std::vector<bool> ok(5, true);
  ok[3] = false;
  const solvers::Evaluation f = p.map_metrics(values, ok, "supports_per_metre: no supports");
  EXPECT_FALSE(f.ok());
  EXPECT_EQ(f.message, "supports_per_metre: no supports");
}

TEST(StudyProblem, AutomaticObjectiveScalesComeFromTheStartDesign) {
  StudySpec s = mapped_spec();
  s.objectives = {objective("stiffness_fluctuation"), objective("min_stiffness", true), objective("contact_ratio")};
  s.objectives[2].scale = 3;  // explicit: kept
  StudyProblem p(s);
  // Until set, an automatic scale is 1.
  EXPECT_EQ(p.objective_scales(), (std::vector<double>{1, 1, 3}));
  DesignEvaluation start;
  start.metric_values = {-0.4, 0.0, 1.6};
  start.metric_ok = {true, true, true};
  p.set_objective_scales_from(start);
  // |value|, and 1 where the value is 0.
  EXPECT_EQ(p.objective_scales(), (std::vector<double>{0.4, 1, 3}));
  const solvers::Evaluation e = p.map_metrics(std::vector<double>{0.2, 5.0, 1.5}, {true, true, true}, "");
  EXPECT_DOUBLE_EQ(e.objectives[0], 0.2 / 0.4);
  EXPECT_DOUBLE_EQ(e.objectives[1], -5.0);
  EXPECT_DOUBLE_EQ(e.objectives[2], 1.5 / 3);
  // A start whose metric failed leaves the automatic scale at 1.
  StudyProblem q(s);
  start.metric_ok = {false, true, true};
  start.metric_values = {0.0, 7.0, 1.6};
  q.set_objective_scales_from(start);
  EXPECT_EQ(q.objective_scales(), (std::vector<double>{1, 7, 3}));
}

}  // namespace
}  // namespace rackopt::study
