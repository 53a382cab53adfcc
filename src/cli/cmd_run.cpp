// rackopt run: a study file end to end (issue 4). Loads and checks the study,
// runs it with the evaluation store in the output folder, shows progress,
// survives Ctrl-C (the first one stops cleanly and the results so far are
// written; --resume continues), then writes the report.
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <unistd.h>

#include "cli.hpp"
#include "rackopt/core/progress_bar.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/report/study_report.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace rackopt::cli {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_interrupts{0};

// First SIGINT/SIGTERM: ask the runner to stop between evaluations (it
// records what it has, the report is written). A second one: the default
// action, at once; the store loses nothing committed either way.
extern "C" void on_interrupt(int sig) {
  if (g_interrupts.fetch_add(1) >= 1) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_stop.store(true);
  static const char msg[] =
      "\nrackopt: stopping after the current evaluation (Ctrl-C again to quit at once)...\n";
  const ssize_t ignored = ::write(STDERR_FILENO, msg, sizeof msg - 1);
  (void)ignored;
}

// Installs the handlers for the life of the object, restores the old ones after.
class InterruptGuard {
 public:
  InterruptGuard() {
    g_stop.store(false);
    g_interrupts.store(0);
    old_int_ = std::signal(SIGINT, on_interrupt);
    old_term_ = std::signal(SIGTERM, on_interrupt);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  void (*old_int_)(int) = SIG_DFL;
  void (*old_term_)(int) = SIG_DFL;
};

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

  const std::string objective = spec.objectives.empty() ? std::string() : spec.objectives[0].label;
  auto bar = std::make_unique<ProgressBar>(0, "evaluations", a.progress);
  study::RunOptions opt;
  opt.out_dir = out_dir;
  opt.resume = a.resume;
  opt.threads = a.threads > 0 ? static_cast<unsigned>(a.threads) : 0u;
  opt.stop = [] { return g_stop.load(); };
  opt.progress = [&](const study::Progress& p) {
    std::string detail;
    if (!objective.empty()) {
      detail = "best " + (p.best ? study::metric_display(objective, *p.best) : std::string("none feasible yet"));
    }
    if (p.failed > 0) detail += (detail.empty() ? "" : ", ") + std::to_string(p.failed) + " failed";
    if (!p.phase.empty()) detail += (detail.empty() ? "" : ", ") + p.phase;
    bar->update(static_cast<long>(p.done), static_cast<long>(p.budget), detail);
  };

  InterruptGuard guard;
  const study::StudyResult result = study::run_study(spec, opt);
  bar.reset();  // finish the progress line before anything else is printed
  const study::StudyReport rep = study::write_study_report(spec, result, out_dir);

  const std::string text = text_for_people(spec, result, rep, out_dir);
  if (a.json) {
    std::cerr << text;
    std::cout << rep.summary_json << "\n";
  } else {
    std::cout << text;
  }
  if (result.status == "stopped") return 130;  // 128 + SIGINT, as a shell reports an interrupted program
  if (result.status == "all_failed") return kRunFailed;
  return kOk;
}

}  // namespace rackopt::cli
