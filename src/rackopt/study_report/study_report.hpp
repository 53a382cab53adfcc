// What a finished (or stopped) study leaves in its output folder besides the
// evaluation store: summary.json, CSV tables, gnuplot scripts, PNGs and
// SVGs, report.md linking them, and report.html (the same report with the
// plots inside, report_html.hpp). docs/output.md ("Study results") lists every file
// and column. The run itself is study/study_runner.hpp; this module only
// presents a StudyResult.
//
// Example:
//   StudyResult r = run_study(spec, options);
//   StudyReport rep = write_study_report(spec, r, options.out_dir);
//   std::cout << rep.summary_json << "\n";         // what `rackopt run --json` prints
//   for (auto& w : rep.warnings) std::cerr << "warning: " << w << "\n";
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// Files of a report by role, in the order written. Roles: "summary_json",
// "report_md", "report_html", "best_csv", "front_csv", "sweep_csv", "history_csv",
// "stiffness_csv", "pareto_png", "history_png", "stiffness_png",
// "sweep_png", the wear roles of `rackopt wear` ("wear_profile_csv",
// "life_samples_csv", "reliability_csv", "life_histogram_csv",
// "wear_profile_png", "life_histogram_png", "reliability_png"), `verify: fe`'s
// "fe_csv" and "fe_png" (study_report/fe_verification_report.hpp), and the
// runner's "evaluations_csv" and "database". gnuplot scripts (*.gp) and the
// SVGs that report.html inlines are written next to each plot but not
// listed here.
struct ReportFiles {
  std::vector<std::pair<std::string, std::string>> entries;  // role, path

  void add(const std::string& role, const std::string& path) { entries.emplace_back(role, path); }
  // The path of `role`, "" when absent.
  std::string get(const std::string& role) const;
};

struct ReportTimings {
  double run_seconds = 0;     // StudyResult::seconds (wall time of this run)
  double report_seconds = 0;  // tables, plots and report.md
};

struct StudyReport {
  ReportFiles files;                  // every file listed in summary.json (all exist)
  std::vector<std::string> written;   // every path written by the report, scripts included
  std::vector<std::string> warnings;  // the result's warnings, then the report's (missing gnuplot, ...)
  std::string summary_json;           // the content of summary.json, one line
};

// Writes the report of `result` into `out_dir` (created if missing); every
// file atomically (write_file_atomic; each plot's PNG and, with the report,
// its SVG, all plots from one gnuplot run: PlotBatch). Which files depends on
// the kind (docs/output.md); plots only when spec.output.plots, report.md,
// report.html and the SVGs only when
// spec.output.report, the stiffness curve only when
// spec.output.stiffness_curve and the runner computed result.best_curve
// (study/best_design_curve.hpp): the report runs no model. A plot gnuplot
// cannot draw, or a stiffness curve the model refused
// (result.best_curve_error), is a warning, not an error. Throws
// std::runtime_error only when a file cannot be written.
StudyReport write_study_report(const StudySpec& spec, const StudyResult& result, const std::string& out_dir);

// The summary object (one JSON object, one line, SI values plus display
// strings): name, kind, status, message, best / least_infeasible / front /
// chosen, evaluations, failed_evaluations, reused_evaluations, warnings,
// timings {seconds, report_seconds, per_evaluation_ms}, files {role: path}.
// Field by field in docs/output.md. `warnings` replaces result.warnings when
// not empty (the report adds its own); either way the best design's own
// warnings (also in best.warnings) are listed first.
std::string study_summary_json(const StudySpec& spec, const StudyResult& result, const ReportFiles& files,
                               const ReportTimings& timings, const std::vector<std::string>& warnings = {});

// Display text of an SI metric value in the metric's display unit, e.g.
// "26.1 MN/m", "61.2 yr", "1.42"; the label may carry a parameter
// ("wear_life_at_R(0.9)"). Unknown labels print as a plain number.
std::string metric_display(const std::string& label, double value_si);

// Display text of variable `v` at the SI value `value_si`, in v.unit.
std::string variable_display(const DesignVariable& v, double value_si);

// The message for people about how the study ended, e.g. "stopped after 120
// evaluations: continue with --resume", "no feasible design: the least
// infeasible one is shown".
std::string status_message(const StudySpec& spec, const StudyResult& result);

}  // namespace rackopt::study_report
