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

std::string drive_optimize(const KindDriverContext& ctx) {
  StudyProblem& base = ctx.base;
  EvaluationLedger& ledger = ctx.ledger;
  StudyResult& result = ledger.result();
  const solvers::SolverSettings& solver = ctx.solver;
  const std::size_t combos = base.num_combinations();
  std::string status;
  std::vector<std::string> statuses(combos);
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
      statuses[c] = "converged";
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
    status = "stopped";
  } else if (!ledger.best()) {
    status = ledger.any_ok() ? "no_feasible_point" : "all_failed";
  } else {
    status = statuses[std::min(ledger.best_tag(), combos - 1)];
    if (status == "no_feasible_point" || status == "all_failed" || status.empty()) status = "converged";
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
