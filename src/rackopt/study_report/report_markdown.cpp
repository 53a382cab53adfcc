#include "rackopt/study_report/report_markdown.hpp"

#include "rackopt/study_report/plot_captions.hpp"

#include "rackopt/solvers/solver_backend.hpp"

#include <cmath>
#include <sstream>

#include "rackopt/core/text.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/study_report/display_units.hpp"
#include "rackopt/study_report/fe_verification_report.hpp"
#include "rackopt/study_report/front_quality_report.hpp"
#include "rackopt/study_report/markdown_text.hpp"
#include "rackopt/study_report/optimum_report.hpp"
#include "rackopt/study_report/result_facts.hpp"
#include "rackopt/study_report/warnings_report.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;
namespace {

namespace fs = std::filesystem;

// Text inside a table cell or on one line: markdown_text escapes the '|'
// that would end the cell and the line break that would end the row.
std::string md_cell(const std::string& s) { return markdown_text(s); }

void md_design(std::ostringstream& o, const StudySpec& spec, const DesignResult& d) {
  o << "| | |\n|---|---|\n";
  for (std::size_t i = 0; i < spec.variables.size() && i < d.x.size(); ++i) {
    o << "| " << markdown_code_cell(spec.variables[i].key) << " | " << md_cell(variable_display(spec.variables[i], d.x[i])) << " |\n";
  }
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
    const bool ok = i < d.metric_ok.size() && d.metric_ok[i] && i < d.metric_values.size();
    o << "| " << md_cell(d.metric_labels[i]) << " | "
      << (ok ? md_cell(metric_display(d.metric_labels[i], d.metric_values[i])) : std::string("failed")) << " |\n";
  }
  o << "| feasible | " << (d.feasible ? "yes" : "no") << " |\n";
  o << "| max violation | " << (std::isfinite(d.max_violation) ? short_number(d.max_violation) : "– (failed)")
    << " |\n";
  if (!d.message.empty()) o << "| message | " << md_cell(d.message) << " |\n";
  o << "\n";
}

}  // namespace

std::string link_target(const fs::path& out_dir, const std::string& path) {
  const fs::path rel = fs::path(path).lexically_normal().lexically_relative(out_dir.lexically_normal());
  if (!rel.empty() && rel.native().rfind("..", 0) != 0) return rel.generic_string();
  return fs::absolute(path).generic_string();
}

std::string report_markdown(const StudySpec& spec, const StudyResult& result, const ReportFiles& files,
                            const std::vector<std::string>& warnings, const fs::path& out_dir) {
  std::ostringstream o;
  o << "# Study: " << markdown_text(spec.name) << "\n\n";
  if (!trim(spec.description).empty()) o << markdown_description(trim(spec.description)) << "\n\n";
  o << "- kind: " << kind_name(spec.kind) << "\n";
  if (!spec.file.empty()) o << "- study file: " << markdown_code(spec.file) << "\n";
  if (!spec.problem_path.empty()) o << "- problem: " << markdown_code(spec.problem_path) << "\n";
  for (const auto& ov : spec.problem_overrides) o << "- problem override: " << markdown_code(ov) << "\n";
  o << "- seed: " << spec.seed << "\n";
  if (spec.kind == StudyKind::kOptimize || spec.kind == StudyKind::kPareto) {
    o << "- solver: " << md_cell(spec.solver.library);
    const solvers::SolverBackend* backend = solvers::find_solver_backend(spec.solver.library);
    if (backend && !backend->algorithms().empty()) o << " " << md_cell(spec.solver.algorithm);
    for (const auto& [key, value] : spec.solver.options) o << ", " << md_cell(key) << " " << format_number(value, 6);
    if (!spec.solver.local_algorithm.empty()) o << " (local " << md_cell(spec.solver.local_algorithm) << ")";
    o << ", at most " << spec.solver.max_evaluations << " evaluations";
    if (spec.solver.starts > 1) o << ", " << spec.solver.starts << " starts";
    o << "\n";
  }
  if (spec.kind == StudyKind::kPareto) {
    o << "- front: " << solvers::method_title(spec.pareto.method) << ", " << spec.pareto.points
      << " points requested\n";
  }
  if (spec.kind == StudyKind::kSweep) {
    const char* m = spec.sweep.method == SweepSpec::Method::kGrid             ? "grid"
                    : spec.sweep.method == SweepSpec::Method::kLatinHypercube ? "Latin hypercube"
                                                                              : "Sobol";
    o << "- sweep: " << m;
    if (spec.sweep.method == SweepSpec::Method::kGrid) {
      o << ", " << spec.sweep.levels << " levels per continuous variable";
    } else {
      o << ", " << spec.sweep.points << " points";
    }
    o << "\n";
  }
  o << "\n";
  if (!spec.variables.empty()) {
    o << "## Design variables\n\n| variable | lower | upper | start | values |\n|---|---|---|---|---|\n";
    for (const auto& v : spec.variables) {
      std::string values;
      for (double x : v.values) values += (values.empty() ? "" : ", ") + variable_display(v, x);
      o << "| " << markdown_code_cell(v.key) << " | " << md_cell(variable_display(v, v.lower)) << " | "
        << md_cell(variable_display(v, v.upper)) << " | " << (v.start ? md_cell(variable_display(v, *v.start)) : "–")
        << " | " << (values.empty() ? "continuous" : md_cell(values))
        << " |\n";
    }
    o << "\n";
  }
  if (!spec.objectives.empty()) {
    o << "## Objectives\n\n";
    for (const auto& ob : spec.objectives) o << "- " << (ob.maximize ? "maximize " : "minimize ") << md_cell(ob.label) << "\n";
    o << "\n";
  }
  if (!spec.constraints.empty()) {
    o << "## Constraints\n\n";
    for (const auto& c : spec.constraints) o << "- " << md_cell(bound_text(c)) << "\n";
    o << "\n";
  }

  o << "## Outcome\n\n";
  o << "**Status: " << to_string(result.status) << "**: " << md_cell(status_message(spec, result)) << "\n\n";
  if (!result.solver_message.empty()) o << "Solver: " << md_cell(result.solver_message) << "\n\n";
  if (spec.kind == StudyKind::kPareto && !result.front.empty()) {
    o << "### Pareto front (" << result.front.size() << " points)\n\n| # | chosen |";
    for (const auto& v : spec.variables) o << " " << markdown_code_cell(v.key) << " |";
    for (const auto& ob : spec.objectives) o << " " << md_cell(ob.label) << " |";
    o << "\n|---|---|";
    for (std::size_t i = 0; i < spec.variables.size() + spec.objectives.size(); ++i) o << "---|";
    o << "\n";
    for (std::size_t k = 0; k < result.front.size(); ++k) {
      const DesignResult& d = result.front[k];
      const bool ch = result.chosen && *result.chosen == k;
      o << "| " << k << " | " << (ch ? "**chosen**" : "") << " |";
      for (std::size_t i = 0; i < spec.variables.size(); ++i) {
        o << " " << (i < d.x.size() ? md_cell(variable_display(spec.variables[i], d.x[i])) : "") << " |";
      }
      for (std::size_t i = 0; i < spec.objectives.size(); ++i) {
        o << " " << (i < d.objectives.size() ? md_cell(metric_display(spec.objectives[i].label, d.objectives[i])) : "")
          << " |";
      }
      o << "\n";
    }
    o << "\n";
    o << front_quality_markdown(spec, result);
    if (result.chosen && *result.chosen < result.front.size()) {
      o << "### Chosen design (front point " << *result.chosen << ")\n\n";
      md_design(o, spec, result.front[*result.chosen]);
    }
  } else if (result.best) {
    const bool single = spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability;
    o << (single ? "### Design" : "### Best design") << (result.best->label.empty() ? "" : " (" + md_cell(result.best->label) + ")") << "\n\n";
    md_design(o, spec, *result.best);
    o << explanation_markdown(spec, result) << per_combination_markdown(spec, result);
  }
  if (result.least_infeasible) {
    o << "### Least infeasible design"
      << (result.least_infeasible->label.empty() ? "" : " (" + md_cell(result.least_infeasible->label) + ")") << "\n\n";
    md_design(o, spec, *result.least_infeasible);
  }
  if (spec.kind == StudyKind::kSweep) {
    const std::size_t feasible = feasible_points(result);
    o << "Sweep: " << result.sweep_points.size() << " points, " << feasible << " feasible.\n\n";
  }

  o << sweep_sensitivity_markdown(spec, result);
  if (result.reliability && result.best_drive) {
    o << "### Wear life and reliability of the design\n\n```\n"
      << wear_summary(*result.best_drive, *result.reliability) << "```\n\n";
  }

  o << fe_verification_markdown(spec, result);
  o << fidelity_markdown(result);
  o << "## Counts and timings\n\n";
  const std::size_t fresh = fresh_evaluations(result);
  o << "- evaluations: " << result.evaluations << " (" << result.failed_evaluations << " failed, "
    << result.reused_evaluations << " taken from the store on resume)\n";
  for (const std::string& note : recorded_rows_notes(result)) o << "- " << note << "\n";
  o << "- wall time of this run: " << short_number(result.seconds) << " s";
  if (fresh > 0) o << " (" << short_number(result.seconds * 1000.0 / static_cast<double>(fresh)) << " ms per new evaluation)";
  o << "\n\n";

  o << warnings_markdown(report_warnings(spec, result, warnings));

  o << "## Files\n\n";
  for (const auto& [role, path] : files.entries) {
    if (role == "report_md" || !fs::exists(path)) continue;
    const std::string target = link_target(out_dir, path);
    o << "- [" << md_cell(fs::path(path).filename().string()) << "](" << markdown_link_destination(target)
      << "): " << md_cell(role) << "\n";
  }
  o << "\n";
  bool any_plot = false;
  for (const auto& [role, path] : files.entries) {
    if (fs::path(path).extension() != ".png" || !fs::exists(path)) continue;
    if (!any_plot) o << "## Plots\n\n";
    any_plot = true;
    const PlotCaption c = plot_caption(role, spec);
    o << "![" << md_cell(c.title) << "](" << markdown_link_destination(link_target(out_dir, path)) << ")\n\n";
    if (!c.caption.empty()) o << "*" << md_cell(c.caption) << "*\n\n";
  }
  return o.str();
}

}  // namespace rackopt::study_report
