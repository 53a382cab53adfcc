#include "rackopt/study/study_kind_rules.hpp"

#include <gtest/gtest.h>

#include "rackopt/core/error.hpp"
#include "rackopt/study/study_runner.hpp"
#include "study_test_support.hpp"

namespace rackopt::study {
namespace {

using testing::continuous;
using testing::discrete;
using testing::objective;
using testing::railway_spec;

StudySpec optimize_spec() {
  StudySpec s = railway_spec(StudyKind::kOptimize);
  s.variables = {continuous("rack.span", 1.0, 3.0)};
  s.objectives = {objective("stiffness_fluctuation")};
  return s;
}

TEST(StudyKindRules, AWellFormedStudyPasses) {
  EXPECT_EQ(check_study_kind_rules(optimize_spec()), std::nullopt);
  StudySpec evaluate = railway_spec(StudyKind::kEvaluate);
  EXPECT_EQ(check_study_kind_rules(evaluate), std::nullopt);  // no variables: the problem's own design
}

TEST(StudyKindRules, ObjectiveCountsPerKind) {
  StudySpec two = optimize_spec();
  two.objectives.push_back(objective("contact_ratio"));
  const auto v = check_study_kind_rules(two);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->part, StudyRulePart::kObjectives);
  EXPECT_NE(v->message.find("exactly one objective, found 2"), std::string::npos) << v->message;

  StudySpec pareto = two;
  pareto.kind = StudyKind::kPareto;
  EXPECT_EQ(check_study_kind_rules(pareto), std::nullopt);
  pareto.objectives.resize(1);
  ASSERT_TRUE(check_study_kind_rules(pareto));
  EXPECT_NE(check_study_kind_rules(pareto)->message.find("2 or 3 objectives"), std::string::npos);
}

TEST(StudyKindRules, VariablesStartsAndSizes) {
  StudySpec none = optimize_spec();
  none.variables.clear();
  EXPECT_EQ(check_study_kind_rules(none)->part, StudyRulePart::kVariables);

  StudySpec evaluate = railway_spec(StudyKind::kEvaluate);
  evaluate.variables = {continuous("rack.span", 1.0, 3.0, 2.0), continuous("pinion.pressure_angle", 0.3, 0.4)};
  const auto start = check_study_kind_rules(evaluate);
  ASSERT_TRUE(start);
  EXPECT_EQ(start->part, StudyRulePart::kVariable);
  EXPECT_EQ(start->variable, 1u);
  EXPECT_EQ(study_rule_key(*start, evaluate), "variables.pinion.pressure_angle");

  StudySpec grid = railway_spec(StudyKind::kSweep);
  grid.variables = {continuous("rack.span", 1.0, 3.0), continuous("pinion.pressure_angle", 0.3, 0.4)};
  grid.sweep.levels = 11;
  grid.sweep.max_points = 121;
  EXPECT_EQ(check_study_kind_rules(grid), std::nullopt);  // 11 x 11 fits exactly
  grid.sweep.max_points = 100;
  const auto big = check_study_kind_rules(grid);
  ASSERT_TRUE(big);
  EXPECT_EQ(big->part, StudyRulePart::kSweepGrid);
  EXPECT_NE(big->message.find("121 points (rack.span 11 x pinion.pressure_angle 11)"), std::string::npos)
      << big->message;
  grid.sweep.method = SweepSpec::Method::kSobol;
  grid.sweep.points = 101;
  EXPECT_EQ(check_study_kind_rules(grid)->part, StudyRulePart::kSweepPoints);

  StudySpec combos = optimize_spec();
  combos.variables.push_back(discrete("pinion.module", {0.01, 0.012, 0.016}));
  combos.variables.push_back(discrete("pinion.teeth", {14, 16, 18}));
  combos.max_discrete_combinations = 8;
  const auto many = check_study_kind_rules(combos);
  ASSERT_TRUE(many);
  EXPECT_EQ(many->part, StudyRulePart::kVariables);
  EXPECT_NE(many->message.find("9 combinations"), std::string::npos) << many->message;
}

TEST(StudyKindRules, SolverShapeCountsContinuousVariablesAndConstraintSides) {
  StudySpec s = optimize_spec();
  s.variables.push_back(discrete("pinion.module", {0.01, 0.012}));
  s.constraints = {testing::constraint("contact_ratio", 1.2, 2.0)};
  const solvers::ProblemShape shape = solver_problem_shape(s);
  EXPECT_EQ(shape.dimension, 1u);
  EXPECT_EQ(shape.inequality, 2u);
  EXPECT_EQ(shape.equality, 0u);

  s.solver.algorithm = "LN_BOBYQA";  // no constraints
  const auto v = check_study_kind_rules(s);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->part, StudyRulePart::kSolverAlgorithm);
  EXPECT_EQ(study_rule_key(*v, s), "solver.algorithm");

  // An eps-constraint front adds one bound per further objective.
  StudySpec pareto = railway_spec(StudyKind::kPareto);
  pareto.variables = {continuous("rack.span", 1.0, 3.0)};
  pareto.objectives = {objective("stiffness_fluctuation"), objective("contact_ratio", true)};
  pareto.solver.algorithm = "LN_BOBYQA";
  const auto eps = check_study_kind_rules(pareto);
  ASSERT_TRUE(eps);
  EXPECT_EQ(eps->part, StudyRulePart::kParetoMethod);
  pareto.pareto.method = solvers::Scalarization::kWeightedSum;
  EXPECT_EQ(check_study_kind_rules(pareto), std::nullopt);
}

// A spec built in code meets the same rule, with the same words, before any
// file is written.
TEST(StudyKindRules, DiscreteVariablesAreIntegersOnlyForAlgorithmsThatSearchThem) {
  StudySpec s = optimize_spec();
  s.variables.push_back(discrete("pinion.module", {0.02, 0.025, 0.03}));
  s.variables.push_back(discrete("pinion.face_width", {0.1}));  // one value: fixed, never a solver variable
  s.max_discrete_combinations = 2;
  // Enumerated (COBYLA): three combinations are over the limit, named.
  ASSERT_FALSE(searches_discrete_as_integers(s));
  auto v = check_study_kind_rules(s);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->part, StudyRulePart::kVariables);
  EXPECT_NE(v->message.find("algorithm gaco"), std::string::npos) << v->message;
  EXPECT_EQ(solver_problem_shape(s).dimension, 1u);
  // GACO searches the module as an integer: no enumeration, no limit.
  s.solver.library = "pagmo";
  s.solver.algorithm = "gaco";
  s.solver.max_evaluations = 500;
  EXPECT_TRUE(searches_discrete_as_integers(s));
  EXPECT_EQ(check_study_kind_rules(s), std::nullopt);
  const solvers::ProblemShape shape = solver_problem_shape(s);
  EXPECT_EQ(shape.dimension, 2u);
  EXPECT_EQ(shape.integer, 1u);
  // CMA-ES does not: enumerated again.
  s.solver.algorithm = "cmaes";
  EXPECT_FALSE(searches_discrete_as_integers(s));
  // A front: NSGA-II searches integers, MOEA/D does not.
  StudySpec f = s;
  f.kind = StudyKind::kPareto;
  f.objectives.push_back(objective("supports_per_metre"));
  f.pareto.method = solvers::Scalarization::kPopulation;
  f.solver.algorithm = "nsga2";
  EXPECT_TRUE(searches_discrete_as_integers(f));
  f.solver.algorithm = "moead";
  EXPECT_FALSE(searches_discrete_as_integers(f));
}

TEST(StudyKindRules, TheRunnerRefusesWithTheSameMessage) {
  StudySpec two = optimize_spec();
  two.objectives.push_back(objective("contact_ratio"));
  const std::string out = testing::scratch_path("kind_rules_refused");
  RunOptions options;
  options.out_dir = out;
  try {
    run_study(two, options);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "objectives");
    EXPECT_EQ(e.message(), check_study_kind_rules(two)->message);
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(out) / "evaluations.sqlite"));
}

}  // namespace
}  // namespace rackopt::study
