// Whole-valued variables (Problem::num_integer): the algorithms that search
// them keep them whole and find optima worked out by hand; the others are
// refused with the names of those that can.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "rackopt/solvers/pareto.hpp"
#include "rackopt/solvers/solver.hpp"
#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

// min (x - 0.3)^2 + (k - 3.6)^2  s.t.  x + k >= 4.8,  x in [-2, 2], k in {0..6}.
// Per k the best x is max(0.3, 4.8 - k): k = 4 gives x = 0.8, f = 0.25 + 0.16
// = 0.41; k = 5 gives x = 0.3, f = 1.96; k = 3 gives x = 1.8, f = 2.25 + 0.36
// = 2.61; the others are worse. Optimum: x = 0.8, k = 4, f = 0.41.
LambdaProblem integer_bowl() {
  LambdaProblem p({-2, 0}, {2, 6},
                  [](std::span<const double> x) {
                    return ok((x[0] - 0.3) * (x[0] - 0.3) + (x[1] - 3.6) * (x[1] - 3.6), {4.8 - x[0] - x[1]});
                  },
                  1);
  p.with_integers(1);
  return p;
}

bool whole(double v) { return v == std::floor(v); }

TEST(IntegerVariables, GacoFindsTheMixedIntegerOptimumAndOnlyEvaluatesWholeValues) {
  rs::SolverSettings s;
  s.library = "pagmo";
  s.algorithm = "gaco";
  s.max_evaluations = 3000;
  s.seed = 5;
  std::size_t fractional = 0, seen = 0;
  rs::SolverCallbacks cb;
  cb.observer = [&](const rs::EvaluationRecord& r) {
    ++seen;
    if (!whole(r.x[1])) ++fractional;
  };
  const rs::SolverResult r = rs::minimize(integer_bowl(), std::vector<double>{0, 1.4}, s, cb);
  EXPECT_EQ(fractional, 0u) << "of " << seen;
  EXPECT_GT(seen, 100u);
  ASSERT_TRUE(r.feasible);
  EXPECT_EQ(r.x[1], 4.0);
  EXPECT_NEAR(r.x[0], 0.8, 0.02);
  EXPECT_NEAR(r.evaluation.objectives[0], 0.41, 0.01);
}

// f1 = x^2 + 0.5 k, f2 = (x - 1)^2 + 0.5 (2 - k), x in [-1, 2], k in {0, 1, 2}.
// Brute force over a fine x grid and every k gives the true front; no point
// NSGA-II reports may be dominated by a brute-force point by more than the
// grid's resolution.
TEST(IntegerVariables, Nsga2FrontOverAWholeValuedVariable) {
  auto objectives = [](double x, double k) {
    return std::pair<double, double>{x * x + 0.5 * k, (x - 1) * (x - 1) + 0.5 * (2 - k)};
  };
  LambdaProblem p({-1, 0}, {2, 2},
                  [&](std::span<const double> x) {
                    const auto [f1, f2] = objectives(x[0], x[1]);
                    rs::Evaluation e;
                    e.objectives = {f1, f2};
                    return e;
                  },
                  0, 0, 2);
  p.with_integers(1);
  rs::ParetoSettings s;
  s.method = rs::Scalarization::kPopulation;
  s.points = 12;
  s.solver.library = "pagmo";
  s.solver.algorithm = "nsga2";
  s.solver.max_evaluations = 2400;
  s.solver.seed = 11;
  std::size_t fractional = 0;
  rs::ParetoCallbacks cb;
  cb.observer = [&](const std::string&, const rs::EvaluationRecord& r) {
    if (!whole(r.x[1])) ++fractional;
  };
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 1}, s, cb);
  EXPECT_EQ(fractional, 0u);
  ASSERT_EQ(r.front.size(), 12u);
  std::vector<std::pair<double, double>> brute;
  for (int k = 0; k <= 2; ++k)
    for (int i = 0; i <= 3000; ++i) brute.push_back(objectives(-1 + 3.0 * i / 3000, k));
  std::set<double> ks;
  for (const rs::ParetoPoint& fp : r.front) {
    ASSERT_TRUE(whole(fp.x[1]));
    ks.insert(fp.x[1]);
    for (const auto& [b1, b2] : brute)
      EXPECT_FALSE(b1 < fp.evaluation.objectives[0] - 2e-3 && b2 < fp.evaluation.objectives[1] - 2e-3)
          << "front point (" << fp.x[0] << ", " << fp.x[1] << ") dominated by (" << b1 << ", " << b2 << ")";
  }
  // The true front passes through all three k (each k owns a stretch of it).
  EXPECT_EQ(ks.size(), 3u);
}

TEST(IntegerVariables, AlgorithmsForContinuousVariablesAreRefusedWithTheOnesThatCan) {
  for (const auto& [library, algorithm] : std::vector<std::pair<std::string, std::string>>{
           {"nlopt", "LN_COBYLA"}, {"ipopt", ""}, {"pagmo", "cmaes"}, {"pagmo", "sade"}}) {
    rs::SolverSettings s;
    s.library = library;
    if (!algorithm.empty()) s.algorithm = algorithm;
    s.max_evaluations = 500;
    try {
      rs::minimize(integer_bowl(), std::vector<double>{0, 1}, s);
      ADD_FAILURE() << library << " " << algorithm << " accepted an integer variable";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("whole-valued"), std::string::npos) << what;
      EXPECT_NE(what.find("pagmo gaco"), std::string::npos) << what;
      EXPECT_NE(what.find("pagmo nsga2"), std::string::npos) << what;
    }
  }
  const rs::ProblemShape shape{2, 2, 0, 0, 1};
  rs::SolverSettings moead;
  moead.library = "pagmo";
  moead.algorithm = "moead";
  moead.max_evaluations = 500;
  EXPECT_TRUE(rs::check_solver_settings(moead, shape).has_value());
}

}  // namespace
