#include "rackopt/study/study_status.hpp"

namespace rackopt::study {

std::string_view to_string(StudyStatus status) {
  switch (status) {
    case StudyStatus::kOk: return "ok";
    case StudyStatus::kConverged: return "converged";
    case StudyStatus::kMaxEvaluations: return "max_evaluations";
    case StudyStatus::kMaxTime: return "max_time";
    case StudyStatus::kMaxIterations: return "max_iterations";
    case StudyStatus::kSolverFailed: return "solver_failed";
    case StudyStatus::kAnchorInfeasible: return "anchor_infeasible";
    case StudyStatus::kNoFeasiblePoint: return "no_feasible_point";
    case StudyStatus::kAllFailed: return "all_failed";
    case StudyStatus::kStopped: return "stopped";
  }
  return "?";
}

StudyStatus study_status(solvers::SolverStatus status) {
  using S = solvers::SolverStatus;
  switch (status) {
    case S::kAllFailed: return StudyStatus::kAllFailed;
    case S::kNoFeasiblePoint: return StudyStatus::kNoFeasiblePoint;
    case S::kMaxEvaluations: return StudyStatus::kMaxEvaluations;
    case S::kMaxTime: return StudyStatus::kMaxTime;
    case S::kStopped: return StudyStatus::kStopped;
    case S::kConverged: return StudyStatus::kConverged;
    case S::kMaxIterations: return StudyStatus::kMaxIterations;
    case S::kSolverFailed: return StudyStatus::kSolverFailed;
  }
  return StudyStatus::kSolverFailed;
}

StudyStatus study_status(solvers::ParetoStatus status) {
  using P = solvers::ParetoStatus;
  switch (status) {
    case P::kOk: return StudyStatus::kOk;
    case P::kNoFeasiblePoint: return StudyStatus::kNoFeasiblePoint;
    case P::kAnchorInfeasible: return StudyStatus::kAnchorInfeasible;
    case P::kStopped: return StudyStatus::kStopped;
  }
  return StudyStatus::kOk;
}

}  // namespace rackopt::study
