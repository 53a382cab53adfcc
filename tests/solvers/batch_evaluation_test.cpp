// Independent points reach Problem::evaluate_batch together, and the result
// does not depend on how the batch is computed.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/solvers/pareto.hpp"
#include "rackopt/solvers/solver.hpp"
#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

// Rosenbrock (f = 0 at (1, 1)) that logs the size of every batch and can
// answer a batch in reverse order of computation (as a pool of workers
// might), which must not change any result.
class BatchLogged : public rs::Problem {
 public:
  explicit BatchLogged(bool reverse) : reverse_(reverse) {}
  std::size_t dimension() const override { return 2; }
  std::vector<double> lower_bounds() const override { return {-2, -2}; }
  std::vector<double> upper_bounds() const override { return {2, 2}; }
  rs::Evaluation evaluate(std::span<const double> x) const override {
    return ok((1 - x[0]) * (1 - x[0]) + 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]));
  }
  std::vector<rs::Evaluation> evaluate_batch(const std::vector<std::vector<double>>& xs) const override {
    sizes.push_back(xs.size());
    std::vector<rs::Evaluation> out(xs.size());
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const std::size_t i = reverse_ ? xs.size() - 1 - k : k;
      out[i] = evaluate(xs[i]);
    }
    return out;
  }
  mutable std::vector<std::size_t> sizes;

 private:
  bool reverse_;
};

// Two objectives, f1 = x^2 + y^2 and f2 = (x-2)^2 + y^2, batches logged.
class BatchLoggedTwoCircles : public BatchLogged {
 public:
  BatchLoggedTwoCircles() : BatchLogged(false) {}
  std::size_t num_objectives() const override { return 2; }
  rs::Evaluation evaluate(std::span<const double> x) const override {
    rs::Evaluation e;
    e.objectives = {x[0] * x[0] + x[1] * x[1], (x[0] - 2) * (x[0] - 2) + x[1] * x[1]};
    return e;
  }
};

TEST(BatchEvaluation, FiniteDifferenceProbesGoTogether) {
  for (bool central : {false, true}) {
    BatchLogged p(false);
    rs::SolverSettings s = nlopt_settings("LD_SLSQP", 200);
    s.central_differences = central;
    const rs::SolverResult r = rs::minimize(p, std::vector<double>{-1.2, 1.0}, s);
    EXPECT_LT(r.evaluation.objectives[0], 0.05);  // near (1, 1); convergence_test.cpp measures how near
    // Every probe batch holds both variables' probes (forward 2, central 4),
    // except where a bound leaves one side only.
    std::size_t probe_batches = 0;
    for (std::size_t n : p.sizes) probe_batches += n == (central ? 4u : 2u) ? 1 : 0;
    EXPECT_GT(probe_batches, 5u) << (central ? "central" : "forward");
  }
}

TEST(BatchEvaluation, ResultsAndRecordOrderDoNotDependOnHowABatchIsComputed) {
  std::vector<std::vector<double>> xs_forward, xs_reverse;
  auto run = [](bool reverse, std::vector<std::vector<double>>& xs) {
    BatchLogged p(reverse);
    rs::SolverSettings s = nlopt_settings("LD_SLSQP", 200);
    rs::SolverCallbacks cb;
    cb.observer = [&](const rs::EvaluationRecord& rec) { xs.push_back(rec.x); };
    return rs::minimize(p, std::vector<double>{-1.2, 1.0}, s, cb);
  };
  const rs::SolverResult a = run(false, xs_forward);
  const rs::SolverResult b = run(true, xs_reverse);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.evaluation.objectives, b.evaluation.objectives);
  EXPECT_EQ(xs_forward, xs_reverse);
}

TEST(BatchEvaluation, Nsga2EvaluatesEachGenerationAsOneBatch) {
  BatchLoggedTwoCircles p;
  rs::ParetoSettings s;
  s.method = rs::Scalarization::kPopulation;
  s.points = 8;
  s.solver.library = "pagmo";
  s.solver.algorithm = "nsga2";
  s.solver.max_evaluations = 24 * 5;
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
  EXPECT_EQ(r.generations, 4u);
  // The first population, then one batch per generation (a generation may
  // hold fewer new designs when offspring repeat a point already evaluated).
  ASSERT_EQ(p.sizes.size(), 5u);
  EXPECT_EQ(p.sizes[0], 24u);
  for (std::size_t k = 1; k < p.sizes.size(); ++k) EXPECT_LE(p.sizes[k], 24u);
}

// The scalarized front's sub-problems hand their finite-difference probes
// to the original problem as batches, and its anchors (one run per
// objective) share rounds: batches of both anchors' probes.
TEST(BatchEvaluation, ScalarizedFrontsBatchProbesAndAnchors) {
  BatchLoggedTwoCircles p;
  rs::ParetoSettings s;
  s.method = rs::Scalarization::kWeightedSum;
  s.points = 5;
  s.solver = nlopt_settings("LD_SLSQP", 100);
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
  EXPECT_EQ(r.front.size(), 5u);
  std::size_t one_run_probes = 0, two_runs_probes = 0;
  for (std::size_t n : p.sizes) {
    one_run_probes += n == 2 ? 1 : 0;  // a sub-problem's two forward probes
    two_runs_probes += n == 4 ? 1 : 0;  // both anchors' probes in one round
  }
  EXPECT_GT(one_run_probes, 3u);
  EXPECT_GT(two_runs_probes, 0u);
}

TEST(BatchEvaluation, TheBudgetCutsABatchAndKeepsWhatWasEvaluated) {
  BatchLogged p(false);
  rs::SolverSettings s = nlopt_settings("LD_SLSQP", 8);
  s.central_differences = true;  // batches of 4 probes after the start point
  std::size_t seen = 0;
  rs::SolverCallbacks cb;
  cb.observer = [&](const rs::EvaluationRecord&) { ++seen; };
  const rs::SolverResult r = rs::minimize(p, std::vector<double>{-1.2, 1.0}, s, cb);
  EXPECT_EQ(r.evaluations, 8u);
  EXPECT_EQ(seen, 8u);
  EXPECT_EQ(to_string(r.status), "max_evaluations");
}

}  // namespace
