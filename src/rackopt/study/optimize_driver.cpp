#include <algorithm>

#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study/recorded_problem.hpp"
#include "rackopt/study/study_kind_drivers.hpp"

namespace rackopt::study {

std::string combination_phase(const StudyProblem& p) {
  if (p.num_combinations() <= 1) return "";
  return "combination " + std::to_string(p.combination() + 1) + "/" + std::to_string(p.num_combinations()) + " (" +
         p.combination_label() + ")";
}

StudyStatus drive_optimize(const KindDriverContext& ctx) {
  StudyProblem& base = ctx.base;
  EvaluationLedger& ledger = ctx.ledger;
  StudyResult& result = ledger.result();
  const solvers::SolverSettings& solver = ctx.solver;
  const std::size_t combos = base.num_combinations();
  StudyStatus status = StudyStatus::kConverged;
  std::vector<std::optional<solvers::SolverStatus>> statuses(combos);  // nullopt: not run (stopped)
  std::string messages;
  for (std::size_t c = 0; c < combos; ++c) {
    if (ledger.stop_requested()) break;
    const StudyProblem p = base.for_combination(c);
    const std::string phase = combination_phase(p);
    ledger.set_phase(phase.empty() ? "optimize" : phase);
    ledger.set_tag(c);
    RecordedProblem rp(ledger, p);
    rp.set_label(phase.empty() ? "optimize" : phase);
    if (p.dimension() == 0) {
      // Every variable discrete: the enumeration is the optimization.
      const std::vector<double> x = p.to_design({});
      ledger.settle(ledger.obtain(p, x), phase.empty() ? "optimize" : phase, false);
      statuses[c] = solvers::SolverStatus::kConverged;
      continue;
    }
    solvers::SolverCallbacks cb;
    cb.observer = [&rp](const solvers::EvaluationRecord& rec) { rp.observed(rec, ""); };
    cb.stop = [&ledger] { return ledger.stop_requested(); };
    const solvers::SolverResult sr = solvers::minimize(rp, p.start_unit(), solver, cb);
    rp.settle_pending();
    statuses[c] = sr.status;
    if (!messages.empty()) messages += "; ";
    messages += (phase.empty() ? "" : phase + ": ") + sr.solver_message;
  }
  result.solver_message = messages;
  if (ledger.stopped()) {
    status = StudyStatus::kStopped;
  } else if (!ledger.best()) {
    status = ledger.any_ok() ? StudyStatus::kNoFeasiblePoint : StudyStatus::kAllFailed;
  } else {
    // The best design's combination tells how the search ended; a best design
    // found although its own solve saw none feasible (our re-check) converged.
    const auto& own = statuses[std::min(ledger.best_tag(), combos - 1)];
    status = own ? study_status(*own) : StudyStatus::kConverged;
    if (status == StudyStatus::kNoFeasiblePoint || status == StudyStatus::kAllFailed) status = StudyStatus::kConverged;
  }
  result.best = ledger.best();
  if (combos > 1) {
    for (std::size_t c = 0; c < combos; ++c) {
      CombinationOutcome co;
      co.label = base.for_combination(c).combination_label();
      co.status = statuses[c];
      co.best = ledger.best_of_tag(c);
      if (!co.best) co.least_infeasible = ledger.least_infeasible_of_tag(c);
      result.per_combination.push_back(std::move(co));
    }
  }
  if (result.best && !ledger.stopped()) result.explanation = explain_optimum(base, result.best->x, ledger.threads());
  return status;
}

}  // namespace rackopt::study
