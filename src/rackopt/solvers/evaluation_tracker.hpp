// Internal to the solver adapters (not part of the public API): the one
// place where the Problem is evaluated. It counts evaluations against the
// budget, polls the stop request and the clock, caches the last few points
// (NLopt asks for the objective and the constraints at the same x in
// separate callbacks), computes finite-difference Jacobians, turns
// non-finite values into failed evaluations, tells the observer, and keeps
// the best point seen. Solvers only ever see what this class hands them.
#pragma once

#include <optional>

#include "rackopt/solvers/solver_status.hpp"

#include <chrono>
#include <cstddef>
#include <exception>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "rackopt/solvers/problem.hpp"
#include "rackopt/solvers/solver.hpp"

namespace rackopt::solvers::detail {

// Why a run was ended by the adapter (not by the solver's own tests).
// kRequests: the solver asked for more points than max_point_requests(),
// i.e. it kept revisiting points answered from the memo (COBYLA cycling on
// an infeasible sub-problem); reported as status "max_evaluations".
enum class Halt { kNone, kBudget, kTime, kStop, kError, kRequests };

// Hard cap on the points a solver may ask for in one run, memo hits
// included: 10 * max_evaluations + 1000 (saturating). Generous for every
// solver that makes progress (SLSQP/Ipopt ask for the same x 2-4 times per
// iterate), small enough that a cycling solver ends in milliseconds.
std::size_t max_point_requests(const SolverSettings& settings);

// Status string of SolverResult for a halt reason ("" for kNone/kError).
std::optional<SolverStatus> halt_status(Halt h);

// Thrown inside the tracker when the run must end (budget, time, stop
// request). Every solver callback catches it; it never leaves the adapters.
struct RunHalted {
  Halt reason;
};

// Finite-difference derivatives of the stacked vector
//   [objective 0, inequality..., equality...]
// at one point, row-major: values[row * n + i] = d row / d x_i.
struct Jacobian {
  bool center_ok = false;      // false: the point itself failed, values are all 0
  std::size_t rows = 0;
  std::vector<double> values;
};

class EvaluationTracker {
 public:
  EvaluationTracker(const Problem& problem, const SolverSettings& settings, const SolverCallbacks& callbacks,
                    std::vector<double> x0_clamped);

  std::size_t dimension() const { return n_; }
  std::size_t num_inequality() const { return ni_; }
  std::size_t num_equality() const { return ne_; }
  const std::vector<double>& lower() const { return lower_; }
  const std::vector<double>& upper() const { return upper_; }
  const std::vector<double>& x0() const { return x0_; }
  // Model evaluations made so far in the whole run (memo hits not counted).
  std::size_t evaluations_so_far() const { return evaluations_; }

  // Multistart number written into the observer records from now on.
  void begin_start(int start);
  // Evaluations made since the last begin_start().
  std::size_t evaluations_in_start() const { return evaluations_ - start_first_index_; }
  // True when the first evaluation of the current start failed (Ipopt then
  // reports Invalid_Number_Detected; we say what really happened).
  bool start_point_failed() const { return start_point_failed_; }
  const std::string& start_point_message() const { return start_point_message_; }

  // The evaluation at x (clamped into the box first). Makes at most one call
  // of Problem::evaluate per distinct x in the whole run (memo of up to
  // kMemoLimit points; solvers do revisit old points, e.g. COBYLA and Ipopt
  // at the end of a run).
  // Every call, memo hits included, polls the stop request and the clock
  // and counts against max_point_requests(): a solver that only revisits
  // old points still ends.
  // Throws RunHalted when the budget, the time, the request cap or a stop
  // request ends the run; lets anything evaluate() or the observer threw
  // pass unchanged.
  Evaluation at(const double* x, bool gradient_probe = false);
  // The same for independent points, result i for xs[i]: the memo answers
  // what it holds, the new distinct points go to Problem::evaluate_batch in
  // one call, and each is then recorded and reported to the observer in the
  // order of `xs` (so the record does not depend on who evaluates them).
  // Every point counts as a request; the stop request and the clock are
  // polled once per batch. When the budget has room for only part of the new
  // points, that part is evaluated and recorded, then RunHalted is thrown.
  std::vector<Evaluation> at_batch(const std::vector<std::vector<double>>& xs, bool gradient_probe = false);
  // Points asked for so far (memo hits included), over the whole run.
  std::size_t point_requests() const { return requests_; }

  // Finite-difference Jacobian at x (see Jacobian); the probes go through
  // at_batch() with gradient_probe = true: one batch of every variable's
  // probes, then one of the other sides of the forward probes that failed.
  // Cached for the last center.
  const Jacobian& jacobian(const double* x);

  // Values handed to a solver in place of a failed evaluation: worse than
  // every objective seen so far, and clearly violated constraints.
  double penalty_objective() const;
  double penalty_constraint() const;

  // Throws RunHalted if a stop request or the time limit says so (no
  // evaluation is made). Used by Ipopt's intermediate callback.
  void poll() const;

  // Runs f; converts RunHalted and any other exception into a halt (the
  // exception is stored for rethrow). Returns false when the run must stop.
  template <class F>
  bool guard(F&& f) noexcept {
    if (halt_ != Halt::kNone) return false;
    try {
      f();
      return true;
    } catch (const RunHalted& h) {
      halt_ = h.reason;
    } catch (...) {
      error_ = std::current_exception();
      halt_ = Halt::kError;
    }
    return false;
  }
  Halt halt() const { return halt_; }
  void rethrow_if_error() const {
    if (error_) std::rethrow_exception(error_);
  }

  // Fills x, evaluation, feasible, evaluations, failed_evaluations,
  // gradient_evaluations and best_history (status is the caller's).
  void fill_result(SolverResult& result) const;
  bool any_ok() const { return ok_evaluations_ > 0; }
  bool any_feasible() const { return has_feasible_; }
  // How the run ended when the tracker alone can tell, most important
  // first: kAllFailed, kNoFeasiblePoint, then the status of a halt (budget,
  // time, stop, request cap); nullopt when the solver's own end decides.
  std::optional<SolverStatus> ending_status() const;

 private:
  static constexpr std::size_t kMemoLimit = 200000;
  Evaluation sanitized(Evaluation e) const;
  void record(const std::vector<double>& x, const Evaluation& e);
  bool stacked(const Evaluation& e, std::vector<double>& out) const;

  const Problem& problem_;
  const SolverSettings& settings_;
  const SolverCallbacks& callbacks_;
  std::size_t n_, ni_, ne_;
  std::vector<double> lower_, upper_, x0_;
  std::chrono::steady_clock::time_point started_;

  std::map<std::vector<double>, Evaluation> memo_;  // every point evaluated (exact doubles)
  std::vector<double> jacobian_x_;
  Jacobian jacobian_;
  bool jacobian_valid_ = false;

  int start_ = 0;
  std::size_t start_first_index_ = 0;
  bool start_point_failed_ = false;
  std::string start_point_message_;

  std::size_t evaluations_ = 0, failed_ = 0, probes_ = 0, ok_evaluations_ = 0;
  std::size_t requests_ = 0, request_cap_ = 0;
  std::vector<double> best_history_;
  bool has_feasible_ = false, has_ok_ = false, has_x0_evaluation_ = false;
  std::vector<double> best_x_, least_infeasible_x_;
  Evaluation best_eval_, least_infeasible_eval_, x0_eval_;
  double least_violation_ = std::numeric_limits<double>::infinity();
  std::string first_failure_;
  double best_objective_seen_ = std::numeric_limits<double>::infinity();
  double worst_objective_seen_ = -std::numeric_limits<double>::infinity();
  double largest_constraint_seen_ = 0.0;

  Halt halt_ = Halt::kNone;
  std::exception_ptr error_;
};

}  // namespace rackopt::solvers::detail
