// Convergence of the adapters on problems with known optima (see
// test_problems.hpp for where each optimum comes from).
#include <gtest/gtest.h>

#include <cmath>

#include "test_problems.hpp"

namespace rs = rackopt::solvers;
using namespace rackopt::solvers::testing;

namespace {

struct Case {
  rs::SolverSettings settings;
  double x_tol;  // accepted distance to the analytic optimum, per component
};

std::string label(const rs::SolverSettings& s) {
  return s.library + ":" + s.algorithm + (s.local_algorithm.empty() ? "" : "/" + s.local_algorithm) +
         (s.central_differences ? " central" : " forward");
}

// Forward differences bias the gradient by about h f''/2 (h = 1e-6 (ub-lb));
// on ill-conditioned Rosenbrock that moves the stationary point by ~2e-3, and
// Ipopt's line search stalls near the optimum. Central differences remove
// the bias to O(h^2) (exact for quadratics).
rs::SolverSettings central(rs::SolverSettings s) {
  s.central_differences = true;
  return s;
}

void expect_optimum(const rs::Problem& p, const std::vector<double>& x0, const Case& c,
                    const std::vector<double>& x_star, double f_star) {
  SCOPED_TRACE(label(c.settings));
  const rs::SolverResult r = rs::minimize(p, x0, c.settings);
  ASSERT_TRUE(r.feasible) << r.status << " " << r.solver_message;
  EXPECT_EQ(to_string(r.status), "converged") << r.solver_message;
  ASSERT_EQ(r.x.size(), x_star.size());
  for (std::size_t i = 0; i < x_star.size(); ++i) EXPECT_NEAR(r.x[i], x_star[i], c.x_tol) << "component " << i;
  EXPECT_NEAR(r.evaluation.objectives[0], f_star, 10 * c.x_tol * (1 + std::abs(f_star)));
  EXPECT_LE(r.evaluations, c.settings.max_evaluations);
  EXPECT_EQ(r.best_history.size(), r.evaluations);
  EXPECT_EQ(r.best_history.back(), r.evaluation.objectives[0]);
}

}  // namespace

TEST(Convergence, Rosenbrock2D) {
  // Analytic optimum (1, 1), f = 0.
  const auto p = rosenbrock();
  for (const Case& c : {Case{nlopt_settings("LN_BOBYQA"), 1e-3}, Case{nlopt_settings("LN_SBPLX"), 1e-3},
                        Case{nlopt_settings("LN_NELDERMEAD"), 2e-3}, Case{central(nlopt_settings("LD_SLSQP")), 1e-4},
                        Case{central(nlopt_settings("LD_LBFGS")), 1e-4}, Case{central(ipopt_settings()), 1e-5}})
    expect_optimum(p, {-1.2, 1.0}, c, {1.0, 1.0}, 0.0);
}

TEST(Convergence, ShiftedQuadratic4D) {
  // Analytic optimum at the center c, f = 0.
  const auto p = shifted_quadratic();
  for (const Case& c : {Case{nlopt_settings("LN_BOBYQA"), 1e-4}, Case{nlopt_settings("LN_COBYLA"), 1e-3},
                        Case{nlopt_settings("LD_SLSQP"), 1e-4}, Case{nlopt_settings("LD_CCSAQ"), 1e-3},
                        Case{central(ipopt_settings()), 1e-6}})
    expect_optimum(p, {0, 0, 0, 0}, c, kQuadCenter, 0.0);
}

TEST(Convergence, ActiveInequality) {
  // min x^2+y^2 s.t. x+y >= 1: (0.5, 0.5), f = 0.5 (Lagrange conditions).
  const auto p = disk_above_line();
  rs::SolverSettings auglag = nlopt_settings("AUGLAG");
  auglag.local_algorithm = "LN_BOBYQA";
  rs::SolverSettings ln_auglag = nlopt_settings("LN_AUGLAG");  // NLopt's default sub-solver, set by us
  for (const Case& c : {Case{nlopt_settings("LN_COBYLA"), 1e-4}, Case{nlopt_settings("LD_SLSQP"), 1e-4},
                        Case{nlopt_settings("LD_MMA"), 1e-3}, Case{nlopt_settings("LD_CCSAQ"), 1e-3},
                        Case{auglag, 1e-3}, Case{ln_auglag, 1e-3}, Case{ipopt_settings(), 1e-5},
                        Case{central(ipopt_settings()), 1e-6}})
    expect_optimum(p, {2.0, -1.0}, c, {0.5, 0.5}, 0.5);
}

TEST(Convergence, Equality) {
  // min x^2+y^2 s.t. x+y = 1: (0.5, 0.5), f = 0.5.
  const auto p = disk_on_line();
  rs::SolverSettings auglag_eq = nlopt_settings("AUGLAG_EQ");
  auglag_eq.local_algorithm = "LN_COBYLA";
  for (const Case& c : {Case{nlopt_settings("LN_COBYLA"), 1e-4}, Case{nlopt_settings("LD_SLSQP"), 1e-4},
                        Case{auglag_eq, 1e-3}, Case{central(ipopt_settings()), 1e-6}})
    expect_optimum(p, {1.5, 1.5}, c, {0.5, 0.5}, 0.5);
}

TEST(Convergence, HockSchittkowski71) {
  const auto p = hs71();
  rs::SolverSettings auglag = nlopt_settings("AUGLAG", 20000);
  auglag.local_algorithm = "LD_LBFGS";
  for (const Case& c : {Case{nlopt_settings("LD_SLSQP"), 1e-4}, Case{nlopt_settings("LN_COBYLA"), 1e-3},
                        Case{auglag, 2e-3}, Case{central(ipopt_settings()), 1e-5}})
    expect_optimum(p, kHs71Start, c, kHs71Optimum, kHs71Objective);
}

TEST(Convergence, IpoptForwardDifferencesStillNearOptimum) {
  // With the default forward differences Ipopt cannot meet tol = 1e-8 on a
  // quadratic (the gradient is biased by h w_i, see above) and may run into
  // the budget, but the best point kept by the adapter is within a few h of
  // the analytic optimum c.
  const auto p = shifted_quadratic();
  const rs::SolverResult r = rs::minimize(p, std::vector<double>{0, 0, 0, 0}, ipopt_settings(600));
  ASSERT_TRUE(r.feasible);
  EXPECT_LE(r.evaluations, 600u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(r.x[i], kQuadCenter[i], 1e-4);
}
