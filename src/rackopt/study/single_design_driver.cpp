#include "rackopt/core/interrupt.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/study/reliability_options.hpp"
#include "rackopt/study/study_kind_drivers.hpp"

namespace rackopt::study {

StudyStatus drive_single_design(const KindDriverContext& ctx, const std::optional<Obtained>& start) {
  const StudySpec& spec = ctx.spec;
  StudyProblem& base = ctx.base;
  EvaluationLedger& ledger = ctx.ledger;
  StudyResult& result = ledger.result();
  const RunOptions& options = ctx.options;
  StudyStatus status = StudyStatus::kOk;
  if (!start) return StudyStatus::kStopped;
  result.best = ledger.to_result(start->design, "start");
  status = start->design.evaluation.ok() ? StudyStatus::kOk : StudyStatus::kAllFailed;
  if (spec.kind == StudyKind::kReliability && start->design.evaluation.ok() && ledger.stop_requested()) {
    status = StudyStatus::kStopped;  // the reliability analysis did not run
  } else if (spec.kind == StudyKind::kReliability && start->design.evaluation.ok()) {
    try {
      const Drive design = base.drive_at(start->design.x);
      WearReliabilityOptions wo = study_reliability_options(spec, design, ledger.threads());
      wo.stop = options.stop;  // thread-safe (polled by the sampling workers and the fits)
      // The samples over the executor's workers (the ranks of an MPI job);
      // empty for threads, which the analysis uses itself.
      wo.sample_executor = ledger.executor().reliability_samples(base, start->design.x);
      // Everything recorded is committed before the long analysis, which is
      // not recorded: a stop abandons it (its samples so far are no result)
      // and the study reports "stopped"; --resume redoes it.
      ledger.store().flush();
      result.reliability = std::make_shared<const WearReliabilityResult>(run_wear_reliability(design, wo));
    } catch (const Interrupted&) {
      ledger.mark_stopped();  // the study stopped; --resume redoes the Monte Carlo
      status = StudyStatus::kStopped;
      result.stopped_during = "the reliability analysis of the design (its samples so far are no result: "
                              "--resume runs the analysis again)";
    } catch (const std::runtime_error& e) {  // DesignError or InputError: the summary is still written
      status = StudyStatus::kAllFailed;
      result.solver_message = std::string("wear reliability: ") + e.what();
    }
  }
  return status;
}

}  // namespace rackopt::study
