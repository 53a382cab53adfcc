#include "rackopt/study_report/run_summary_text.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rackopt/core/text.hpp"
#include "rackopt/fe/fe_comparison_report.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/study_report/result_facts.hpp"
#include "rackopt/study_report/warnings_report.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;
namespace {

void design_lines(std::ostringstream& o, const StudySpec& spec, const DesignResult& d) {
  for (std::size_t i = 0; i < spec.variables.size() && i < d.x.size(); ++i) {
    o << "    " << spec.variables[i].key << " = " << variable_display(spec.variables[i], d.x[i]) << "\n";
  }
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
    const bool ok = i < d.metric_ok.size() && d.metric_ok[i] && i < d.metric_values.size();
    o << "    " << d.metric_labels[i] << ": "
      << (ok ? metric_display(d.metric_labels[i], d.metric_values[i]) : std::string("failed")) << "\n";
  }
  if (!d.feasible && std::isfinite(d.max_violation)) {
    o << "    max constraint violation (normalized): " << d.max_violation << "\n";
  }
  if (!d.message.empty()) o << "    " << d.message << "\n";
}

}  // namespace

std::string study_summary_text(const StudySpec& spec, const StudyResult& r, const StudyReport& rep,
                               const std::string& out_dir) {
  std::ostringstream o;
  o << "study " << one_line(spec.name) << " (" << kind_name(spec.kind) << "): " << to_string(r.status) << "\n";
  o << "  " << status_message(spec, r) << "\n";
  if (spec.kind == StudyKind::kPareto && !r.front.empty()) {
    o << "  Pareto front, " << r.front.size() << " points:\n";
    for (std::size_t k = 0; k < r.front.size(); ++k) {
      const bool chosen = r.chosen && *r.chosen == k;
      o << (chosen ? "  * " : "    ") << k << ":";
      for (std::size_t i = 0; i < spec.objectives.size() && i < r.front[k].objectives.size(); ++i) {
        o << "  " << spec.objectives[i].label << " "
          << metric_display(spec.objectives[i].label, r.front[k].objectives[i]);
      }
      o << "\n";
    }
    if (r.chosen && *r.chosen < r.front.size()) {
      o << "  chosen design (*):\n";
      design_lines(o, spec, r.front[*r.chosen]);
    }
  } else if (r.best) {
    const bool single = spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability;
    o << (single ? "  design" : "  best design") << (r.best->label.empty() ? "" : " (" + r.best->label + ")")
      << ":\n";
    design_lines(o, spec, *r.best);
  }
  if (r.reliability && r.best_drive) o << wear_summary(*r.best_drive, *r.reliability);
  if (r.fe_verification) {
    o << "  FE verification of the " << (spec.kind == StudyKind::kPareto ? "chosen" : "best") << " design:\n"
      << fe::fe_comparison_summary(*r.fe_verification);
  } else if (spec.verify_fe) {
    o << "  FE verification: " << r.fe_verification_error << "\n";
  }
  if (spec.kind == StudyKind::kSweep && !r.sweep_points.empty()) {
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
        o << metric_display(labels[i], lo) << " .. " << metric_display(labels[i], hi) << "\n";
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
  for (const std::string& note : recorded_rows_notes(r)) o << "  " << note << "\n";
  // Model warnings are often one near-copy per design: grouped by kind, the
  // best design's own first; the first few kinds here, all in report.md.
  o << warnings_text(report_warnings(spec, r, rep.warnings), 5);
  const std::string md = rep.files.get("report_md");
  const std::string html = rep.files.get("report_html");
  o << "  wrote " << out_dir << "/ (" << (md.empty() ? std::string("summary.json") : md)
    << (html.empty() ? std::string() : ", " + html) << ")\n";
  if (r.status == StudyStatus::kStopped) o << "  continue with: rackopt run " << spec.file << " --out " << out_dir << " --resume\n";
  return o.str();
}

}  // namespace rackopt::study_report
