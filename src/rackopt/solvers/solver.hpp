// One entry point for every single-objective optimizer the toolkit uses:
// NLopt 2.7 algorithms, Ipopt 3.11 and pagmo 2.18's population methods behind
// the same settings and result (each library is a SolverBackend,
// solver_backend.hpp).
//
// The adapters never trust a solver's own answer: they evaluate the Problem
// themselves (once per distinct x), keep the best feasible point seen over
// every evaluation (finite-difference probes included), count evaluations
// against the budget, and carry exceptions thrown by the model out unchanged.
// See docs/solvers.md for the algorithm table and the pitfalls handled.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rackopt/solvers/problem.hpp"
#include "rackopt/solvers/solver_status.hpp"

namespace rackopt::solvers {

struct SolverSettings {
  // A library of solver_backends() (solver_backend.hpp): "nlopt", "ipopt" or
  // "pagmo", any case.
  std::string library = "nlopt";
  // One of the library's algorithms (any case; NLopt's take an optional
  // NLOPT_ prefix); ignored by Ipopt, which has one method.
  std::string algorithm = "LN_COBYLA";
  // Sub-solver of the AUGLAG and MLSL variants (AUGLAG, AUGLAG_EQ, G_MLSL,
  // G_MLSL_LDS, LN_/LD_AUGLAG(_EQ), GN_/GD_MLSL(_LDS)); empty = LD_MMA for the
  // LD_/GD_ ones, LN_COBYLA for the others. The adapter always sets one:
  // NLopt 2.7.1 segfaults or throws without it. Must be a local LN_/LD_
  // algorithm (check_solver_settings says which); other algorithms refuse it.
  std::string local_algorithm;
  double xtol_rel = 1e-6, xtol_abs = 0, ftol_rel = 1e-10, ftol_abs = 0;
  // Budget on model evaluations INCLUDING finite-difference probes, enforced
  // by the adapter: evaluate() is called at most this many times in total.
  // Points a solver asks for again are answered from a memo without a model
  // call, but EVERY request counts against a second, hard cap of
  // 10 * max_evaluations + 1000 requests, so a solver that cycles on old
  // points (COBYLA on an infeasible sub-problem, CRS2 on a box corner) still
  // ends: status "max_evaluations", solver_message says "kept revisiting
  // evaluated points".
  std::size_t max_evaluations = 1000;
  // Wall time of this run (all starts); 0 = no limit. Checked, like
  // callbacks.stop, on every point request, memo hits included.
  double max_seconds = 0;
  // Multistart: x0 first, then (starts-1) points of a Latin hypercube in the
  // box drawn from `seed`. All starts share one budget.
  int starts = 1;
  std::uint64_t seed = 1;               // stochastic algorithms and multistart points; same seed => same result
  double constraint_tolerance = 1e-6;   // our own feasibility re-check of every candidate
  // Finite-difference step h_i = gradient_step * (upper_i - lower_i), at
  // least 16 ulp of |x_i| and at most half the range; probes never leave the
  // box (one-sided next to a bound).
  double gradient_step = 1e-6;
  // Central differences (2n probes instead of n) remove the O(h) gradient
  // bias; use them with Ipopt and whenever the optimum must be accurate to
  // better than ~1e-3 (docs/solvers.md, "Finite differences").
  bool central_differences = false;
  // The library's own settings by key (SolverBackend::options() declares
  // each with its default and range, e.g. Ipopt's "ipopt_tol" or pagmo's
  // "population"); a key left out takes the default.
  std::map<std::string, double> options;
};

struct SolverCallbacks {
  EvaluationObserver observer;  // every evaluation, in order (may be empty)
  StopRequest stop;             // polled on every point request, memo hits included (may be empty)
};

struct SolverResult {
  // Best FEASIBLE point the adapter itself saw (objective minimal among
  // points with max_violation <= constraint_tolerance); if none: the least
  // infeasible successful evaluation; if every evaluation failed: x0.
  std::vector<double> x;
  Evaluation evaluation;          // the evaluation of x
  bool feasible = false;
  // Why the run ended, most important first:
  //   kAllFailed        every evaluation failed (evaluation.message says why)
  //   kNoFeasiblePoint  evaluations succeeded but none was feasible
  //   kMaxEvaluations | kMaxTime | kStopped   budget (or the request cap) / time / stop request hit
  //   kConverged        the solver ended by its own convergence test
  //   kMaxIterations    Ipopt reached ipopt_max_iterations
  //   kSolverFailed     the solver gave up (NLopt FAILURE, Ipopt restoration failure, ...);
  //                     x is still the best point seen
  SolverStatus status = SolverStatus::kConverged;
  std::string solver_message;     // what NLopt/Ipopt said (return code name per start), for the record
  std::size_t evaluations = 0, failed_evaluations = 0;
  std::size_t gradient_evaluations = 0;  // how many of `evaluations` were finite-difference probes
  std::vector<double> best_history;  // best feasible objective after each evaluation, +inf before the first
};

// The counts that decide whether a solver can run a problem, known before
// the problem exists (a study file names its variables and constraints).
struct ProblemShape {
  std::size_t dimension = 0;   // continuous variables the solver moves
  std::size_t objectives = 1;
  std::size_t inequality = 0;  // constraints g(x) <= 0
  std::size_t equality = 0;    // constraints h(x) = 0
  std::size_t integer = 0;     // of `dimension`, the last ones take whole values only
};
ProblemShape shape_of(const Problem& problem);

// The setting a refusal concerns, so a study file can point at its line.
enum class SolverSetting {
  kLibrary,         // the library, or what the library cannot do (Ipopt's equality count)
  kAlgorithm,       // the NLopt algorithm, or what it cannot do with this shape
  kLocalAlgorithm,  // the sub-solver of AUGLAG/MLSL
  kNumbers,         // a budget or tolerance out of range
  kOption,          // one of the library's own settings (SolverSettingsRefusal::option names it)
  kProblem,         // the shape itself (no variables, not one objective)
};
struct SolverSettingsRefusal {
  SolverSetting setting;
  std::string message;  // what is wrong AND what to use instead
  std::string option;   // kOption: the key in SolverSettings::options
};

// Whether `settings` can run a problem of `shape`: nullopt when they can;
// otherwise which setting is wrong and why (the same messages as below).
std::optional<SolverSettingsRefusal> check_solver_settings(const SolverSettings& settings, const ProblemShape& shape);

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

// The front-finding algorithm names of every library ("nsga2", "moead").
bool algorithm_finds_fronts(const SolverSettings& settings);

}  // namespace rackopt::solvers
