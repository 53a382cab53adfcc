#include <algorithm>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/study/combination_runs.hpp"
#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study/wear_discretization_check.hpp"
#include "rackopt/study/recorded_problem.hpp"
#include "rackopt/study/study_kind_drivers.hpp"
#include "rackopt/study/study_kind_rules.hpp"

namespace rackopt::study {

std::string combination_phase(const StudyProblem& p) {
  if (p.num_combinations() <= 1 || p.discrete_as_integers()) return "";
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
  // One run per combination, the runs in lockstep (each round's designs of
  // every combination go to the executor as one batch), or one run over
  // them all when the algorithm searches the discrete variables as
  // integers. Either way each design is ranked within its own combination.
  const bool integers = searches_discrete_as_integers(ctx.spec);
  ledger.set_tagger([&base](std::span<const double> x) { return base.combination_of(x); });
  auto label = [](const StudyProblem& p) {
    const std::string phase = combination_phase(p);
    return phase.empty() ? std::string("optimize") : phase;
  };
  CombinationRuns runs(ledger, base, solver_views(base), label);
  std::vector<std::optional<solvers::SolverStatus>> statuses(runs.size());  // nullopt: not run (stopped)
  std::vector<std::string> run_messages(runs.size());
  runs.run([&](std::size_t c, const solvers::Problem& problem) {
    if (ledger.stop_requested()) return;
    const StudyProblem& p = runs.view(c);
    const RecordedProblem& rp = runs.recorded(c);
    ledger.set_phase(label(p));
    if (p.dimension() == 0) {
      // Every variable discrete: the enumeration is the optimization.
      problem.evaluate_batch({std::vector<double>{}});
      rp.settle_pending();
      statuses[c] = solvers::SolverStatus::kConverged;
      return;
    }
    solvers::SolverCallbacks cb;
    cb.observer = [&](const solvers::EvaluationRecord& rec) {
      ledger.set_phase(label(p));
      rp.observed(rec, "");
    };
    cb.stop = [&ledger] { return ledger.stop_requested(); };
    const solvers::SolverResult sr = solvers::minimize(problem, p.start_unit(), solver, cb);
    rp.settle_pending();
    statuses[c] = sr.status;
    const std::string phase = combination_phase(p);
    run_messages[c] = (phase.empty() ? "" : phase + ": ") + sr.solver_message;
  });
  ledger.set_tagger({});
  std::string messages;
  for (const std::string& m : run_messages) {
    if (m.empty()) continue;
    if (!messages.empty()) messages += "; ";
    messages += m;
  }
  // The run a combination's designs came from.
  auto run_of = [&](std::size_t combination) { return integers ? 0 : std::min(combination, runs.size() - 1); };
  result.solver_message = messages;
  if (ledger.stopped()) {
    status = StudyStatus::kStopped;
  } else if (!ledger.best()) {
    status = ledger.any_ok() ? StudyStatus::kNoFeasiblePoint : StudyStatus::kAllFailed;
  } else {
    // The best design's combination tells how the search ended; a best design
    // found although its own solve saw none feasible (our re-check) converged.
    const auto& own = statuses[run_of(ledger.best_tag())];
    status = own ? study_status(*own) : StudyStatus::kConverged;
    if (status == StudyStatus::kNoFeasiblePoint || status == StudyStatus::kAllFailed) status = StudyStatus::kConverged;
  }
  result.best = ledger.best();
  if (combos > 1) {
    // Searched as integers: the combinations the search reached (there may
    // be too many to list them all), each with the one run's status.
    std::vector<std::size_t> listed;
    if (integers) {
      listed = ledger.tags_ranked();
    } else {
      for (std::size_t c = 0; c < combos; ++c) listed.push_back(c);
    }
    for (std::size_t c : listed) {
      CombinationOutcome co;
      co.label = base.for_combination(c).combination_label();
      co.status = statuses[run_of(c)];
      co.best = ledger.best_of_tag(c);
      if (!co.best) co.least_infeasible = ledger.least_infeasible_of_tag(c);
      result.per_combination.push_back(std::move(co));
    }
  }
  if (result.best && !ledger.stopped()) {
    try {
      result.explanation = explain_optimum(base, result.best->x, ledger.threads());
      check_wear_discretization(base, result.best->x, *result.explanation, ledger.threads());
    } catch (const Interrupted&) {
      // Ctrl-C while the optimum's neighbours (or its refinement) were
      // evaluated: every design is recorded; the report says stopped,
      // without the explanation (or without the refinement's error).
      ledger.mark_stopped();
      status = StudyStatus::kStopped;
    }
  }
  return status;
}

}  // namespace rackopt::study
