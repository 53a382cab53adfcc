// A variable the solver left a hair off its bound is at that bound in the
// optimum's explanation: solvers stop within their step tolerance of a
// bound (COBYLA does not step onto it at all), so 17.0001 deg on a
// 17..25 deg range is "at its lower bound 17 deg", and the report says
// which bound holds the optimum.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study_report/optimum_report.hpp"
#include "study_test_support.hpp"

namespace rackopt::study {
namespace {

using namespace rackopt::study::testing;

constexpr double kLow = 17 * kDeg, kHigh = 25 * kDeg;

// The contact ratio falls as the pressure angle grows: maximized, it
// pushes the angle into its lower bound; the span does not change it.
StudySpec contact_ratio_spec() {
  StudySpec s = railway_spec(StudyKind::kOptimize);
  DesignVariable angle = continuous("pinion.pressure_angle", kLow, kHigh, 20 * kDeg);
  angle.unit = "deg";
  s.variables = {angle, continuous("rack.span", 1.2, 3.0, 2.0)};
  s.objectives = {objective("contact_ratio", true)};
  return s;
}

TEST(OptimumAtBound, AVariableWithinTheToleranceOfABoundIsAtThatBound) {
  const StudySpec spec = contact_ratio_spec();
  const StudyProblem p(spec);
  const double off = 1e-4 * (kHigh - kLow);
  const OptimumExplanation e = explain_optimum(p, {kLow + off, 2.0});
  ASSERT_EQ(e.variables.size(), 2u);
  const VariableStatus& angle = e.variables[0];
  EXPECT_TRUE(angle.at_lower) << angle.value;
  EXPECT_FALSE(angle.at_upper);
  EXPECT_DOUBLE_EQ(angle.bound_tolerance, kBoundToleranceFloor * (kHigh - kLow));
  ASSERT_TRUE(angle.pushed_into_bound);
  EXPECT_TRUE(*angle.pushed_into_bound);  // a smaller angle would give a larger contact ratio
  EXPECT_FALSE(e.variables[1].at_lower || e.variables[1].at_upper);
  EXPECT_FALSE(e.variables[1].pushed_into_bound);

  StudyResult r;
  r.explanation = e;
  const std::string md = study_report::explanation_markdown(spec, r);
  EXPECT_NE(md.find("Variables at a bound: `pinion.pressure_angle` at its lower bound 17 deg, which holds the optimum"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("No continuous variable is at a bound"), std::string::npos) << md;

  // Ten times the tolerance off the bound is inside the box.
  const OptimumExplanation inside = explain_optimum(p, {kLow + 10 * kBoundToleranceFloor * (kHigh - kLow), 2.0});
  EXPECT_FALSE(inside.variables[0].at_lower);
  EXPECT_FALSE(inside.variables[0].pushed_into_bound);
}

// NLopt stops within max(xtol_abs, xtol_rel) of the unit box it works on;
// a looser tolerance than the floor widens "at a bound" with it. The other
// libraries have no step tolerance: the floor.
TEST(OptimumAtBound, ToleranceFollowsTheSolversStepTolerance) {
  solvers::SolverSettings s;
  EXPECT_EQ(bound_tolerance_fraction(s), kBoundToleranceFloor);
  s.xtol_rel = 1e-2;
  EXPECT_EQ(bound_tolerance_fraction(s), 1e-2);
  s.xtol_rel = 0;
  s.xtol_abs = 5e-3;
  EXPECT_EQ(bound_tolerance_fraction(s), 5e-3);
  s.library = "ipopt";
  EXPECT_EQ(bound_tolerance_fraction(s), kBoundToleranceFloor);
}

}  // namespace
}  // namespace rackopt::study
