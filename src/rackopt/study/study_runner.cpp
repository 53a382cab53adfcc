#include "rackopt/study/study_runner.hpp"

#include <chrono>
#include <exception>
#include <filesystem>
#include <memory>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/study/best_design_curve.hpp"
#include "rackopt/study/evaluation_ledger.hpp"
#include "rackopt/study/fe_verification.hpp"
#include "rackopt/study/fidelity_settings.hpp"
#include "rackopt/study/study_kind_drivers.hpp"
#include "rackopt/study/study_kind_rules.hpp"
#include "rackopt/study/study_problem.hpp"

namespace rackopt::study {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

StudyResult run_study(const StudySpec& spec, const RunOptions& options) {
  const auto t0 = Clock::now();

  // ---- set-up checks: everything that can be refused before a file is written
  check_count(options.threads, kThreadsLimit, "threads");
  StudyProblem base(spec);
  if (const auto broken = check_study_kind_rules(spec))
    throw study_error(spec, study_rule_key(*broken, spec), broken->message);
  {
    // The start design must be a drive the loader accepts, and the metrics
    // must be configured (wear section, duty, allowables): set-up errors.
    std::optional<Drive> start_drive;
    try {
      start_drive.emplace(base.drive_at(base.start_design()));
    } catch (const DesignError&) {
      // An impossible start design is a failed evaluation, not a set-up error.
    }
    if (start_drive) metrics::check_metric_requests(*start_drive, base.metric_requests(), spec.metric_options);
  }
  solvers::SolverSettings solver = spec.solver;
  solver.seed = spec.seed;
  std::vector<std::vector<double>> points;
  if (spec.kind == StudyKind::kSweep) points = sweep_points(spec);

  // ---- store
  std::filesystem::create_directories(options.out_dir.empty() ? "." : options.out_dir);
  const std::filesystem::path out = options.out_dir.empty() ? std::filesystem::path(".") : std::filesystem::path(options.out_dir);
  const std::string db_path = (out / "evaluations.sqlite").string();
  const std::string csv_path = (out / "evaluations.csv").string();
  EvaluationLedger ledger(spec, options, base);
  ledger.open_store(db_path);
  StudyResult& result = ledger.result();

  // ---- the start design: the scale of automatic objectives, and the design
  // of evaluate/reliability. A sweep without automatic scales skips it.
  bool needs_start = spec.kind != StudyKind::kSweep;
  for (const auto& o : spec.objectives) needs_start = needs_start || o.scale <= 0;
  // Runs: one per discrete combination, or one over all of them when the
  // solver searches the discrete variables as integers.
  const bool integers = searches_discrete_as_integers(spec);
  const std::size_t runs = integers ? 1 : base.num_combinations();
  const bool solves = integers || base.dimension() > 0;
  std::size_t budget = needs_start ? 1 : 0;
  switch (spec.kind) {
    case StudyKind::kSweep: budget += points.size(); break;
    case StudyKind::kOptimize: budget += runs * (solves ? spec.solver.max_evaluations : 1); break;
    case StudyKind::kPareto:
      budget += runs * (solves ? spec.pareto.points * spec.solver.max_evaluations : 1);
      break;
    default: break;
  }
  ledger.set_budget(budget);

  std::optional<Obtained> start;
  if (needs_start && !ledger.stop_requested()) {
    ledger.set_phase("start");
    const std::vector<double> x = base.start_design();
    // The scales come from the metric values only, so a rebuilt record and a
    // fresh evaluation give the same scales.
    start = ledger.lookup(x);
    try {
      if (!start) start = Obtained{base.evaluate_design(x, ledger.threads()), Origin::kNew, 0};
    } catch (const Interrupted&) {
      // Ctrl-C inside one long evaluation (a Monte Carlo life at R): nothing
      // of it is recorded; the study stops, its report is written (a stopped
      // study with what --resume finds) and --resume evaluates it again.
      ledger.mark_stopped();
    }
  }
  if (start) {
    base.set_objective_scales_from(start->design);
    start->design.evaluation = base.map_metrics(start->design.metric_values, start->design.metric_ok,
                                                start->design.evaluation.message);
    ledger.settle(*start, "start", false, spec.kind != StudyKind::kSweep);
  }

  const KindDriverContext context{spec, options, base, ledger, solver};
  StudyStatus status = StudyStatus::kOk;
  switch (spec.kind) {
    case StudyKind::kEvaluate:
    case StudyKind::kReliability: status = drive_single_design(context, start); break;
    case StudyKind::kSweep: status = drive_sweep(context, points); break;
    case StudyKind::kOptimize: status = drive_optimize(context); break;
    case StudyKind::kPareto: status = drive_pareto(context); break;
  }

  if (spec.kind != StudyKind::kSweep && !result.best && ledger.least_infeasible())
    result.least_infeasible = ledger.least_infeasible();
  if (result.best && result.best->ok) {
    try {
      result.best_drive = std::make_shared<const Drive>(base.drive_at(result.best->x));
    } catch (const std::exception&) {
      // An ok design has a drive; nothing to plot otherwise.
    }
  }
  result.status = status;
  result.warnings = ledger.warnings();
  result.warning_groups = ledger.warning_tally().groups();
  result.warning_kinds_dropped = ledger.warning_tally().dropped();
  try {
    result.fidelity = fidelity_settings(base.drive_at(result.best ? result.best->x : base.start_design()), spec);
  } catch (const std::exception&) {
    // A design the loader refuses has no settings to show; the report says none.
  }
  result.database_path = db_path;
  result.evaluations_csv_path = csv_path;

  record::EvaluationStore& store = ledger.store();
  store.set_meta("status", ledger.stopped() ? "stopped" : "finished");
  store.set_meta("result_status", std::string(to_string(status)));
  record::write_evaluations_csv(store, base.variable_keys(), base.metric_labels(), csv_path);
  // After the record is complete: the curve is for the report only.
  attach_best_design_curve(spec, result);
  verify_best_design_by_fe(spec, options, result);
  if (result.status == StudyStatus::kStopped) store.set_meta("status", "stopped");  // stopped during the FE
  result.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return result;
}

}  // namespace rackopt::study
