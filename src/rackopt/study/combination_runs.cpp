#include "rackopt/study/combination_runs.hpp"

#include "rackopt/core/interrupt.hpp"
#include "rackopt/study/study_kind_rules.hpp"

namespace rackopt::study {

std::vector<StudyProblem> solver_views(const StudyProblem& base) {
  if (searches_discrete_as_integers(base.spec())) return {base.with_discrete_as_integers()};
  std::vector<StudyProblem> views;
  for (std::size_t c = 0; c < base.num_combinations(); ++c) views.push_back(base.for_combination(c));
  return views;
}

CombinationRuns::CombinationRuns(EvaluationLedger& ledger, const StudyProblem& base, std::vector<StudyProblem> views,
                                 const std::function<std::string(const StudyProblem&)>& label)
    : ledger_(ledger), base_(base), views_(std::move(views)) {
  for (const StudyProblem& v : views_) {
    recorded_.push_back(std::make_unique<RecordedProblem>(ledger, v));
    recorded_.back()->set_label(label(v));
  }
}

void CombinationRuns::run(const std::function<void(std::size_t, const solvers::Problem&)>& run) {
  try {
    solvers::run_in_lockstep(
        views_.size(), kCombinationRunsAtOnce,
        [&](std::size_t c, solvers::LockstepChannel& channel) {
          const solvers::LockstepProblem problem(views_[c], channel);
          run(c, problem);
        },
        [&](const std::vector<solvers::LockstepRequest>& round) { return serve(round); });
  } catch (const Interrupted&) {
    // Ctrl-C inside an evaluation (a Monte Carlo life at R): that batch is
    // abandoned (--resume evaluates it again); what the runs had evaluated
    // before it is recorded, and the study ends as stopped with its report.
    ledger_.mark_stopped();
    for (const auto& r : recorded_) r->settle_pending();
  }
}

std::vector<std::vector<solvers::Evaluation>> CombinationRuns::serve(const std::vector<solvers::LockstepRequest>& round) {
  // What each run evaluated before and has not reported is recorded first,
  // as a run alone would (RecordedProblem::evaluate_batch), then the
  // round's designs in one batch, run by run.
  for (const solvers::LockstepRequest& r : round) recorded_[r.job]->settle_pending();
  std::vector<std::vector<double>> xs;
  for (const solvers::LockstepRequest& r : round)
    for (const auto& u : *r.us) xs.push_back(views_[r.job].to_design(u));
  std::vector<Obtained> got = ledger_.obtain_batch(base_, xs);
  std::vector<std::vector<solvers::Evaluation>> replies;
  std::size_t next = 0;
  for (const solvers::LockstepRequest& r : round) {
    std::vector<Obtained> mine;
    for (std::size_t k = 0; k < r.us->size(); ++k) mine.push_back(std::move(got[next++]));
    replies.push_back(recorded_[r.job]->accept(*r.us, std::move(mine)));
  }
  return replies;
}

}  // namespace rackopt::study
