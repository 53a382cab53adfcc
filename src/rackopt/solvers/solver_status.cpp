#include "rackopt/solvers/solver_status.hpp"

namespace rackopt::solvers {

std::string_view to_string(SolverStatus status) {
  switch (status) {
    case SolverStatus::kAllFailed: return "all_failed";
    case SolverStatus::kNoFeasiblePoint: return "no_feasible_point";
    case SolverStatus::kMaxEvaluations: return "max_evaluations";
    case SolverStatus::kMaxTime: return "max_time";
    case SolverStatus::kStopped: return "stopped";
    case SolverStatus::kConverged: return "converged";
    case SolverStatus::kMaxIterations: return "max_iterations";
    case SolverStatus::kSolverFailed: return "solver_failed";
  }
  return "?";
}

}  // namespace rackopt::solvers
