// status_message, declared with its contract in study_report.hpp.
#include <string>

#include "rackopt/study_report/display_units.hpp"
#include "rackopt/study_report/result_facts.hpp"
#include "rackopt/study_report/study_report.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;

std::string status_message(const StudySpec& spec, const StudyResult& r) {
  const std::string n = std::to_string(r.evaluations) + " evaluation" + (r.evaluations == 1 ? "" : "s");
  if (r.status == StudyStatus::kStopped) {
    const std::string during = r.stopped_during.empty() ? "" : ", during " + r.stopped_during;
    return "stopped after " + n + during +
           "; the results so far are written. Continue with --resume (same --out).";
  }
  if (r.status == StudyStatus::kNoFeasiblePoint) {
    std::string s = "no feasible design in " + n + ".";
    if (r.least_infeasible) {
      s += " The least infeasible design (" + r.least_infeasible->label + ") violates the constraints by " +
           short_number(r.least_infeasible->max_violation) + " (normalized).";
    }
    return s;
  }
  if (r.status == StudyStatus::kAllFailed) {
    std::string s = "every one of the " + n + " failed.";
    const DesignResult* d = r.least_infeasible ? &*r.least_infeasible : (r.best ? &*r.best : nullptr);
    if (d != nullptr && !d->message.empty()) s += " First reason: " + d->message;
    return s;
  }
  std::string s;
  if (r.status == StudyStatus::kOk) {
    s = "done, " + n + ".";
  } else if (r.status == StudyStatus::kConverged) {
    s = "converged after " + n + ".";
  } else if (r.status == StudyStatus::kMaxEvaluations) {
    s = "evaluation budget reached (" + n + ").";
  } else if (r.status == StudyStatus::kMaxTime) {
    s = "time limit reached after " + n + ".";
  } else {
    s = std::string(to_string(r.status)) + " after " + n + ".";
  }
  if (spec.kind == StudyKind::kSweep) {
    const std::size_t feasible = feasible_points(r);
    s += " " + std::to_string(feasible) + " of " + std::to_string(r.sweep_points.size()) + " points feasible.";
  }
  if (spec.kind == StudyKind::kPareto) {
    s += " " + std::to_string(r.front.size()) + " front point" + (r.front.size() == 1 ? "" : "s") + ".";
  } else if (r.best && (spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability)) {
    s += r.best->ok ? (r.best->feasible ? " The design is feasible." : " The design violates the constraints.")
                    : " The design failed: " + r.best->message;
  } else if (r.best) {
    s += r.best->feasible ? " Best feasible design shown." : " Best design shown.";
  } else if (r.least_infeasible) {
    s += " No feasible design: the least infeasible one is shown.";
  }
  return s;
}

}  // namespace rackopt::study_report
