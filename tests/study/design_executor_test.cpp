// Batches of designs on an executor: the same record and results whoever
// computes them.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "rackopt/solvers/pareto.hpp"
#include "rackopt/study/design_executor.hpp"
#include "rackopt/study/study_runner.hpp"
#include "study_test_support.hpp"

namespace rackopt::study {
namespace {

using namespace rackopt::study::testing;

// Computes every batch backwards (as independent workers might finish) and
// logs the batch sizes.
class BackwardsExecutor final : public DesignExecutor {
 public:
  std::vector<DesignEvaluation> evaluate(const StudyProblem& problem, const std::vector<std::vector<double>>& xs,
                                         unsigned) override {
    sizes.push_back(xs.size());
    std::vector<DesignEvaluation> out(xs.size());
    for (std::size_t k = xs.size(); k-- > 0;) out[k] = problem.evaluate_design(xs[k], 1);
    return out;
  }
  unsigned workers() const override { return 3; }
  std::string describe() const override { return "backwards"; }
  std::vector<std::size_t> sizes;
};

StudySpec population_study() {
  StudySpec s = railway_spec(StudyKind::kPareto);
  s.variables = {continuous("rack.span", 1.0, 3.0), continuous("pinion.pressure_angle", 12 * kDeg, 20 * kDeg)};
  s.objectives = {objective("stiffness_fluctuation"), objective("supports_per_metre")};
  s.constraints = {constraint("contact_ratio", 1.3)};
  s.solver.library = "pagmo";
  s.solver.algorithm = "nsga2";
  s.solver.max_evaluations = 24 * 4;
  s.pareto.method = solvers::Scalarization::kPopulation;
  s.pareto.points = 6;
  return s;
}

void expect_same_results(const StudyResult& a, const StudyResult& b) {
  ASSERT_EQ(a.evaluations, b.evaluations);
  ASSERT_EQ(a.front.size(), b.front.size());
  for (std::size_t i = 0; i < a.front.size(); ++i) {
    EXPECT_EQ(a.front[i].x, b.front[i].x);
    EXPECT_EQ(a.front[i].metric_values, b.front[i].metric_values);
    EXPECT_EQ(a.front[i].label, b.front[i].label);
  }
  EXPECT_EQ(a.best_history, b.best_history);
}

TEST(DesignExecutor, APopulationStudyGivesTheSameResultOnEveryExecutor) {
  const StudySpec s = population_study();
  const StudyResult serial = run_study(s, options_in(scratch_path("exec_serial"), 1));
  const StudyResult threads = run_study(s, options_in(scratch_path("exec_threads"), 2));
  RunOptions backwards_options = options_in(scratch_path("exec_backwards"), 1);
  auto backwards = std::make_shared<BackwardsExecutor>();
  backwards_options.executor = backwards;
  const StudyResult other = run_study(s, backwards_options);
  expect_same_results(serial, threads);
  expect_same_results(serial, other);
  // The start design alone, the first population, then one batch per generation.
  ASSERT_GE(backwards->sizes.size(), 3u);
  EXPECT_EQ(*std::max_element(backwards->sizes.begin(), backwards->sizes.end()), 24u);
}

// Optimize and pareto studies over a module list: one COBYLA run per module,
// the runs in lockstep, so a batch holds one request of every run.
TEST(DesignExecutor, EnumeratedCombinationsGiveTheSameRecordOnEveryExecutorAndShareBatches) {
  for (StudyKind kind : {StudyKind::kOptimize, StudyKind::kPareto}) {
    StudySpec s = railway_spec(kind);
    s.variables = {discrete("pinion.module", {0.025, 0.031831, 0.04}),
                   continuous("pinion.pressure_angle", 12 * kDeg, 20 * kDeg)};
    s.objectives = {objective("stiffness_fluctuation")};
    if (kind == StudyKind::kPareto) {
      s.variables.push_back(continuous("rack.span", 1.0, 3.0));
      s.objectives.push_back(objective("supports_per_metre"));
      s.pareto.points = 4;
    }
    s.constraints = {constraint("contact_ratio", 1.3)};
    s.solver.max_evaluations = 30;
    const std::string name = kind == StudyKind::kOptimize ? "lockstep_optimize" : "lockstep_pareto";
    const StudyResult serial = run_study(s, options_in(scratch_path(name + "_serial"), 1));
    const StudyResult threads = run_study(s, options_in(scratch_path(name + "_threads"), 2));
    RunOptions backwards_options = options_in(scratch_path(name + "_backwards"), 1);
    auto backwards = std::make_shared<BackwardsExecutor>();
    backwards_options.executor = backwards;
    const StudyResult other = run_study(s, backwards_options);
    expect_same_results(serial, threads);
    expect_same_results(serial, other);
    ASSERT_TRUE(serial.best && other.best);
    EXPECT_EQ(serial.best->x, other.best->x);
    const auto a = rows_of(serial, s), b = rows_of(other, s);
    ASSERT_EQ(a.size(), b.size());
    // Runs that ask for the same design in one round (the anchors all start
    // from x0, COBYLA's first simplex with them) record it once.
    std::set<std::vector<double>> distinct;
    for (const auto& row : a) distinct.insert(row.x);
    EXPECT_EQ(distinct.size(), a.size()) << name;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].x, b[k].x);
      EXPECT_EQ(a[k].phase, b[k].phase);
    }
    // Three runs side by side, one request each per round; a front's two
    // anchors also run side by side within each: batches of 3 and 3 x 2.
    EXPECT_EQ(*std::max_element(backwards->sizes.begin(), backwards->sizes.end()),
              kind == StudyKind::kOptimize ? 3u : 6u)
        << name;
  }
}

TEST(DesignExecutor, ThreadExecutorDescribesItselfAndKeepsOrder) {
  const StudySpec s = population_study();
  StudyProblem p(s);
  const auto one = make_thread_executor(1);
  const auto two = make_thread_executor(2);
  EXPECT_EQ(one->describe(), "1 thread");
  EXPECT_EQ(two->describe(), "2 threads");
  std::vector<std::vector<double>> xs;
  for (int k = 0; k < 7; ++k) xs.push_back({1.0 + 0.25 * k, (12 + k) * kDeg});
  const auto a = one->evaluate(p, xs, 1);
  const auto b = two->evaluate(p, xs, 1);
  ASSERT_EQ(a.size(), 7u);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    EXPECT_EQ(a[k].x, xs[k]);
    EXPECT_EQ(a[k].metric_values, b[k].metric_values);
  }
}

}  // namespace
}  // namespace rackopt::study
