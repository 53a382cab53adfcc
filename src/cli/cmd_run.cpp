// rackopt run: a study file end to end. Loads and checks the study, takes
// the output folder's lock, runs the study with the evaluation store there,
// shows progress, survives Ctrl-C (the first one stops cleanly and the
// results so far are written; --resume continues; core/interrupt.hpp), then
// writes the report.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>


#include "cli.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/fe/fe_comparison_report.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/report/study_report.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace rackopt::cli {
namespace {

// "railway sizing" -> "railway_sizing": a folder name without surprises.
std::string folder_name(const std::string& name) {
  std::string out;
  for (char c : name) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    out += plain ? c : '_';
  }
  if (out.empty() || out == "." || out == "..") out = "study";
  return out;
}

void design_lines(std::ostringstream& o, const study::StudySpec& spec, const study::DesignResult& d) {
  for (std::size_t i = 0; i < spec.variables.size() && i < d.x.size(); ++i) {
    o << "    " << spec.variables[i].key << " = " << study::variable_display(spec.variables[i], d.x[i]) << "\n";
  }
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
    const bool ok = i < d.metric_ok.size() && d.metric_ok[i] && i < d.metric_values.size();
    o << "    " << d.metric_labels[i] << ": "
      << (ok ? study::metric_display(d.metric_labels[i], d.metric_values[i]) : std::string("failed")) << "\n";
  }
  if (!d.feasible && std::isfinite(d.max_violation)) {
    o << "    max constraint violation (normalized): " << d.max_violation << "\n";
  }
  if (!d.message.empty()) o << "    " << d.message << "\n";
}

std::string text_for_people(const study::StudySpec& spec, const study::StudyResult& r,
                            const study::StudyReport& rep, const std::string& out_dir) {
  std::ostringstream o;
  o << "study " << spec.name << " (" << study::kind_name(spec.kind) << "): " << r.status << "\n";
  o << "  " << study::status_message(spec, r) << "\n";
  if (spec.kind == study::StudyKind::kPareto && !r.front.empty()) {
    o << "  Pareto front, " << r.front.size() << " points:\n";
    for (std::size_t k = 0; k < r.front.size(); ++k) {
      const bool chosen = r.chosen && *r.chosen == k;
      o << (chosen ? "  * " : "    ") << k << ":";
      for (std::size_t i = 0; i < spec.objectives.size() && i < r.front[k].objectives.size(); ++i) {
        o << "  " << spec.objectives[i].label << " "
          << study::metric_display(spec.objectives[i].label, r.front[k].objectives[i]);
      }
      o << "\n";
    }
    if (r.chosen && *r.chosen < r.front.size()) {
      o << "  chosen design (*):\n";
      design_lines(o, spec, r.front[*r.chosen]);
    }
  } else if (r.best) {
    const bool single = spec.kind == study::StudyKind::kEvaluate || spec.kind == study::StudyKind::kReliability;
    o << (single ? "  design" : "  best design") << (r.best->label.empty() ? "" : " (" + r.best->label + ")")
      << ":\n";
    design_lines(o, spec, *r.best);
  }
  if (r.reliability && r.best_drive) o << rackopt::wear_summary(*r.best_drive, *r.reliability);
  if (r.fe_verification) {
    o << "  FE verification of the " << (spec.kind == study::StudyKind::kPareto ? "chosen" : "best") << " design:\n"
      << fe::fe_comparison_summary(*r.fe_verification);
  } else if (spec.verify_fe) {
    o << "  FE verification: " << r.fe_verification_error << "\n";
  }
  if (spec.kind == study::StudyKind::kSweep && !r.sweep_points.empty()) {
    // The response range of every metric over the points that computed it:
    // the first thing one wants to know of a sweep.
    const auto& labels = r.sweep_points.front().metric_labels;
    o << "  metric ranges over the sweep:\n";
    for (std::size_t i = 0; i < labels.size(); ++i) {
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& p : r.sweep_points) {
        if (i >= p.metric_ok.size() || !p.metric_ok[i]) continue;
        lo = std::min(lo, p.metric_values[i]);
        hi = std::max(hi, p.metric_values[i]);
      }
      o << "    " << labels[i] << ": ";
      if (lo > hi) {
        o << "failed everywhere\n";
      } else {
        o << study::metric_display(labels[i], lo) << " .. " << study::metric_display(labels[i], hi) << "\n";
      }
    }
  }
  if (r.least_infeasible) {
    o << "  NO FEASIBLE DESIGN. Least infeasible design ("
      << r.least_infeasible->label << "):\n";
    design_lines(o, spec, *r.least_infeasible);
  }
  o << "  evaluations: " << r.evaluations << " (" << r.failed_evaluations << " failed, " << r.reused_evaluations
    << " from the store), " << r.seconds << " s\n";
  // Model warnings can be many near-copies (one per design): the first few
  // here, all of them in summary.json and report.md.
  const std::size_t shown = std::min<std::size_t>(rep.warnings.size(), 5);
  for (std::size_t i = 0; i < shown; ++i) o << "  warning: " << rep.warnings[i] << "\n";
  if (rep.warnings.size() > shown) {
    o << "  ... and " << rep.warnings.size() - shown << " more warnings (summary.json, report.md)\n";
  }
  const std::string md = rep.files.get("report_md");
  o << "  wrote " << out_dir << "/ (" << (md.empty() ? std::string("summary.json") : md) << ")\n";
  if (r.status == "stopped") o << "  continue with: rackopt run " << spec.file << " --out " << out_dir << " --resume\n";
  return o.str();
}

}  // namespace

int cmd_run(const Args& a) {
  namespace fs = std::filesystem;
  const study::StudySpec spec = study::load_study_file(a.file, a.overrides);
  const std::string out_dir =
      a.out_dir.empty() ? (fs::path("out") / folder_name(spec.name)).string() : a.out_dir;

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
  opt.stop = [] { return stop_requested(); };
  opt.progress = [&](const study::Progress& p) {
    std::string detail;
    if (!objective.empty()) {
      detail = "best " + (p.best ? study::metric_display(objective, *p.best) : std::string("none feasible yet"));
    }
    if (p.failed > 0) detail += (detail.empty() ? "" : ", ") + std::to_string(p.failed) + " failed";
    if (!p.phase.empty()) detail += (detail.empty() ? "" : ", ") + p.phase;
    bar->update(static_cast<long>(p.done), static_cast<long>(p.budget), detail, budget_is_bound);
  };

  const study::StudyResult result = study::run_study(spec, opt);
  bar->finish(result.status != "stopped");  // finish the progress line before anything else is printed
  const study::StudyReport rep = study::write_study_report(spec, result, out_dir);

  const std::string text = text_for_people(spec, result, rep, out_dir);
  set_immediate_stop_output("");  // our own output follows
  if (a.json) {
    std::cerr << text;
    std::cout << rep.summary_json << "\n";
  } else {
    std::cout << text;
  }
  // Stopped, or interrupted after the last evaluation (while the report was
  // written): either way the run was interrupted.
  if (result.status == "stopped" || stop_requested()) return kInterruptedExit;
  if (result.status == "all_failed") return kRunFailed;
  if (spec.verify_fe && !result.fe_verification && result.best_drive) return kRunFailed;  // asked for, failed
  return kOk;
}

}  // namespace rackopt::cli
