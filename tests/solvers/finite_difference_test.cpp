// Finite-difference gradients of the adapters (EvaluationTracker::jacobian)
// against closed-form derivatives, at the bounds and for variables whose
// range is tiny next to their magnitude; Ipopt with central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rackopt/solvers/evaluation_tracker.hpp"
#include "test_problems.hpp"

namespace rs = rackopt::solvers;
namespace rd = rackopt::solvers::detail;
using namespace rackopt::solvers::testing;

namespace {

// f = x^2 + 3y on [0,1] x [-1,2], so df/dx = 2x, df/dy = 3. Steps with
// gradient_step g: h_x = g, h_y = 3g. For the quadratic term a forward step h
// gives 2x + h, a backward one 2x - h, a central one 2x exactly; the linear
// term is exact either way.
LambdaProblem quadratic_plus_linear() {
  return LambdaProblem({0, -1}, {1, 2}, [](std::span<const double> x) { return ok(x[0] * x[0] + 3 * x[1]); });
}

struct Probe {
  double x, y;
  bool central;
  double dfdx;  // expected (closed form of the difference quotient, see above)
};

}  // namespace

TEST(FiniteDifferences, OneSidedAtTheBoundsExactInside) {
  const auto p = quadratic_plus_linear();
  const double g = 0.01;
  for (const Probe& c : {Probe{0.5, 0.5, true, 1.0}, Probe{0.5, 0.5, false, 1.0 + g},
                         Probe{1.0, 2.0, true, 2.0 - g}, Probe{1.0, 2.0, false, 2.0 - g},
                         Probe{0.0, -1.0, true, g}, Probe{0.0, -1.0, false, g},
                         Probe{1.0 - g / 2, 0.0, true, 2 * (1.0 - g / 2) - g}}) {  // less than h from the bound
    SCOPED_TRACE(::testing::Message() << "(" << c.x << ", " << c.y << ") " << (c.central ? "central" : "forward"));
    rs::SolverSettings s;
    s.gradient_step = g;
    s.central_differences = c.central;
    std::vector<std::vector<double>> probes;
    rs::SolverCallbacks cb;
    cb.observer = [&](const rs::EvaluationRecord& r) { probes.push_back(r.x); };
    rd::EvaluationTracker t(p, s, cb, {c.x, c.y});
    const double x[2] = {c.x, c.y};
    const rd::Jacobian& j = t.jacobian(x);
    ASSERT_TRUE(j.center_ok);
    EXPECT_NEAR(j.values[0], c.dfdx, 1e-9);
    EXPECT_NEAR(j.values[1], 3.0, 1e-9);
    for (const auto& q : probes) {  // never outside the box
      EXPECT_GE(q[0], 0.0);
      EXPECT_LE(q[0], 1.0);
      EXPECT_GE(q[1], -1.0);
      EXPECT_LE(q[1], 2.0);
    }
  }
}

TEST(FiniteDifferences, LargestStepStaysInsideTheBox) {
  // gradient_step 0.25 (the largest allowed) from points on and next to the
  // bounds: every probe inside, every derivative finite and of the right sign
  // (df/dx = 2x >= 0 on [0,1]).
  const auto p = quadratic_plus_linear();
  for (bool central : {false, true})
    for (double x0 : {0.0, 0.1, 0.5, 0.9, 1.0}) {
      rs::SolverSettings s;
      s.gradient_step = 0.25;
      s.central_differences = central;
      bool inside = true;
      rs::SolverCallbacks cb;
      cb.observer = [&](const rs::EvaluationRecord& r) {
        inside = inside && r.x[0] >= 0 && r.x[0] <= 1 && r.x[1] >= -1 && r.x[1] <= 2;
      };
      rd::EvaluationTracker t(p, s, cb, {x0, 2.0});
      const double x[2] = {x0, 2.0};
      const rd::Jacobian& j = t.jacobian(x);
      EXPECT_TRUE(inside) << x0;
      EXPECT_TRUE(std::isfinite(j.values[0]) && std::isfinite(j.values[1])) << x0;
      EXPECT_GE(j.values[0], 0.0) << x0;
      EXPECT_NEAR(j.values[1], 3.0, 1e-12) << x0;
    }
}

TEST(FiniteDifferences, TinyRangeFarFromZeroStillMovesX) {
  // A variable in [1e8, 1e8 + 1e-2] with gradient_step 1e-7: the nominal step
  // 1e-9 is below half an ulp of 1e8 (7.45e-9), so x + h == x. The step is
  // raised to 16 ulp of |x|; the slope of f = (x - c)^2 is 2 (x - c).
  const double lo = 1e8, hi = 1e8 + 1e-2, c = 1e8 + 7e-3;
  const LambdaProblem p({lo}, {hi}, [c](std::span<const double> x) { return ok((x[0] - c) * (x[0] - c)); });
  const double xc = 1e8 + 5e-3;
  for (bool central : {false, true}) {
    rs::SolverSettings s;
    s.gradient_step = 1e-7;
    s.central_differences = central;
    const rs::SolverCallbacks none;  // the tracker keeps references: no temporaries
    rd::EvaluationTracker t(p, s, none, {xc});
    const rd::Jacobian& j = t.jacobian(&xc);
    EXPECT_NEAR(j.values[0], 2 * (xc - c), 1e-6) << (central ? "central" : "forward");  // -4e-3
  }
  // So a gradient-based solver can move: SLSQP reaches c.
  rs::SolverSettings s = nlopt_settings("LD_SLSQP", 300);
  s.gradient_step = 1e-7;
  s.xtol_rel = 0;
  s.xtol_abs = 1e-9;
  const rs::SolverResult r = rs::minimize(p, std::vector<double>{xc}, s);
  EXPECT_NEAR(r.x[0], c, 1e-5) << r.status << " " << r.solver_message;
}

TEST(FiniteDifferences, NaNPointIsNeverEvaluated) {
  std::size_t calls = 0;
  const LambdaProblem p({0}, {1}, [&calls](std::span<const double> x) {
    ++calls;
    return ok(x[0]);
  });
  const rs::SolverSettings s;
  const rs::SolverCallbacks none;
  rd::EvaluationTracker t(p, s, none, {0.5});
  const double bad = std::numeric_limits<double>::quiet_NaN();
  const rs::Evaluation e = t.at(&bad);
  EXPECT_FALSE(e.ok());
  EXPECT_NE(e.message.find("NaN"), std::string::npos) << e.message;
  EXPECT_EQ(calls, 0u);
  const rd::Jacobian& j = t.jacobian(&bad);
  EXPECT_FALSE(j.center_ok);
  EXPECT_EQ(calls, 0u);
}

TEST(FiniteDifferences, IpoptCentralReachesTheOptimumWithinTheBudget) {
  // docs/solvers.md: with forward differences Ipopt's gradient is biased by
  // ~h f''/2 and it cannot meet tol 1e-8; central differences are exact for
  // quadratics, so it converges, accurately and quickly. Analytic optima:
  // the center c of the shifted quadratic, (0.5, 0.5) for the disk problems.
  struct Case {
    const char* name;
    LambdaProblem problem;
    std::vector<double> x0, x_star;
  };
  for (const Case& c : {Case{"quadratic", shifted_quadratic(), {0, 0, 0, 0}, kQuadCenter},
                        Case{"inequality", disk_above_line(), {2, -1}, {0.5, 0.5}},
                        Case{"equality", disk_on_line(), {1.5, 1.5}, {0.5, 0.5}}}) {
    SCOPED_TRACE(c.name);
    rs::SolverSettings s = ipopt_settings(600);
    s.central_differences = true;
    const rs::SolverResult r = rs::minimize(c.problem, c.x0, s);
    EXPECT_EQ(to_string(r.status), "converged") << r.solver_message;
    EXPECT_LT(r.evaluations, 300u);
    for (std::size_t i = 0; i < c.x_star.size(); ++i) EXPECT_NEAR(r.x[i], c.x_star[i], 1e-7);
  }
}
