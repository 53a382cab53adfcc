// Global sensitivity of a sweep's metrics to its design variables, from the
// sweep's own points (no model evaluation): Sobol first-order indices S_i and,
// on a complete full-factorial grid, total indices S_Ti. Methods, sources and
// accuracy: docs/models/sensitivity.md.
//
// The indices treat the design box as the input distribution: every variable
// independent and uniform over its sweep levels (grid) or its range (Latin
// hypercube, Sobol). They rank which variable moves a metric across the box,
// not how steep the metric is at one design.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

struct DesignResult;  // study_result.hpp

// How one variable drives one metric.
struct VariableSensitivity {
  std::string variable;          // DesignVariable::key
  // Sobol first-order index Var(E[Y|X_i]) / Var(Y), in [0, 1].
  double first_order = 0;
  // Sobol total index E[Var(Y|X_~i)] / Var(Y), in [0, 1]; only from a complete
  // grid (nullopt from the given-data estimator).
  std::optional<double> total;
  // Classes the estimate used: grid levels, or bins / distinct values.
  std::size_t classes = 0;
};

// Every variable's indices for one metric.
struct MetricSensitivity {
  std::string metric;            // the metric label (DesignResult::metric_labels)
  std::size_t points_used = 0;   // points whose metric was computed (and finite)
  std::size_t points_left_out = 0;  // failed (metric not ok, non-finite, or not recorded)
  double variance = 0;           // Var(Y) over the points used, SI unit of the metric squared (1/N)
  // "grid ANOVA" (exact decomposition on a complete full-factorial grid),
  // "given-data binning" (first order only), or "none" (no ranking: see note).
  std::string method;
  // Ranked by first_order, then total, descending (ties keep the variables'
  // order); empty when method == "none". Variables with a single value among
  // the points used are not listed (the note names them).
  std::vector<VariableSensitivity> variables;
  std::string note;              // left-out points, skipped variables, why no total / no ranking
};

// One MetricSensitivity per metric label of the points (the first point's
// labels, in order); empty when there is no point. `points` are the sweep
// points of a StudyResult (any order); `spec` gives the variables and the
// sweep method and levels (a grid is checked against the levels the runner
// builds from it). A point leaves a metric out when its metric_ok is false,
// its value is not finite, or it has no such label. Never returns NaN: a
// constant metric (standard deviation <= 1e-12 of its largest magnitude) or
// fewer than 2 usable points give method "none" and a note.
// Throws std::invalid_argument when a point's x does not have one value per
// spec.variables entry (a caller's bug, not a model failure).
std::vector<MetricSensitivity> sweep_sensitivity(const StudySpec& spec, const std::vector<DesignResult>& points);

// A markdown fragment for the report: per metric a line (method, points) and
// a table | variable | S_i | S_Ti |, ranked, indices with 3 decimals ("-"
// where there is no total), the note below it. No heading of its own.
std::string sensitivity_markdown(const std::vector<MetricSensitivity>& sensitivities);

// Writes one JSON array value (the caller writes the key first, e.g.
// w.key("sensitivity")): per metric an object {metric, method, points_used,
// points_left_out, variance, note, variables: [{variable, first_order, total
// (null when absent), classes}]}, in the ranked order.
void sensitivity_json(JsonWriter& w, const std::vector<MetricSensitivity>& sensitivities);

}  // namespace rackopt::study
