// A pareto study's front: the population method end to end, the quality
// figures and the shortfall report of the scalarized methods.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rackopt/solvers/front_quality.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "rackopt/study/study_runner.hpp"
#include "study_test_support.hpp"

namespace rackopt::study {
namespace {

using namespace rackopt::study::testing;

StudySpec span_and_angle_front() {
  StudySpec s = railway_spec(StudyKind::kPareto);
  s.variables = {continuous("rack.span", 1.0, 3.0), continuous("pinion.pressure_angle", 12 * kDeg, 20 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation"), objective("supports_per_metre")};
  s.constraints = {constraint("contact_ratio", 1.3)};
  return s;
}

TEST(StudyParetoPopulation, Nsga2DeliversTheRequestedFeasibleFrontWithItsQuality) {
  StudySpec s = span_and_angle_front();
  s.solver.library = "pagmo";
  s.solver.algorithm = "nsga2";
  s.solver.max_evaluations = 24 * 12;
  s.pareto.method = solvers::Scalarization::kPopulation;
  s.pareto.points = 8;
  const StudyResult r = run_study(s, options_in(scratch_path("nsga2")));
  EXPECT_EQ(to_string(r.status), "ok");
  ASSERT_EQ(r.front.size(), 8u);
  EXPECT_LE(r.evaluations, 24u * 12u);
  for (const DesignResult& p : r.front) {
    EXPECT_TRUE(p.feasible);
    EXPECT_GE(metric(p, "contact_ratio"), 1.3 * (1 - s.solver.constraint_tolerance));
    EXPECT_DOUBLE_EQ(p.objectives[1], 1.0 / p.x[0]);  // supports per metre is 1/span
    EXPECT_NE(p.label.find("nsga2 generation"), std::string::npos) << p.label;
  }
  for (std::size_t i = 1; i < r.front.size(); ++i) EXPECT_LE(r.front[i - 1].objectives[0], r.front[i].objectives[0]);

  ASSERT_TRUE(r.front_summary);
  const FrontSummary& f = *r.front_summary;
  EXPECT_EQ(f.requested, 8u);
  EXPECT_TRUE(f.shortfall.empty());
  EXPECT_EQ(f.quality.non_dominated, 8u);
  // The summary's figures are those of the front's own vectors (both
  // objectives minimized: the own units as they are).
  solvers::ObjectiveVectors v;
  for (const DesignResult& p : r.front) v.push_back(p.objectives);
  const solvers::FrontQuality q = solvers::front_quality(v);
  EXPECT_DOUBLE_EQ(f.quality.hypervolume, q.hypervolume);
  EXPECT_DOUBLE_EQ(f.quality.spacing, q.spacing);
  EXPECT_GT(q.hypervolume, 0.3);
  // The history ends after every evaluation, never falls and ends at least
  // at the delivered front's hypervolume (the front is a thinned subset).
  ASSERT_FALSE(f.history_evaluations.empty());
  EXPECT_EQ(f.history_evaluations.back(), r.evaluations);
  for (std::size_t k = 1; k < f.history_hypervolume.size(); ++k)
    EXPECT_GE(f.history_hypervolume[k], f.history_hypervolume[k - 1]);
  EXPECT_GE(f.history_hypervolume.back(), f.quality.hypervolume - 1e-12);
}

TEST(StudyParetoPopulation, Nsga2SearchesAModuleListAsAnIntegerInOneRun) {
  // Over the span only the support count and the ripple trade; the module
  // list adds a whole-valued variable. One NSGA-II run with one budget
  // (not one per module), every design's module from the list, a front of
  // feasible non-dominated designs that can mix modules.
  const std::vector<double> modules = {0.025, 0.031831, 0.04};
  StudySpec s = span_and_angle_front();
  s.variables.push_back(discrete("pinion.module", modules));
  s.solver.library = "pagmo";
  s.solver.algorithm = "nsga2";
  s.solver.max_evaluations = 24 * 10;
  s.pareto.method = solvers::Scalarization::kPopulation;
  s.pareto.points = 8;
  const std::string dir = scratch_path("nsga2_integers");
  const StudyResult r = run_study(s, options_in(dir));
  EXPECT_EQ(to_string(r.status), "ok");
  EXPECT_LE(r.evaluations, 24u * 10u + 1u);
  ASSERT_EQ(r.front.size(), 8u);
  for (const auto& rec : rows_of(r, s))
    EXPECT_NE(std::find(modules.begin(), modules.end(), rec.x[2]), modules.end()) << rec.x[2];
  for (const DesignResult& p : r.front) {
    EXPECT_TRUE(p.feasible);
    EXPECT_EQ(p.label.find("combination"), std::string::npos) << p.label;  // one run, no per-module phase
    for (const DesignResult& q : r.front)
      EXPECT_FALSE(q.objectives[0] < p.objectives[0] && q.objectives[1] < p.objectives[1]);
  }
}

TEST(StudyParetoPopulation, ResumeGivesTheSameFrontFromTheStore) {
  StudySpec s = span_and_angle_front();
  s.solver.library = "pagmo";
  s.solver.algorithm = "moead";
  s.solver.max_evaluations = 24 * 4;
  s.pareto.method = solvers::Scalarization::kPopulation;
  s.pareto.points = 5;
  const std::string dir = scratch_path("moead_resume");
  const StudyResult first = run_study(s, options_in(dir));
  RunOptions again = options_in(dir);
  again.resume = true;
  const StudyResult second = run_study(s, again);
  EXPECT_EQ(second.reused_evaluations, first.evaluations);
  ASSERT_EQ(first.front.size(), second.front.size());
  for (std::size_t i = 0; i < first.front.size(); ++i) EXPECT_EQ(first.front[i].x, second.front[i].x);
  ASSERT_TRUE(first.front_summary && second.front_summary);
  EXPECT_EQ(first.front_summary->history_hypervolume, second.front_summary->history_hypervolume);
}

TEST(StudyParetoScalarized, AShortFrontSaysWhichSubProblemsGaveNoNewPoint) {
  // Four points with a tiny budget per sub-problem: some give duplicates or
  // dominated designs, and the summary must name them.
  StudySpec s = span_and_angle_front();
  s.pareto.points = 12;
  s.pareto.duplicate_tolerance = 0.2;  // a coarse front: neighbours within 20 % of the range are one point
  s.solver.max_evaluations = 30;
  const StudyResult r = run_study(s, options_in(scratch_path("eps_short")));
  ASSERT_TRUE(r.front_summary);
  ASSERT_LT(r.front.size(), 12u);
  ASSERT_FALSE(r.front_summary->shortfall.empty());
  bool names_a_subproblem = false;
  for (const std::string& line : r.front_summary->shortfall)
    names_a_subproblem = names_a_subproblem || line.find("eps ") != std::string::npos;
  EXPECT_TRUE(names_a_subproblem) << r.front_summary->shortfall.front();
}

}  // namespace
}  // namespace rackopt::study
