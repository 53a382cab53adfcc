// study_summary_json, declared with its contract in study_report.hpp.
#include <cmath>
#include <optional>

#include "rackopt/core/text.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/wear_files.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/study_report/display_units.hpp"
#include "rackopt/study_report/fe_verification_report.hpp"
#include "rackopt/study_report/front_quality_report.hpp"
#include "rackopt/study_report/optimum_report.hpp"
#include "rackopt/study_report/result_facts.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study_report/warnings_report.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;
namespace {

// One design as summary.json's best, least_infeasible, front and optimum
// entries all show it, so a program reads every design the same way.
void json_design(JsonWriter& j, const StudySpec& spec, const DesignResult& d, std::optional<bool> chosen) {
  j.begin_object();
  j.key("label").value(d.label);
  if (chosen) j.key("chosen").value(*chosen);
  // Its row in evaluations.csv, which warning_groups' evaluations name.
  if (d.evaluation_id > 0) {
    j.key("evaluation").value(static_cast<long>(d.evaluation_id));
  } else {
    j.key("evaluation").null();
  }
  j.key("variables").begin_object();
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const DesignVariable& v = spec.variables[i];
    j.key(v.key).begin_object();
    if (i < d.x.size()) {
      j.key("value").value(d.x[i]);
      j.key("display").value(variable_display(v, d.x[i]));
    } else {
      j.key("value").null();
      j.key("display").value("");
    }
    j.key("unit").value(std::string(si_unit(v.kind)));
    j.end_object();
  }
  j.end_object();
  j.key("metrics").begin_object();
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
    const std::string& l = d.metric_labels[i];
    const bool ok = i < d.metric_ok.size() && d.metric_ok[i] && i < d.metric_values.size();
    j.key(l).begin_object();
    if (ok) {
      j.key("value").value(d.metric_values[i]);
      j.key("display").value(metric_display(l, d.metric_values[i]));
    } else {
      j.key("value").null();
      j.key("display").value("failed");
    }
    j.key("ok").value(ok);
    const MetricUnit u = metric_unit(l);
    j.key("unit").value(u.si);
    j.end_object();
  }
  j.end_object();
  j.key("objectives").begin_array();
  for (std::size_t i = 0; i < spec.objectives.size(); ++i) {
    const ObjectiveSpec& o = spec.objectives[i];
    j.begin_object();
    j.key("metric").value(o.label);
    j.key("sense").value(o.maximize ? "maximize" : "minimize");
    if (i < d.objectives.size() && std::isfinite(d.objectives[i])) {
      j.key("value").value(d.objectives[i]);
      j.key("display").value(metric_display(o.label, d.objectives[i]));
    } else {
      j.key("value").null();
      j.key("display").value("failed");
    }
    j.end_object();
  }
  j.end_array();
  j.key("ok").value(d.ok);
  j.key("feasible").value(d.feasible);
  j.key("max_violation").value(d.max_violation);  // +inf (failed) is written as null
  j.key("message").value(d.message);
  j.key("warnings").begin_array();
  for (const auto& w : d.warnings) j.value(w);
  j.end_array();
  j.end_object();
}

}  // namespace

std::string study_summary_json(const StudySpec& spec, const StudyResult& result, const ReportFiles& files,
                               const ReportTimings& timings, const std::vector<std::string>& warnings) {
  JsonWriter j;
  j.begin_object();
  j.key("ok").value(true);
  j.key("study").value(spec.name);
  j.key("kind").value(kind_name(spec.kind));
  j.key("description").value(trim(spec.description));
  j.key("file").value(spec.file);
  j.key("problem").value(spec.problem_path);
  j.key("seed").value(static_cast<double>(spec.seed));
  j.key("status").value(std::string(to_string(result.status)));
  j.key("message").value(status_message(spec, result));
  j.key("solver_message").value(result.solver_message);
  j.key("feasible").value(result.best.has_value() && result.best->feasible);

  j.key("variables").begin_array();
  for (const auto& v : spec.variables) {
    j.begin_object();
    j.key("name").value(v.key);
    j.key("unit").value(std::string(si_unit(v.kind)));
    j.key("display_unit").value(variable_unit(v).display);
    j.key("lower").value(v.lower);
    j.key("upper").value(v.upper);
    j.key("discrete").value(v.discrete());
    j.end_object();
  }
  j.end_array();
  j.key("objectives").begin_array();
  for (const auto& o : spec.objectives) {
    j.begin_object().key("metric").value(o.label).key("sense").value(o.maximize ? "maximize" : "minimize");
    j.end_object();
  }
  j.end_array();
  j.key("constraints").begin_array();
  for (const auto& c : spec.constraints) {
    j.begin_object().key("metric").value(c.label);
    if (c.min) j.key("min").value(*c.min);
    if (c.max) j.key("max").value(*c.max);
    if (c.equals) j.key("equals").value(*c.equals);
    j.key("text").value(bound_text(c));
    j.end_object();
  }
  j.end_array();

  j.key("best");
  if (result.best) {
    json_design(j, spec, *result.best, std::nullopt);
  } else {
    j.null();
  }
  if (result.least_infeasible) {
    j.key("least_infeasible");
    json_design(j, spec, *result.least_infeasible, std::nullopt);
  }
  if (spec.kind == StudyKind::kPareto) {
    j.key("front").begin_array();
    for (std::size_t k = 0; k < result.front.size(); ++k) {
      json_design(j, spec, result.front[k], result.chosen && *result.chosen == k);
    }
    j.end_array();
    j.key("chosen");
    if (result.chosen) {
      j.value(static_cast<long>(*result.chosen));
    } else {
      j.null();
    }
    front_quality_json(j, spec, result);
  }
  if (spec.kind == StudyKind::kSweep) {
    const std::size_t feasible = feasible_points(result);
    j.key("sweep_points").value(static_cast<long>(result.sweep_points.size()));
    j.key("feasible_points").value(static_cast<long>(feasible));
  }
  if (result.reliability && result.best_drive) {
    // The same object `rackopt wear --json` prints for this design: life,
    // life at R, R(t), the chosen fit with its KS statistic, exact quantiles.
    j.key("reliability").raw(
        wear_json(*result.best_drive, *result.reliability, wear_files_by_role(files.entries), 0.0));
  }
  optimum_json(j, spec, result, [](JsonWriter& w, const StudySpec& sp, const DesignResult& d) {
    json_design(w, sp, d, std::nullopt);
  });
  fe_verification_json(j, spec, result);
  j.key("evaluations").value(static_cast<long>(result.evaluations));
  j.key("failed_evaluations").value(static_cast<long>(result.failed_evaluations));
  j.key("reused_evaluations").value(static_cast<long>(result.reused_evaluations));
  j.key("damaged_records_recomputed").value(static_cast<long>(result.damaged_records));
  j.key("unchecked_records").value(static_cast<long>(result.unchecked_records));
  j.key("warnings").begin_array();
  for (const auto& w : warnings_best_first(result, warnings.empty() ? result.warnings : warnings)) j.value(w);
  j.end_array();
  warning_groups_json(j, report_warnings(spec, result, warnings.empty() ? result.warnings : warnings));
  const std::size_t fresh = fresh_evaluations(result);
  j.key("timings").begin_object();
  j.key("seconds").value(timings.run_seconds);
  j.key("report_seconds").value(timings.report_seconds);
  j.key("per_evaluation_ms");
  if (fresh > 0) {
    j.value(timings.run_seconds * 1000.0 / static_cast<double>(fresh));
  } else {
    j.null();
  }
  j.end_object();
  j.key("files").begin_object();
  for (const auto& [role, path] : files.entries) j.key(role).value(path);
  j.end_object();
  j.end_object();
  return j.str();
}

}  // namespace rackopt::study_report
