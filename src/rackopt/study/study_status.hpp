// How a study ended. An optimize study ends as its best design's solver
// run did, a pareto study with one combination as its front computation did;
// to_string gives the text of summary.json, report.md and the record.
#pragma once

#include <ostream>
#include <string_view>

#include "rackopt/solvers/pareto.hpp"
#include "rackopt/solvers/solver_status.hpp"

namespace rackopt::study {

enum class StudyStatus {
  kOk,               // evaluate, sweep, reliability, pareto: done
  kConverged,        // optimize: the solver's convergence test (or every variable discrete)
  kMaxEvaluations,   // optimize: the evaluation budget
  kMaxTime,          // optimize: the time limit
  kMaxIterations,    // optimize with Ipopt: ipopt_max_iterations
  kSolverFailed,     // optimize: the solver gave up (its best design is kept)
  kAnchorInfeasible, // pareto: an anchor found no feasible point; the front may be partial
  kNoFeasiblePoint,  // designs were computed, none feasible
  kAllFailed,        // every design failed
  kStopped,          // a stop request (Ctrl-C): --resume continues
};

// "ok", "converged", "max_evaluations", "max_time", "max_iterations",
// "solver_failed", "anchor_infeasible", "no_feasible_point", "all_failed",
// "stopped".
std::string_view to_string(StudyStatus status);
inline std::ostream& operator<<(std::ostream& out, StudyStatus status) { return out << to_string(status); }

// The study status that carries a solver's or a front's status over.
StudyStatus study_status(solvers::SolverStatus status);
StudyStatus study_status(solvers::ParetoStatus status);

}  // namespace rackopt::study
