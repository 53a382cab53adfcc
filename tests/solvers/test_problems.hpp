// Small analytic problems for the solver adapter tests. Every expected
// optimum used by the tests is derived from the math in the test comments,
// never from a run of the adapters.
#pragma once

#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "rackopt/solvers/problem.hpp"
#include "rackopt/solvers/solver.hpp"

namespace rackopt::solvers::testing {

using Fn = std::function<Evaluation(std::span<const double>)>;

// A Problem from a lambda; bounds and constraint counts as given.
class LambdaProblem : public Problem {
 public:
  LambdaProblem(std::vector<double> lower, std::vector<double> upper, Fn fn, std::size_t num_ineq = 0,
                std::size_t num_eq = 0, std::size_t num_obj = 1)
      : lower_(std::move(lower)), upper_(std::move(upper)), fn_(std::move(fn)), ni_(num_ineq), ne_(num_eq),
        no_(num_obj) {}
  std::size_t dimension() const override { return lower_.size(); }
  std::vector<double> lower_bounds() const override { return lower_; }
  std::vector<double> upper_bounds() const override { return upper_; }
  std::size_t num_objectives() const override { return no_; }
  std::size_t num_inequality() const override { return ni_; }
  std::size_t num_equality() const override { return ne_; }
  std::size_t num_integer() const override { return nix_; }
  Evaluation evaluate(std::span<const double> x) const override { return fn_(x); }
  // The last n variables whole-valued (Problem::num_integer).
  LambdaProblem& with_integers(std::size_t n) {
    nix_ = n;
    return *this;
  }

 private:
  std::vector<double> lower_, upper_;
  Fn fn_;
  std::size_t ni_, ne_, no_;
  std::size_t nix_ = 0;
};

inline Evaluation ok(double f, std::vector<double> ineq = {}, std::vector<double> eq = {}) {
  Evaluation e;
  e.objectives = {f};
  e.inequality = std::move(ineq);
  e.equality = std::move(eq);
  return e;
}

inline Evaluation failed(std::string why) {
  Evaluation e;
  e.status = EvaluationStatus::kFailed;
  e.message = std::move(why);
  return e;
}

// Rosenbrock in 2D: f = (1-x)^2 + 100 (y-x^2)^2, minimum f = 0 at (1, 1).
inline LambdaProblem rosenbrock() {
  return LambdaProblem({-2, -2}, {2, 2}, [](std::span<const double> x) {
    return ok((1 - x[0]) * (1 - x[0]) + 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]));
  });
}

// Shifted, weighted quadratic in 4D: f = sum w_i (x_i - c_i)^2, minimum 0 at c.
inline const std::vector<double> kQuadCenter{0.3, -1.2, 2.5, 0.7};
inline LambdaProblem shifted_quadratic() {
  return LambdaProblem({-5, -5, -5, -5}, {5, 5, 5, 5}, [](std::span<const double> x) {
    const double w[4] = {1.0, 2.0, 0.5, 3.0};
    double f = 0;
    for (int i = 0; i < 4; ++i) f += w[i] * (x[i] - kQuadCenter[i]) * (x[i] - kQuadCenter[i]);
    return ok(f);
  });
}

// min x^2 + y^2 s.t. x + y >= 1 (g = 1 - x - y <= 0). Lagrange: 2x = 2y = lambda,
// x + y = 1 -> (0.5, 0.5), f = 0.5; the constraint is active.
inline LambdaProblem disk_above_line() {
  return LambdaProblem({-2, -2}, {2, 2},
                       [](std::span<const double> x) { return ok(x[0] * x[0] + x[1] * x[1], {1 - x[0] - x[1]}); }, 1);
}

// min x^2 + y^2 s.t. x + y = 1: same stationary point (0.5, 0.5), f = 0.5.
inline LambdaProblem disk_on_line() {
  return LambdaProblem({-2, -2}, {2, 2},
                       [](std::span<const double> x) { return ok(x[0] * x[0] + x[1] * x[1], {}, {x[0] + x[1] - 1}); },
                       0, 1);
}

// Hock-Schittkowski problem 71: min x1 x4 (x1 + x2 + x3) + x3
// s.t. x1 x2 x3 x4 >= 25, x1^2 + x2^2 + x3^2 + x4^2 = 40, 1 <= x <= 5, x0 = (1, 5, 5, 1).
// Published optimum (Hock & Schittkowski 1981): f* = 17.0140173,
// x* = (1, 4.7429994, 3.8211503, 1.3794082).
inline LambdaProblem hs71() {
  return LambdaProblem({1, 1, 1, 1}, {5, 5, 5, 5},
                       [](std::span<const double> x) {
                         return ok(x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2], {25 - x[0] * x[1] * x[2] * x[3]},
                                   {x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3] - 40});
                       },
                       1, 1);
}
inline const std::vector<double> kHs71Start{1, 5, 5, 1};
inline const std::vector<double> kHs71Optimum{1, 4.7429994, 3.8211503, 1.3794082};
inline constexpr double kHs71Objective = 17.0140173;

inline SolverSettings nlopt_settings(const std::string& algorithm, std::size_t budget = 4000) {
  SolverSettings s;
  s.library = "nlopt";
  s.algorithm = algorithm;
  s.max_evaluations = budget;
  return s;
}

inline SolverSettings ipopt_settings(std::size_t budget = 4000) {
  SolverSettings s;
  s.library = "ipopt";
  s.max_evaluations = budget;
  return s;
}

}  // namespace rackopt::solvers::testing
