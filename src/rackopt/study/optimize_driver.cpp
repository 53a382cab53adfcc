#include <algorithm>

#include "rackopt/study/combination_runs.hpp"
#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study/recorded_problem.hpp"
#include "rackopt/study/study_kind_drivers.hpp"
#include "rackopt/study/study_kind_rules.hpp"

namespace rackopt::study {

std::string combination_phase(const StudyProblem& p) {
  if (p.num_combinations() <= 1) return "";
  return "combination " + std::to_string(p.combination() + 1) + "/" + std::to_string(p.num_combinations()) + " (" +
         p.combination_label() + ")";
}

namespace {

// One run over every combination: the discrete variables are whole-valued
// solver variables. Each design is ranked within its own combination, so
// the per-combination table shows the best the search visited in each.
solvers::SolverStatus optimize_with_integers(const KindDriverContext& ctx, std::string& message) {
  EvaluationLedger& ledger = ctx.ledger;
  const StudyProblem p = ctx.base.with_discrete_as_integers();
  ledger.set_phase("optimize");
  ledger.set_tagger([&p](std::span<const double> x) { return p.combination_of(x); });
  RecordedProblem rp(ledger, p);
  rp.set_label("optimize");
  solvers::SolverCallbacks cb;
  cb.observer = [&rp](const solvers::EvaluationRecord& rec) { rp.observed(rec, ""); };
  cb.stop = [&ledger] { return ledger.stop_requested(); };
  const solvers::SolverResult sr = solvers::minimize(rp, p.start_unit(), ctx.solver, cb);
  rp.settle_pending();
  ledger.set_tagger({});
  message = sr.solver_message;
  return sr.status;
}

}  // namespace

StudyStatus drive_optimize(const KindDriverContext& ctx) {
  StudyProblem& base = ctx.base;
  EvaluationLedger& ledger = ctx.ledger;
  StudyResult& result = ledger.result();
  const solvers::SolverSettings& solver = ctx.solver;
  const std::size_t combos = base.num_combinations();
  StudyStatus status = StudyStatus::kConverged;
  std::vector<std::optional<solvers::SolverStatus>> statuses(combos);  // nullopt: not run (stopped)
  std::string messages;
  const bool integers = searches_discrete_as_integers(ctx.spec);
  std::optional<solvers::SolverStatus> joint;  // the one run's status when searched as integers
  if (integers && !ledger.stop_requested()) joint = optimize_with_integers(ctx, messages);
  if (!integers) {
    // One run per combination, the runs in lockstep: each round's designs of
    // every combination go to the executor as one batch.
    ledger.set_tagger([&base](std::span<const double> x) { return base.combination_of(x); });
    auto label = [](const StudyProblem& p) {
      const std::string phase = combination_phase(p);
      return phase.empty() ? std::string("optimize") : phase;
    };
    CombinationRuns runs(ledger, base, solver_views(base), label);
    std::vector<std::string> run_messages(combos);
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
    for (const std::string& m : run_messages) {
      if (m.empty()) continue;
      if (!messages.empty()) messages += "; ";
      messages += m;
    }
  }
  result.solver_message = messages;
  if (ledger.stopped()) {
    status = StudyStatus::kStopped;
  } else if (!ledger.best()) {
    status = ledger.any_ok() ? StudyStatus::kNoFeasiblePoint : StudyStatus::kAllFailed;
  } else {
    // The best design's combination tells how the search ended; a best design
    // found although its own solve saw none feasible (our re-check) converged.
    const auto& own = integers ? joint : statuses[std::min(ledger.best_tag(), combos - 1)];
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
      co.status = integers ? joint : statuses[c];
      co.best = ledger.best_of_tag(c);
      if (!co.best) co.least_infeasible = ledger.least_infeasible_of_tag(c);
      result.per_combination.push_back(std::move(co));
    }
  }
  if (result.best && !ledger.stopped()) result.explanation = explain_optimum(base, result.best->x, ledger.threads());
  return status;
}

}  // namespace rackopt::study
