// How a single-objective solve ended, most important first in
// SolverResult::status's precedence (solver.hpp). The text of each value
// (to_string) is what reports, JSON and the record show.
#pragma once

#include <ostream>
#include <string_view>

namespace rackopt::solvers {

enum class SolverStatus {
  kAllFailed,        // every evaluation failed
  kNoFeasiblePoint,  // evaluations succeeded, none feasible
  kMaxEvaluations,   // the evaluation budget or the request cap was hit
  kMaxTime,          // the wall-time limit was hit
  kStopped,          // a stop request (Ctrl-C) ended it
  kConverged,        // the solver's own convergence test ended it
  kMaxIterations,    // Ipopt reached ipopt_max_iterations
  kSolverFailed,     // the solver gave up (NLopt FAILURE, Ipopt restoration failure, ...)
};

// "all_failed", "no_feasible_point", "max_evaluations", "max_time",
// "stopped", "converged", "max_iterations", "solver_failed".
std::string_view to_string(SolverStatus status);
inline std::ostream& operator<<(std::ostream& out, SolverStatus status) { return out << to_string(status); }

}  // namespace rackopt::solvers
