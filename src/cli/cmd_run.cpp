// rackopt run: a study file end to end. Loads and checks the study, takes
// the output folder's lock, runs the study with the evaluation store there,
// shows progress, survives Ctrl-C (the first one stops cleanly and the
// results so far are written; --resume continues; core/interrupt.hpp), then
// writes the report.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "cli.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/study_report/run_summary_text.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#ifdef RACKOPT_WITH_MPI
#include "rackopt/mpi/mpi_job.hpp"
#endif

namespace rackopt::cli {
int cmd_run(const Args& a) {
  if (a.ranks > 0) return cmd_run_ranks(a);  // mpirun's job, or --ranks 1 back here
  const study::StudySpec spec = studyfile::load_study_file(a.file, a.overrides);
  const std::string out_dir =
      a.out_dir.empty() ? study::default_out_dir(spec) : a.out_dir;

  if (spec.verify_fe) {  // `verify: fe` without ccx or Gmsh: refused before the study runs
    (void)fe::find_ccx();
    (void)fe::gmsh_api();
  }
  const FolderLock lock(out_dir);  // held until the report is written
  report_stale_temporaries(lock);

  const std::string objective = spec.objectives.empty() ? std::string() : spec.objectives[0].label;
  // Optimizers and Pareto drivers usually end before their evaluation budget.
  const bool budget_is_bound = spec.kind == study::StudyKind::kOptimize || spec.kind == study::StudyKind::kPareto;
  auto bar = std::make_unique<ProgressBar>(0, "evaluations", a.progress);
  study::RunOptions opt;
  opt.out_dir = out_dir;
  opt.resume = a.resume;
  opt.threads = a.threads > 0 ? static_cast<unsigned>(a.threads) : 0u;
#ifdef RACKOPT_WITH_MPI
  // Under mpirun every rank computes its share of each batch, with
  // --threads threads (default 1: the ranks already fill the cores).
  if (mpi::MpiJob* job = mpi::MpiJob::current(); job && job->size() > 1) {
    opt.threads = a.threads > 0 ? static_cast<unsigned>(a.threads) : 1u;
    opt.executor = job->executor(opt.threads);
  }
#endif
  opt.stop = [] { return stop_requested(); };
  opt.progress = [&](const study::Progress& p) {
    std::string detail;
    if (!objective.empty()) {
      detail = "best " + (p.best ? study_report::metric_display(objective, *p.best) : std::string("none feasible yet"));
    }
    if (p.failed > 0) detail += (detail.empty() ? "" : ", ") + std::to_string(p.failed) + " failed";
    if (!p.phase.empty()) detail += (detail.empty() ? "" : ", ") + p.phase;
    bar->update(static_cast<long>(p.done), static_cast<long>(p.budget), detail, budget_is_bound);
  };

  const study::StudyResult result = study::run_study(spec, opt);
  bar->finish(result.status != study::StudyStatus::kStopped);  // finish the progress line before anything else is printed
  const study_report::StudyReport rep = study_report::write_study_report(spec, result, out_dir);

  const std::string text = study_report::study_summary_text(spec, result, rep, out_dir);
  set_immediate_stop_output("");  // our own output follows
  if (a.json) {
    std::cerr << text;
    std::cout << rep.summary_json << "\n";
  } else {
    std::cout << text;
  }
  // Stopped, or interrupted after the last evaluation (while the report was
  // written): either way the run was interrupted.
  if (result.status == study::StudyStatus::kStopped || stop_requested()) return kInterruptedExit;
  if (result.status == study::StudyStatus::kAllFailed) return kRunFailed;
  if (spec.verify_fe && !result.fe_verification && result.best_drive) return kRunFailed;  // asked for, failed
  return kOk;
}

}  // namespace rackopt::cli
