// Pareto fronts by scalarization against fronts known in closed form. Every
// expected front is derived in the comment of its test, never from a run.
#include "rackopt/solvers/pareto.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

rs::Evaluation ok_multi(std::vector<double> f, std::vector<double> ineq = {}) {
  rs::Evaluation e;
  e.objectives = std::move(f);
  e.inequality = std::move(ineq);
  return e;
}

// f1 = x^2 + y^2, f2 = (x-2)^2 + y^2 on [-1,3]^2. Both grow with |y|, so the
// Pareto set is y = 0 between the two minimizers: x in [0, 2]. There
// f1 = x^2, f2 = (2-x)^2, i.e. the front f2 = (2 - sqrt(f1))^2, f1 in [0, 4].
// With `min_x` > 0 the inequality g = min_x - x <= 0 cuts the set to
// x in [min_x, 2], f1 in [min_x^2, 4].
LambdaProblem two_circles(double min_x = -1e9) {
  const bool constrained = min_x > -1e8;
  return LambdaProblem(
      {-1, -1}, {3, 3},
      [=](std::span<const double> x) {
        std::vector<double> g;
        if (constrained) g.push_back(min_x - x[0]);
        return ok_multi({x[0] * x[0] + x[1] * x[1], (x[0] - 2) * (x[0] - 2) + x[1] * x[1]}, g);
      },
      constrained ? 1 : 0, 0, 2);
}

double analytic_f2(double f1) { return (2 - std::sqrt(std::max(0.0, f1))) * (2 - std::sqrt(std::max(0.0, f1))); }

void expect_mutually_non_dominated(const rs::ParetoResult& r) {
  for (std::size_t i = 0; i < r.front.size(); ++i)
    for (std::size_t j = 0; j < r.front.size(); ++j)
      if (i != j) {
        EXPECT_FALSE(rs::dominates(r.front[i].evaluation.objectives, r.front[j].evaluation.objectives))
            << r.front[i].label << " dominates " << r.front[j].label;
      }
}

rs::ParetoSettings settings(rs::Scalarization method, const std::string& algorithm, std::size_t points) {
  rs::ParetoSettings s;
  s.method = method;
  s.points = points;
  s.solver = nlopt_settings(algorithm, 2000);
  s.solver.central_differences = true;  // front accuracy 1e-3 needs unbiased gradients (docs/solvers.md)
  return s;
}

}  // namespace

TEST(Pareto, DominatesAndNonDominatedByHand) {
  using V = std::vector<double>;
  EXPECT_TRUE(rs::dominates(V{1, 2}, V{1, 3}));   // equal in one, better in the other
  EXPECT_TRUE(rs::dominates(V{0, 0, 0}, V{1, 1, 1}));
  EXPECT_FALSE(rs::dominates(V{1, 2}, V{1, 2}));  // equal: no
  EXPECT_FALSE(rs::dominates(V{1, 3}, V{2, 2}));  // trade-off: no, either way
  EXPECT_FALSE(rs::dominates(V{2, 2}, V{1, 3}));
  EXPECT_THROW(rs::dominates(V{1, 2}, V{1, 2, 3}), std::invalid_argument);
  // (3,3) is dominated by (2,2); (2,4) by (2,2); the two copies of (1,5) stay.
  const std::vector<V> pts{{2, 2}, {3, 3}, {1, 5}, {2, 4}, {4, 1}, {1, 5}};
  EXPECT_EQ(rs::non_dominated(pts), (std::vector<std::size_t>{0, 2, 4, 5}));
  EXPECT_TRUE(rs::non_dominated({}).empty());
}

TEST(Pareto, ConvexBiObjectiveBothMethods) {
  const auto p = two_circles();
  const std::size_t points = 20;
  const double spacing = 4.0 / static_cast<double>(points - 1);  // even spacing of f1 over [0, 4]
  for (rs::Scalarization method : {rs::Scalarization::kEpsilonConstraint, rs::Scalarization::kWeightedSum})
    for (const char* algorithm : {"LN_COBYLA", "LD_SLSQP"}) {
      SCOPED_TRACE(std::string(algorithm) + (method == rs::Scalarization::kWeightedSum ? " weighted" : " eps"));
      rs::ParetoSettings s = settings(method, algorithm, points);
      // eps grid on f1 (primary = f2): then the f1 levels are evenly spaced.
      // (Bounding f2 instead spaces f1 unevenly: the front is flat in f2 near f1 = 4.)
      s.primary = 1;
      const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{1.0, 0.5}, s);
      EXPECT_EQ(to_string(r.status), "ok");
      EXPECT_EQ(r.subproblems, points);
      ASSERT_EQ(r.ideal.size(), 2u);
      EXPECT_NEAR(r.ideal[0], 0.0, 1e-4);  // anchors: min f1 = 0 at (0,0), min f2 = 0 at (2,0)
      EXPECT_NEAR(r.ideal[1], 0.0, 1e-4);
      EXPECT_NEAR(r.nadir[0], 4.0, 2e-3);  // f1 at (2,0), f2 at (0,0)
      EXPECT_NEAR(r.nadir[1], 4.0, 2e-3);
      ASSERT_GE(r.front.size(), points - 4);
      std::vector<double> f1s;
      for (const rs::ParetoPoint& q : r.front) {
        EXPECT_TRUE(q.feasible);
        const double f1 = q.evaluation.objectives[0], f2 = q.evaluation.objectives[1];
        EXPECT_NEAR(f2, analytic_f2(f1), 1e-3) << q.label << " f1=" << f1;
        f1s.push_back(f1);
      }
      expect_mutually_non_dominated(r);
      // Sorted by the primary objective f2 => f1 descending.
      for (std::size_t i = 1; i < r.front.size(); ++i)
        EXPECT_LE(r.front[i - 1].evaluation.objectives[1], r.front[i].evaluation.objectives[1]);
      std::sort(f1s.begin(), f1s.end());
      EXPECT_GE(f1s.back() - f1s.front(), 0.9 * 4.0);
      for (std::size_t i = 1; i < f1s.size(); ++i) EXPECT_LE(f1s[i] - f1s[i - 1], 2.5 * spacing) << "gap at " << f1s[i];
    }
}

TEST(Pareto, ConstrainedFrontStartsAtTheConstraint) {
  // x >= 0.5 cuts the Pareto set to x in [0.5, 2]: the f1-anchor is (0.5, 0), f1 = 0.25.
  const auto p = two_circles(0.5);
  for (rs::Scalarization method : {rs::Scalarization::kEpsilonConstraint, rs::Scalarization::kWeightedSum}) {
    rs::ParetoSettings s = settings(method, "LD_SLSQP", 12);
    const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{1.0, 0.5}, s);
    EXPECT_EQ(to_string(r.status), "ok");
    ASSERT_FALSE(r.front.empty());
    EXPECT_NEAR(r.ideal[0], 0.25, 1e-4);
    double min_f1 = 1e9;
    for (const rs::ParetoPoint& q : r.front) {
      EXPECT_GE(q.x[0], 0.5 - 1e-6);
      EXPECT_NEAR(q.evaluation.objectives[1], analytic_f2(q.evaluation.objectives[0]), 1e-3);
      min_f1 = std::min(min_f1, q.evaluation.objectives[0]);
    }
    EXPECT_NEAR(min_f1, 0.25, 1e-4);
    EXPECT_EQ(r.front.front().evaluation.objectives[0], min_f1);  // sorted by f1 (primary 0)
  }
}

TEST(Pareto, ConcaveFrontOnlyEpsConstraintFindsTheInterior) {
  // f1 = x, f2 = 1 - x^2 on [0,1]: every x is Pareto optimal (f1 up, f2 down),
  // front f2 = 1 - f1^2, concave. A weighted sum w1 x + w2 (1 - x^2) is concave
  // in x, so its minimum is always at x = 0 or x = 1: only the two ends.
  // eps-constraint: min x s.t. 1 - x^2 <= eps gives x = sqrt(1 - eps), interior.
  const LambdaProblem p({0}, {1}, [](std::span<const double> x) { return ok_multi({x[0], 1 - x[0] * x[0]}); }, 0, 0,
                        2);
  const std::size_t points = 11;
  {
    const rs::ParetoResult r =
        rs::pareto_front(p, std::vector<double>{0.3}, settings(rs::Scalarization::kEpsilonConstraint, "LN_COBYLA", points));
    EXPECT_EQ(to_string(r.status), "ok");
    std::size_t interior = 0;
    for (const rs::ParetoPoint& q : r.front) {
      EXPECT_NEAR(q.evaluation.objectives[1], 1 - q.evaluation.objectives[0] * q.evaluation.objectives[0], 1e-6);
      if (q.x[0] > 0.01 && q.x[0] < 0.99) ++interior;
    }
    EXPECT_GE(interior, points - 3);
    expect_mutually_non_dominated(r);
  }
  {
    const rs::ParetoResult r =
        rs::pareto_front(p, std::vector<double>{0.3}, settings(rs::Scalarization::kWeightedSum, "LN_COBYLA", points));
    EXPECT_EQ(to_string(r.status), "ok");
    ASSERT_EQ(r.front.size(), 2u);  // the ends only; everything else is a duplicate of one of them
    EXPECT_NEAR(r.front[0].x[0], 0.0, 1e-6);
    EXPECT_NEAR(r.front[1].x[0], 1.0, 1e-6);
    EXPECT_EQ(r.dominated.size(), points - 2);
  }
}

TEST(Pareto, ThreeObjectivesTriangle) {
  // f_i = |x - a_i|^2 with a_i the corners of an equilateral triangle of side 1.
  // A sum of strictly convex functions: the Pareto set is the convex hull of
  // the a_i (the triangle), the anchors are the corners with f_i = 0 and
  // f_j = 1 for j != i, so ideal = (0,0,0) and nadir = (1,1,1).
  const double h = std::sqrt(3.0) / 2;
  const double a[3][2] = {{0, 0}, {1, 0}, {0.5, h}};
  const LambdaProblem p(
      {-1, -1}, {2, 2},
      [&](std::span<const double> x) {
        std::vector<double> f;
        for (const auto& c : a) f.push_back((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]));
        return ok_multi(f);
      },
      0, 0, 3);
  // Weighted sum here; the eps-constraint run, whose low grid cells are
  // infeasible and made LN_COBYLA cycle forever before the adapter's request
  // cap, is Termination.ThreeObjectiveEpsConstraintFrontEnds (under a watchdog).
  for (rs::Scalarization method : {rs::Scalarization::kWeightedSum}) {
    rs::ParetoSettings s = settings(method, "LN_COBYLA", 19);
    const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.4, 0.3}, s);
    EXPECT_EQ(to_string(r.status), "ok");
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_NEAR(r.ideal[i], 0.0, 1e-5);
      EXPECT_NEAR(r.nadir[i], 1.0, 1e-3);
    }
    ASSERT_GE(r.front.size(), 8u);
    for (std::size_t i = 0; i < 3; ++i) {  // each corner is on the front
      double best = 1e9;
      for (const rs::ParetoPoint& q : r.front) best = std::min(best, q.evaluation.objectives[i]);
      EXPECT_NEAR(best, 0.0, 1e-5) << "anchor " << i;
    }
    for (const rs::ParetoPoint& q : r.front) {
      EXPECT_TRUE(q.feasible);
      // Inside the triangle: y >= 0, and on the inner side of both slanted edges.
      const double x = q.x[0], y = q.x[1];
      EXPECT_GE(y, -2e-3) << q.label;
      EXPECT_LE(y, 2 * h * x + 2e-3) << q.label;
      EXPECT_LE(y, 2 * h * (1 - x) + 2e-3) << q.label;
    }
    expect_mutually_non_dominated(r);
  }
}

TEST(Pareto, FailedRegionDoesNotStopTheFront) {
  // The convex two-circle problem whose model fails for 0.9 < x < 1.1. The
  // eps level f1 <= 1 (points 9 -> levels 0.5, 1, 1.5, ...) has its optimum
  // x = 1 inside the hole, so solvers hit it; the rest of the front survives.
  const LambdaProblem p(
      {-1, -1}, {3, 3},
      [](std::span<const double> x) {
        if (x[0] > 0.9 && x[0] < 1.1) return failed("hole at x = " + std::to_string(x[0]));
        return ok_multi({x[0] * x[0] + x[1] * x[1], (x[0] - 2) * (x[0] - 2) + x[1] * x[1]});
      },
      0, 0, 2);
  rs::ParetoSettings s = settings(rs::Scalarization::kEpsilonConstraint, "LN_COBYLA", 9);
  s.primary = 1;
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.2, 0.5}, s);
  EXPECT_EQ(to_string(r.status), "ok");
  // 9 on the grid; the level inside the hole gives a design the others
  // already have, so one filling sub-problem follows and finds a new point.
  EXPECT_GE(r.subproblems, 10u);
  EXPECT_EQ(r.front.size(), 9u);
  EXPECT_TRUE(std::any_of(r.front.begin(), r.front.end(),
                          [](const rs::ParetoPoint& q) { return q.label.find("eps fill") != std::string::npos; }));
  EXPECT_GT(r.failed_evaluations, 0u);
  bool left = false, right = false;
  for (const rs::ParetoPoint& q : r.front) {
    EXPECT_TRUE(q.evaluation.ok());
    EXPECT_NEAR(q.evaluation.objectives[1], analytic_f2(q.evaluation.objectives[0]), 1e-3);
    left = left || q.x[0] < 0.8;
    right = right || q.x[0] > 1.2;
  }
  EXPECT_TRUE(left);
  EXPECT_TRUE(right);
}

TEST(Pareto, GapFillingEndsWhenNoPairCanGiveANewPoint) {
  // With duplicate_tolerance 0.15 no front of the two circles can hold more
  // than about 1/0.15 + 1 distinct points, so 12 cannot be delivered: the
  // filling sub-problems run (each pair once, at most twice the missing
  // count) and end; what is delivered stays distinct and non-dominated.
  const auto p = two_circles();
  rs::ParetoSettings s = settings(rs::Scalarization::kEpsilonConstraint, "LN_COBYLA", 12);
  s.duplicate_tolerance = 0.15;
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s);
  ASSERT_LT(r.front.size(), 12u);
  ASSERT_GE(r.front.size(), 5u);
  std::size_t fills = 0;
  for (const auto* list : {&r.front, &r.dominated, &r.infeasible})
    for (const rs::ParetoPoint& q : *list) fills += q.label.find("eps fill") != std::string::npos ? 1 : 0;
  EXPECT_GT(fills, 0u);
  EXPECT_EQ(r.subproblems, 12u + fills);
  EXPECT_LE(fills, 2 * 12u);
  for (std::size_t i = 0; i < r.front.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      bool same = true;
      for (std::size_t k = 0; k < 2; ++k)
        same = same && std::abs(r.front[i].evaluation.objectives[k] - r.front[j].evaluation.objectives[k]) <=
                           0.15 * (r.nadir[k] - r.ideal[k]);
      EXPECT_FALSE(same) << r.front[i].label << " duplicates " << r.front[j].label;
    }
  expect_mutually_non_dominated(r);
}

TEST(Pareto, DeterministicAndObserved) {
  const auto p = two_circles();
  rs::ParetoSettings s = settings(rs::Scalarization::kEpsilonConstraint, "LN_COBYLA", 8);
  std::vector<std::string> labels;
  bool anchor_after_eps = false;
  std::size_t next_index = 0;
  bool indices_ok = true;
  rs::ParetoCallbacks cb;
  cb.observer = [&](const std::string& label, const rs::EvaluationRecord& rec) {
    indices_ok = indices_ok && rec.index == next_index++;
    // The record carries the ORIGINAL evaluation: both objectives, no eps constraint.
    indices_ok = indices_ok && rec.evaluation.objectives.size() == 2 && rec.evaluation.inequality.empty();
    // Labels in the order they first appear; the anchors run in lockstep
    // (interleaved), the eps sub-problems after them, one after the other.
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
    if (label.rfind("anchor", 0) == 0 && !labels.empty() && labels.back().rfind("eps", 0) == 0) anchor_after_eps = true;
  };
  const rs::ParetoResult a = rs::pareto_front(p, std::vector<double>{1.0, 0.5}, s, cb);
  const rs::ParetoResult b = rs::pareto_front(p, std::vector<double>{1.0, 0.5}, s);
  EXPECT_TRUE(indices_ok);
  EXPECT_EQ(next_index, a.evaluations);
  EXPECT_EQ(labels, (std::vector<std::string>{"anchor 0", "anchor 1", "eps 1", "eps 2", "eps 3", "eps 4", "eps 5",
                                              "eps 6"}));
  EXPECT_FALSE(anchor_after_eps);
  ASSERT_EQ(a.front.size(), b.front.size());
  for (std::size_t i = 0; i < a.front.size(); ++i) {
    EXPECT_EQ(a.front[i].x, b.front[i].x);  // bit-identical
    EXPECT_EQ(a.front[i].label, b.front[i].label);
  }
  EXPECT_EQ(a.evaluations, b.evaluations);
}

TEST(Pareto, StopRequestEndsTheFront) {
  const auto p = two_circles();
  rs::ParetoSettings s = settings(rs::Scalarization::kEpsilonConstraint, "LN_COBYLA", 20);
  std::size_t seen = 0;
  rs::ParetoCallbacks cb;
  cb.observer = [&](const std::string&, const rs::EvaluationRecord&) { ++seen; };
  cb.stop = [&] { return seen >= 150; };
  const rs::ParetoResult r = rs::pareto_front(p, std::vector<double>{1.0, 0.5}, s, cb);
  EXPECT_EQ(to_string(r.status), "stopped");
  EXPECT_EQ(r.evaluations, 150u);
  EXPECT_LT(r.subproblems, 20u);
}

TEST(Pareto, RefusesWhatCannotWork) {
  const auto p = two_circles();
  const std::vector<double> x0{1.0, 0.5};
  rs::ParetoSettings s = settings(rs::Scalarization::kEpsilonConstraint, "LN_BOBYQA", 6);
  try {
    rs::pareto_front(p, x0, s);
    ADD_FAILURE() << "BOBYQA accepted for eps-constraint";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("kWeightedSum"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("LN_COBYLA"), std::string::npos) << e.what();
  }
  s.method = rs::Scalarization::kWeightedSum;  // bounds only: fine for BOBYQA
  EXPECT_EQ(rs::pareto_front(p, x0, s).status, rs::ParetoStatus::kOk);
  EXPECT_THROW(rs::pareto_front(rosenbrock(), std::vector<double>{0, 0}, s), std::invalid_argument);  // 1 objective
  s.primary = 2;
  EXPECT_THROW(rs::pareto_front(p, x0, s), std::invalid_argument);
  s.primary = 0;
  s.points = 1;
  EXPECT_THROW(rs::pareto_front(p, x0, s), std::invalid_argument);
}
