// Runs that must END: solvers that keep asking for points already evaluated
// (answered from the adapter's memo), stop requests and time limits seen on
// such runs, Pareto fronts with infeasible eps cells. Every run here goes
// through `finishes_within`: if a regression brings the hang back, the test
// fails after a few seconds instead of blocking CI.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <limits>

#include "rackopt/solvers/evaluation_tracker.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

// Runs f on its own thread. A stuck solver thread cannot be cancelled, so on
// timeout the test binary reports the hang and exits at once (gtest runs
// each test in its own process under ctest, so only this test fails).
template <class F>
auto finishes_within(double seconds, const char* what, F f) -> decltype(f()) {
  auto done = std::async(std::launch::async, std::move(f));
  if (done.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
    std::fprintf(stderr, "\nHANG: %s did not finish within %g s\n", what, seconds);
    std::fflush(stderr);
    std::_Exit(3);
  }
  return done.get();
}

double elapsed_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// f_i = |x - a_i|^2 with a_i the corners of an equilateral triangle of side 1
// (a_0 = (0,0), a_1 = (1,0), a_2 = (1/2, sqrt(3)/2)).
const double kH = std::sqrt(3.0) / 2;
const double kCorner[3][2] = {{0, 0}, {1, 0}, {0.5, kH}};
std::vector<double> triangle_objectives(std::span<const double> x) {
  std::vector<double> f;
  for (const auto& c : kCorner) f.push_back((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]));
  return f;
}

// The eps sub-problem "eps 1,1" of the 3-objective triangle front (ideal 0,
// nadir 1): min f_0 s.t. f_1 <= eps, f_2 <= eps. For eps = 0.2 it is
// infeasible: the discs of radius sqrt(0.2) = 0.447 around a_1 and a_2 (1
// apart) do not meet. max(f_1, f_2) is smallest at the midpoint of a_1 a_2,
// (0.75, sqrt(3)/4), where f_1 = f_2 = 1/4: the least violation is 0.05.
LambdaProblem infeasible_eps_cell(double eps = 0.2) {
  return LambdaProblem({-1, -1}, {2, 2},
                       [eps](std::span<const double> x) {
                         const std::vector<double> f = triangle_objectives(x);
                         return ok(f[0], {f[1] - eps, f[2] - eps});
                       },
                       2);
}

// f = x + y on [0,1]^2: the minimum is the corner (0,0). GN_CRS2_LM
// (NLopt 2.7.1) keeps reflecting its population onto that corner, asking
// for the very same point over and over.
LambdaProblem linear_to_corner() {
  return LambdaProblem({0, 0}, {1, 1}, [](std::span<const double> x) { return ok(x[0] + x[1]); });
}

// Counts the stop polls: the adapter polls once per point request (memo
// hits included), so this is an independent count of what the solver asked.
struct Counting {
  std::size_t evaluations = 0, polls = 0;
  std::size_t stop_after_polls = 0;  // 0 = never stop
  rs::SolverCallbacks callbacks() {
    rs::SolverCallbacks cb;
    cb.observer = [this](const rs::EvaluationRecord&) { ++evaluations; };
    cb.stop = [this] {
      ++polls;
      return stop_after_polls > 0 && polls >= stop_after_polls;
    };
    return cb;
  }
};

}  // namespace

TEST(Termination, RequestCapMatchesTheDocumentedFormula) {
  rs::SolverSettings s;
  s.max_evaluations = 2000;
  EXPECT_EQ(rs::detail::max_point_requests(s), 21000u);
  s.max_evaluations = 1;
  EXPECT_EQ(rs::detail::max_point_requests(s), 1010u);
  s.max_evaluations = std::numeric_limits<std::size_t>::max() / 2;  // saturates instead of wrapping
  EXPECT_EQ(rs::detail::max_point_requests(s), std::numeric_limits<std::size_t>::max());
}

TEST(Termination, CobylaOnInfeasibleEpsCellEnds) {
  // Before the request cap, LN_COBYLA cycled here forever on memoized points
  // (20 evaluations, then nothing new); max_seconds did not help either.
  const auto p = infeasible_eps_cell();
  for (const char* algorithm : {"LN_COBYLA", "LD_SLSQP", "LD_MMA", "LN_AUGLAG"}) {
    SCOPED_TRACE(algorithm);
    Counting seen;
    const rs::SolverSettings s = nlopt_settings(algorithm, 2000);
    const rs::SolverResult r = finishes_within(20, algorithm, [&] {
      return rs::minimize(p, std::vector<double>{0.4, 0.3}, s, seen.callbacks());
    });
    EXPECT_EQ(to_string(r.status), "no_feasible_point");
    EXPECT_LE(r.evaluations, 2000u);
    EXPECT_EQ(r.evaluations, seen.evaluations);
    // At most the cap of requests, plus the one poll that found it exhausted.
    EXPECT_LE(seen.polls, rs::detail::max_point_requests(s) + 1);
    // No point violates less than 0.05 (see infeasible_eps_cell); the
    // adapter keeps the least violating point it saw.
    const double violation = rs::max_violation(r.evaluation);
    EXPECT_GE(violation, 0.05 - 1e-12);
    EXPECT_LT(violation, 0.06);
    if (seen.polls > 10 * seen.evaluations) {
      EXPECT_NE(r.solver_message.find("kept revisiting"), std::string::npos) << r.solver_message;
    }
  }
}

TEST(Termination, RevisitingSolverIsCutByTheRequestCap) {
  const auto p = linear_to_corner();
  Counting seen;
  const rs::SolverSettings s = nlopt_settings("GN_CRS2_LM", 500);
  const rs::SolverResult r = finishes_within(20, "GN_CRS2_LM on a linear function", [&] {
    return rs::minimize(p, std::vector<double>{0.5, 0.5}, s, seen.callbacks());
  });
  EXPECT_EQ(to_string(r.status), "max_evaluations") << r.solver_message;
  EXPECT_LT(r.evaluations, 500u);  // the cap, not the evaluation budget, ended it
  EXPECT_EQ(seen.polls, rs::detail::max_point_requests(s) + 1);
  EXPECT_NE(r.solver_message.find("kept revisiting evaluated points"), std::string::npos) << r.solver_message;
  EXPECT_NEAR(r.x[0], 0.0, 1e-6);  // the analytic minimum (0, 0)
  EXPECT_NEAR(r.x[1], 0.0, 1e-6);
}

TEST(Termination, TimeLimitAndStopArePolledOnMemoHits) {
  // A budget so large that only the clock or the stop request can end the
  // revisiting solvers: both must be seen although no new point is evaluated.
  const auto corner = linear_to_corner();
  const auto cell = infeasible_eps_cell();
  for (const char* algorithm : {"GN_CRS2_LM", "LN_COBYLA"}) {
    SCOPED_TRACE(algorithm);
    const rs::Problem& p = std::string(algorithm) == "LN_COBYLA" ? static_cast<const rs::Problem&>(cell) : corner;
    rs::SolverSettings s = nlopt_settings(algorithm, 1'000'000'000);
    s.max_seconds = 0.2;
    Counting timed;
    const auto t0 = std::chrono::steady_clock::now();
    const rs::SolverResult r = finishes_within(20, "time limit on a revisiting solver", [&] {
      return rs::minimize(p, std::vector<double>{0.5, 0.5}, s, timed.callbacks());
    });
    const double seconds = elapsed_since(t0);
    EXPECT_GE(seconds, 0.2);
    EXPECT_LT(seconds, 2.0);
    EXPECT_LT(r.evaluations, 10'000u);  // the solver was not making new points
    EXPECT_GT(timed.polls, 10 * r.evaluations);
    if (to_string(r.status) != "no_feasible_point") {
      EXPECT_EQ(to_string(r.status), "max_time");
    }

    s.max_seconds = 0;
    Counting stopping;
    stopping.stop_after_polls = 50'000;
    const rs::SolverResult q = finishes_within(20, "stop request on a revisiting solver", [&] {
      return rs::minimize(p, std::vector<double>{0.5, 0.5}, s, stopping.callbacks());
    });
    EXPECT_EQ(stopping.polls, 50'000u);
    EXPECT_LT(q.evaluations, 10'000u);
    if (to_string(q.status) != "no_feasible_point") {
      EXPECT_EQ(to_string(q.status), "stopped");
    }
  }
}

TEST(Termination, ThreeObjectiveEpsConstraintFrontEnds) {
  // The triangle front of pareto_test.cpp (ThreeObjectivesTriangle) with the
  // eps-constraint method, whose low grid cells are infeasible (see
  // infeasible_eps_cell). The Pareto set is the triangle itself (a sum of
  // strictly convex functions: the convex hull of the a_i); ideal (0,0,0),
  // nadir (1,1,1).
  const LambdaProblem p(
      {-1, -1}, {2, 2},
      [](std::span<const double> x) {
        rs::Evaluation e;
        e.objectives = triangle_objectives(x);
        return e;
      },
      0, 0, 3);
  rs::ParetoSettings s;
  s.method = rs::Scalarization::kEpsilonConstraint;
  s.points = 19;  // 3 anchors + a 4 x 4 grid
  s.solver = nlopt_settings("LN_COBYLA", 2000);
  const rs::ParetoResult r = finishes_within(20, "3-objective eps-constraint front", [&] {
    return rs::pareto_front(p, std::vector<double>{0.4, 0.3}, s);
  });
  EXPECT_EQ(to_string(r.status), "ok");
  EXPECT_EQ(r.subproblems, 19u);
  EXPECT_LE(r.evaluations, 19u * 2000u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.ideal[i], 0.0, 1e-5);
    EXPECT_NEAR(r.nadir[i], 1.0, 1e-3);
  }
  ASSERT_GE(r.front.size(), 8u);
  for (const rs::ParetoPoint& q : r.front) {
    const double x = q.x[0], y = q.x[1];
    EXPECT_GE(y, -2e-3) << q.label;
    EXPECT_LE(y, 2 * kH * x + 2e-3) << q.label;
    EXPECT_LE(y, 2 * kH * (1 - x) + 2e-3) << q.label;
  }
}

TEST(Termination, ParetoStopDuringAnInfeasibleSubProblemEndsTheFront) {
  // Nothing is feasible (x >= 5 outside the box [-1,3]^2), so every sub-solve
  // reports no_feasible_point, which outranks "stopped" in its status: the
  // front must still notice the stop and start no further sub-problem. The
  // two anchors run in lockstep: the one that asked for its next point in
  // the round the stop came makes that one evaluation more, no other.
  const LambdaProblem p(
      {-1, -1}, {3, 3},
      [](std::span<const double> x) {
        rs::Evaluation e;
        e.objectives = {x[0] * x[0] + x[1] * x[1], (x[0] - 2) * (x[0] - 2) + x[1] * x[1]};
        e.inequality = {5 - x[0]};
        return e;
      },
      1, 0, 2);
  rs::ParetoSettings s;
  s.points = 10;
  s.solver = nlopt_settings("LN_COBYLA", 400);
  std::size_t seen = 0;
  rs::ParetoCallbacks cb;
  cb.observer = [&](const std::string&, const rs::EvaluationRecord&) { ++seen; };
  cb.stop = [&] { return seen >= 30; };
  const rs::ParetoResult r = finishes_within(20, "stopped Pareto front", [&] {
    return rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s, cb);
  });
  EXPECT_EQ(to_string(r.status), "stopped");
  EXPECT_GE(r.evaluations, 30u);
  EXPECT_LE(r.evaluations, 31u);
  EXPECT_EQ(r.subproblems, 2u);  // the anchors; no eps sub-problem started
  EXPECT_TRUE(r.front.empty());

  // A stop that is already set: nothing is evaluated at all.
  cb.stop = [] { return true; };
  seen = 0;
  const rs::ParetoResult none = finishes_within(20, "Pareto front stopped from the start", [&] {
    return rs::pareto_front(p, std::vector<double>{0.5, 0.5}, s, cb);
  });
  EXPECT_EQ(to_string(none.status), "stopped");
  EXPECT_EQ(none.evaluations, 0u);
  EXPECT_EQ(none.subproblems, 1u);
}
