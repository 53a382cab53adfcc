// pagmo's population methods against fronts and optima known in closed form
// (derived in the comments of test_problems.hpp and below, never from a run).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rackopt/solvers/front_quality.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "rackopt/solvers/solver.hpp"
#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

rs::Evaluation pagmo_two_objectives(double f1, double f2, std::vector<double> g = {}) {
  rs::Evaluation e;
  e.objectives = {f1, f2};
  e.inequality = std::move(g);
  return e;
}

// f1 = x^2 + y^2, f2 = (x-2)^2 + y^2 on [-1,3]^2: the Pareto set is y = 0,
// x in [0, 2], the front f2 = (2 - sqrt(f1))^2 for f1 in [0, 4]. With the
// constraint x >= min_x the front starts at f1 = min_x^2.
LambdaProblem pagmo_two_circles(std::optional<double> min_x = std::nullopt) {
  return LambdaProblem(
      {-1, -1}, {3, 3},
      [=](std::span<const double> x) {
        std::vector<double> g;
        if (min_x) g.push_back(*min_x - x[0]);
        return pagmo_two_objectives(x[0] * x[0] + x[1] * x[1], (x[0] - 2) * (x[0] - 2) + x[1] * x[1], g);
      },
      min_x ? 1 : 0, 0, 2);
}

double pagmo_front_f2(double f1) { return std::pow(2 - std::sqrt(std::max(0.0, f1)), 2); }

rs::ParetoSettings pagmo_population_front(const std::string& algorithm, std::size_t points, std::size_t budget) {
  rs::ParetoSettings s;
  s.method = rs::Scalarization::kPopulation;
  s.points = points;
  s.solver.library = "pagmo";
  s.solver.algorithm = algorithm;
  s.solver.max_evaluations = budget;
  s.solver.seed = 7;
  return s;
}

// The hypervolume of the exact front against `ref`, by the midpoint rule on
// f1 (independent of pagmo): the integral of ref2 - f2(f1) over [lo, ref1].
double pagmo_exact_front_hypervolume(double lo, double ref1, double ref2) {
  const int n = 200000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double f1 = lo + (ref1 - lo) * (i + 0.5) / n;
    sum += std::max(0.0, ref2 - pagmo_front_f2(std::min(f1, 4.0)));
  }
  return sum * (ref1 - lo) / n;
}

class PopulationFront : public ::testing::TestWithParam<const char*> {};

TEST_P(PopulationFront, FindsTheRequestedNumberOfPointsOnTheExactFront) {
  const LambdaProblem p = pagmo_two_circles();
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, pagmo_population_front(GetParam(), 15, 4000));
  EXPECT_EQ(r.status, rs::ParetoStatus::kOk);
  ASSERT_EQ(r.front.size(), 15u);
  EXPECT_LE(r.evaluations, 4000u);
  EXPECT_GT(r.generations, 50u);
  for (const auto& fp : r.front) {
    const double f1 = fp.evaluation.objectives[0], f2 = fp.evaluation.objectives[1];
    EXPECT_NEAR(f2, pagmo_front_f2(f1), 0.02) << fp.label;
    EXPECT_LE(std::abs(fp.x[1]), 0.1) << fp.label;  // 2 y^2 within the 0.02 above
  }
  for (std::size_t i = 0; i < r.front.size(); ++i)
    for (std::size_t j = 0; j < r.front.size(); ++j)
      if (i != j) {
        EXPECT_FALSE(rs::dominates(r.front[i].evaluation.objectives, r.front[j].evaluation.objectives));
      }
  // The front spans both ends and covers nearly all of the exact front's
  // hypervolume: 15 points of a staircase under the curve with ref (4.4, 4.4).
  EXPECT_LT(r.front.front().evaluation.objectives[0], 0.05);
  EXPECT_GT(r.front.back().evaluation.objectives[0], 3.9);
  rs::ObjectiveVectors v;
  for (const auto& fp : r.front) v.push_back(fp.evaluation.objectives);
  const double exact = pagmo_exact_front_hypervolume(0.0, 4.4, 4.4);
  const double found = rs::hypervolume(v, std::vector<double>{4.4, 4.4});
  EXPECT_LT(found, exact);
  EXPECT_GT(found, 0.95 * exact);
}

TEST_P(PopulationFront, KeepsInfeasiblePointsOffTheFront) {
  // x >= 1: the front is f1 in [1, 4] (x in [1, 2]).
  const LambdaProblem p = pagmo_two_circles(1.0);
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.0, 0.5}, pagmo_population_front(GetParam(), 10, 3000));
  ASSERT_FALSE(r.front.empty());
  for (const auto& fp : r.front) {
    EXPECT_TRUE(fp.feasible);
    EXPECT_GE(fp.x[0], 1.0 - 1e-6) << fp.label;
    EXPECT_NEAR(fp.evaluation.objectives[1], pagmo_front_f2(fp.evaluation.objectives[0]), 0.02) << fp.label;
  }
  EXPECT_LT(r.front.front().evaluation.objectives[0], 1.1);
}

TEST_P(PopulationFront, IsDeterministicForASeedAndChangesWithIt) {
  const LambdaProblem p = pagmo_two_circles();
  auto s = pagmo_population_front(GetParam(), 8, 800);
  const rs::ParetoResult a = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
  const rs::ParetoResult b = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
  ASSERT_EQ(a.front.size(), b.front.size());
  for (std::size_t i = 0; i < a.front.size(); ++i) EXPECT_EQ(a.front[i].x, b.front[i].x);
  s.solver.seed = 8;
  const rs::ParetoResult c = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
  bool differs = c.front.size() != a.front.size();
  for (std::size_t i = 0; !differs && i < a.front.size(); ++i) differs = a.front[i].x != c.front[i].x;
  EXPECT_TRUE(differs);
}

TEST_P(PopulationFront, ObserverSeesEveryEvaluationWithItsGeneration) {
  const LambdaProblem p = pagmo_two_circles();
  std::size_t seen = 0;
  std::string first_label, last_label;
  rs::ParetoCallbacks cb;
  cb.observer = [&](const std::string& label, const rs::EvaluationRecord& rec) {
    EXPECT_EQ(rec.index, seen);
    if (seen == 0) first_label = label;
    last_label = label;
    ++seen;
  };
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, pagmo_population_front(GetParam(), 8, 480), cb);
  EXPECT_EQ(seen, r.evaluations);
  EXPECT_EQ(first_label, std::string(GetParam()) + " generation 0");
  EXPECT_EQ(last_label, std::string(GetParam()) + " generation " + std::to_string(r.generations));
}

TEST_P(PopulationFront, AStopRequestEndsTheRunWithTheFrontSoFar) {
  const LambdaProblem p = pagmo_two_circles();
  std::size_t seen = 0;
  rs::ParetoCallbacks cb;
  cb.observer = [&](const std::string&, const rs::EvaluationRecord&) { ++seen; };
  cb.stop = [&] { return seen >= 100; };
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, pagmo_population_front(GetParam(), 8, 4000), cb);
  EXPECT_EQ(r.status, rs::ParetoStatus::kStopped);
  // The stop is polled before every batch (NSGA-II: a generation; MOEA/D: a
  // design): the batch under way is finished, no further one starts.
  EXPECT_GE(r.evaluations, 100u);
  EXPECT_LE(r.evaluations, 100u + 24u);
  EXPECT_FALSE(r.front.empty());
}

INSTANTIATE_TEST_SUITE_P(Pagmo, PopulationFront, ::testing::Values("nsga2", "moead"));

TEST(PagmoFront, FourObjectivesAndFailedEvaluationsNeverOnTheFront) {
  // f_k = |x - c_k|^2 for four corners c_k of the unit square, on [0,1]^2:
  // every point of the square is Pareto-optimal (the convex hull of the c_k).
  // Designs with x0 + x1 > 1.5 fail: none may reach the front.
  const std::vector<std::array<double, 2>> c{{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  const LambdaProblem p(
      {0, 0}, {1, 1},
      [&](std::span<const double> x) {
        if (x[0] + x[1] > 1.5) return failed("corner region fails");
        rs::Evaluation e;
        for (const auto& ck : c) e.objectives.push_back(std::pow(x[0] - ck[0], 2) + std::pow(x[1] - ck[1], 2));
        return e;
      },
      0, 0, 4);
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.2, 0.2}, pagmo_population_front("nsga2", 20, 2400));
  EXPECT_EQ(r.front.size(), 20u);
  for (const auto& fp : r.front) EXPECT_LE(fp.x[0] + fp.x[1], 1.5);
  EXPECT_GT(r.failed_evaluations, 0u);
}

TEST(PagmoFront, RefusesWhatItCannotRun) {
  const LambdaProblem p = pagmo_two_circles();
  auto s = pagmo_population_front("nsga2", 10, 4000);
  s.solver.options["population"] = 10;  // not a multiple of 4
  try {
    rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
    FAIL() << "population 10 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("multiple of 4"), std::string::npos) << e.what();
  }
  s = pagmo_population_front("nsga2", 10, 30);  // no room for a second generation of 24
  EXPECT_THROW(rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s), std::invalid_argument);
  s = pagmo_population_front("cmaes", 10, 4000);  // one objective only
  EXPECT_THROW(rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s), std::invalid_argument);
  s = pagmo_population_front("nsga2", 10, 4000);
  s.method = rs::Scalarization::kEpsilonConstraint;  // a front algorithm cannot solve sub-problems
  EXPECT_THROW(rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s), std::invalid_argument);
}

rs::SolverSettings pagmo_minimize_settings(const std::string& algorithm, std::size_t budget) {
  rs::SolverSettings s;
  s.library = "pagmo";
  s.algorithm = algorithm;
  s.max_evaluations = budget;
  s.seed = 3;
  return s;
}

class PopulationMinimize : public ::testing::TestWithParam<const char*> {};

TEST_P(PopulationMinimize, FindsTheConstrainedQuadraticOptimum) {
  // min x^2 + y^2 s.t. x + y >= 1 -> (0.5, 0.5), f = 0.5 (test_problems.hpp).
  const LambdaProblem p = disk_above_line();
  const rs::SolverResult r = rs::minimize(p, std::vector<double>{2, 2}, pagmo_minimize_settings(GetParam(), 6000));
  EXPECT_TRUE(r.feasible);
  EXPECT_NEAR(r.evaluation.objectives[0], 0.5, 5e-3);
  EXPECT_NEAR(r.x[0], 0.5, 0.05);
  EXPECT_LE(r.evaluations, 6000u);
  EXPECT_TRUE(r.status == rs::SolverStatus::kConverged || r.status == rs::SolverStatus::kMaxEvaluations)
      << r.status;
}

TEST_P(PopulationMinimize, RefusesMultistartAndFrontAlgorithmsInMinimize) {
  auto s = pagmo_minimize_settings(GetParam(), 1000);
  s.starts = 3;
  EXPECT_THROW(rs::minimize(rosenbrock(), std::vector<double>{0, 0}, s), std::invalid_argument);
  s = pagmo_minimize_settings("nsga2", 1000);
  EXPECT_THROW(rs::minimize(rosenbrock(), std::vector<double>{0, 0}, s), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Pagmo, PopulationMinimize, ::testing::Values("cmaes", "sade", "gaco"));

TEST(PagmoMinimize, CmaesSolvesRosenbrock) {
  // Minimum 0 at (1, 1).
  const rs::SolverResult r = rs::minimize(rosenbrock(), std::vector<double>{-1.5, 1.5}, pagmo_minimize_settings("cmaes", 8000));
  EXPECT_LT(r.evaluation.objectives[0], 1e-4);
  EXPECT_NEAR(r.x[0], 1.0, 1e-2);
}

}  // namespace
