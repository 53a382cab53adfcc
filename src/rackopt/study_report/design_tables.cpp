#include "rackopt/study_report/design_tables.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rackopt/core/text.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/study_report/display_units.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;
namespace {

// The value of metric `label` in `d`, if computed.
std::optional<double> metric_of(const DesignResult& d, const std::string& label) {
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
    if (d.metric_labels[i] == label) {
      const bool ok = i < d.metric_ok.size() && d.metric_ok[i];
      if (ok && i < d.metric_values.size() && std::isfinite(d.metric_values[i])) return d.metric_values[i];
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// lead: extra leading columns (name, value per design).
DesignTable design_table(const StudySpec& spec, const std::vector<std::string>& labels,
                         const std::vector<const DesignResult*>& designs,
                         const std::vector<std::string>& lead_names,
                         const std::vector<std::vector<std::string>>& lead_values) {
  DesignTable t;
  auto add = [&](const std::string& name) {
    t.header.push_back(name);
    t.columns.emplace(name, static_cast<int>(t.header.size()));
  };
  for (const auto& n : lead_names) add(n);
  add("label");
  for (const auto& v : spec.variables) add(var_col(v));
  for (const auto& l : labels) add(metric_col(l));
  add("ok");
  add("feasible");
  add("max_violation");
  // Display-unit copies for people reading the table; the SI columns are the contract.
  std::vector<bool> var_display(spec.variables.size(), false);
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const VariableUnit u = variable_unit(spec.variables[i]);
    if (u.display != u.si && !u.display.empty()) {
      var_display[i] = true;
      add(with_suffix(spec.variables[i].key, u.display));
    }
  }
  std::vector<bool> metric_display_col(labels.size(), false);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const MetricUnit u = metric_unit(labels[i]);
    if (u.display != u.si && !u.display.empty() && u.factor != 1) {
      metric_display_col[i] = true;
      add(with_suffix(labels[i], u.display));
    }
  }
  add("message");  // last: free text never shifts a numeric column

  std::ostringstream o;
  for (std::size_t i = 0; i < t.header.size(); ++i) o << (i ? "," : "") << csv_field(t.header[i]);
  o << "\n";
  for (std::size_t r = 0; r < designs.size(); ++r) {
    const DesignResult& d = *designs[r];
    std::vector<std::string> row;
    if (r < lead_values.size()) row = lead_values[r];
    row.resize(lead_names.size());
    row.push_back(d.label);
    for (std::size_t i = 0; i < spec.variables.size(); ++i) row.push_back(i < d.x.size() ? exact_number(d.x[i]) : "");
    for (const auto& l : labels) {
      const auto v = metric_of(d, l);
      row.push_back(v ? exact_number(*v) : "");
    }
    row.push_back(d.ok ? "1" : "0");
    row.push_back(d.feasible ? "1" : "0");
    row.push_back(exact_number(d.max_violation));
    for (std::size_t i = 0; i < spec.variables.size(); ++i) {
      if (!var_display[i]) continue;
      row.push_back(i < d.x.size() ? exact_number(d.x[i] / variable_unit(spec.variables[i]).factor) : "");
    }
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (!metric_display_col[i]) continue;
      const auto v = metric_of(d, labels[i]);
      row.push_back(v ? exact_number(*v / metric_unit(labels[i]).factor) : "");
    }
    row.push_back(d.message);
    for (std::size_t i = 0; i < row.size(); ++i) o << (i ? "," : "") << csv_field(row[i]);
    o << "\n";
  }
  t.text = o.str();
  return t;
}

}  // namespace

std::vector<std::string> metric_labels(const StudySpec& spec, const StudyResult& result) {
  std::vector<std::string> labels;
  for (const auto& m : spec.all_metrics()) labels.push_back(metrics::to_string(m));
  // A result may carry metrics the spec does not name (a runner adding its
  // own): keep them too, after the spec's.
  auto take = [&](const DesignResult& d) {
    for (const auto& l : d.metric_labels) {
      if (std::find(labels.begin(), labels.end(), l) == labels.end()) labels.push_back(l);
    }
  };
  if (result.best) take(*result.best);
  if (result.least_infeasible) take(*result.least_infeasible);
  for (const auto& d : result.front) take(d);
  for (const auto& d : result.sweep_points) take(d);
  return labels;
}

std::string var_col(const DesignVariable& v) { return with_suffix(v.key, variable_unit(v).si); }
std::string metric_col(const std::string& label) { return with_suffix(label, metric_unit(label).si); }

std::optional<DesignTable> best_table(const StudySpec& spec, const std::vector<std::string>& labels,
                                      const StudyResult& result) {
  std::vector<const DesignResult*> rows;
  std::vector<std::vector<std::string>> roles;
  if (result.best && spec.kind != StudyKind::kPareto) {
    rows.push_back(&*result.best);
    roles.push_back({"best"});
  }
  if (result.least_infeasible) {
    rows.push_back(&*result.least_infeasible);
    roles.push_back({"least_infeasible"});
  }
  if (rows.empty()) return std::nullopt;
  return design_table(spec, labels, rows, {"role"}, roles);
}

std::optional<DesignTable> front_table(const StudySpec& spec, const std::vector<std::string>& labels,
                                       const StudyResult& result) {
  if (spec.kind != StudyKind::kPareto || result.front.empty()) return std::nullopt;
  std::vector<const DesignResult*> rows;
  std::vector<std::vector<std::string>> lead;
  for (std::size_t k = 0; k < result.front.size(); ++k) {
    rows.push_back(&result.front[k]);
    lead.push_back({std::to_string(k), result.chosen && *result.chosen == k ? "1" : "0"});
  }
  return design_table(spec, labels, rows, {"point", "chosen"}, lead);
}

std::optional<DesignTable> sweep_table(const StudySpec& spec, const std::vector<std::string>& labels,
                                       const StudyResult& result) {
  if (result.sweep_points.empty()) return std::nullopt;
  std::vector<const DesignResult*> rows;
  std::vector<std::vector<std::string>> lead;
  for (std::size_t k = 0; k < result.sweep_points.size(); ++k) {
    rows.push_back(&result.sweep_points[k]);
    lead.push_back({std::to_string(k)});
  }
  return design_table(spec, labels, rows, {"point"}, lead);
}

std::optional<std::string> history_table(const StudySpec& spec, const StudyResult& result) {
  if (result.best_history.empty() || spec.objectives.empty()) return std::nullopt;
  const std::string& label = spec.objectives[0].label;
  const MetricUnit u = metric_unit(label);
  const bool display_col = !u.display.empty() && u.display != u.si && u.factor != 1;
  std::ostringstream o;
  o << "evaluation," << csv_field("best_" + metric_col(label));
  if (display_col) o << "," << csv_field("best_" + with_suffix(label, u.display));
  o << "\n";
  for (std::size_t i = 0; i < result.best_history.size(); ++i) {
    const double h = result.best_history[i];
    o << (i + 1) << "," << exact_number(h);
    if (display_col) o << "," << (std::isfinite(h) ? exact_number(h / u.factor) : "");
    o << "\n";
  }
  return o.str();
}

}  // namespace rackopt::study_report
