// One entry point for every single-objective optimizer the toolkit uses:
// NLopt 2.7 algorithms and Ipopt 3.11 behind the same settings and result.
//
// The adapters never trust a solver's own answer: they evaluate the Problem
// themselves (once per distinct x), keep the best feasible point seen over
// every evaluation (finite-difference probes included), count evaluations
// against the budget, and carry exceptions thrown by the model out unchanged.
// See docs/solvers.md for the algorithm table and the pitfalls handled.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rackopt/solvers/problem.hpp"

namespace rackopt::solvers {

struct SolverSettings {
  std::string library = "nlopt";        // "nlopt" | "ipopt" (case-insensitive)
  std::string algorithm = "LN_COBYLA";  // NLopt name, NLOPT_ prefix optional, case-insensitive; ignored for ipopt
  // Sub-solver of AUGLAG/AUGLAG_EQ/G_MLSL/G_MLSL_LDS (required there) and of
  // LN_/LD_AUGLAG(_EQ), GN_/GD_MLSL(_LDS) (optional: LN_COBYLA / LD_MMA by default).
  std::string local_algorithm;
  double xtol_rel = 1e-6, xtol_abs = 0, ftol_rel = 1e-10, ftol_abs = 0;
  // Budget on model evaluations INCLUDING finite-difference probes, enforced
  // by the adapter: evaluate() is called at most this many times in total.
  std::size_t max_evaluations = 1000;
  double max_seconds = 0;               // wall time; 0 = no limit
  // Multistart: x0 first, then (starts-1) points of a Latin hypercube in the
  // box drawn from `seed`. All starts share one budget.
  int starts = 1;
  std::uint64_t seed = 1;               // stochastic algorithms and multistart points; same seed => same result
  double constraint_tolerance = 1e-6;   // our own feasibility re-check of every candidate
  double gradient_step = 1e-6;          // finite-difference step relative to (upper-lower) of each variable
  bool central_differences = false;
  double ipopt_tol = 1e-8;
  int ipopt_max_iterations = 3000;
  int ipopt_print_level = 0;
};

struct SolverCallbacks {
  EvaluationObserver observer;  // every evaluation, in order (may be empty)
  StopRequest stop;             // polled before every evaluation (may be empty)
};

struct SolverResult {
  // Best FEASIBLE point the adapter itself saw (objective minimal among
  // points with max_violation <= constraint_tolerance); if none: the least
  // infeasible successful evaluation; if every evaluation failed: x0.
  std::vector<double> x;
  Evaluation evaluation;          // the evaluation of x
  bool feasible = false;
  // Why the run ended, most important first:
  //   "all_failed"        every evaluation failed (evaluation.message says why)
  //   "no_feasible_point" evaluations succeeded but none was feasible
  //   "max_evaluations" | "max_time" | "stopped"   budget / time / stop request hit
  //   "converged"         the solver ended by its own convergence test
  //   "max_iterations"    Ipopt reached ipopt_max_iterations
  //   "solver_failed"     the solver gave up (NLopt FAILURE, Ipopt restoration failure, ...);
  //                       x is still the best point seen
  std::string status;
  std::string solver_message;     // what NLopt/Ipopt said (return code name per start), for the record
  std::size_t evaluations = 0, failed_evaluations = 0;
  std::size_t gradient_evaluations = 0;  // how many of `evaluations` were finite-difference probes
  std::vector<double> best_history;  // best feasible objective after each evaluation, +inf before the first
};

// Empty string when `settings` can run `problem`; otherwise a message saying
// what is wrong AND what to use instead. Checks the library and algorithm
// names (listing the valid ones), constraint support of the algorithm, the
// local algorithm of AUGLAG/MLSL, more equality constraints than variables,
// a single objective, finite bounds with lower < upper, x0 size and
// finiteness, and the numeric settings (budget > 0, starts >= 1, ...).
std::string check_solver_settings(const SolverSettings& settings, const Problem& problem);
// Same, also checking x0 (its size and finiteness).
std::string check_solver_settings(const SolverSettings& settings, const Problem& problem,
                                  std::span<const double> x0);

// Minimizes objective 0 subject to the problem's constraints from x0
// (clamped into the bounds). Throws std::invalid_argument with the
// check_solver_settings message for an unusable combination. Rethrows
// (unchanged type and message) anything evaluate() or a callback threw.
// Points handed to evaluate() are always inside the box.
SolverResult minimize(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                      const SolverCallbacks& callbacks = {});

// The NLopt algorithm names accepted (without the NLOPT_ prefix).
std::vector<std::string> nlopt_algorithm_names();

}  // namespace rackopt::solvers
