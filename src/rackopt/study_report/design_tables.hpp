// The CSV tables of a study report: best.csv, front.csv and sweep.csv share
// one layout (DesignTable: SI columns named with their unit, then display-unit
// copies, the message last), history.csv has its own. Columns in
// docs/output.md ("Study results").
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// A design table's text and where each column is, so the gnuplot scripts
// can address columns by name.
struct DesignTable {
  std::vector<std::string> header;
  std::map<std::string, int> columns;  // column name -> 1-based index
  std::string text;

  // The 1-based index of column `name`, 0 when the table has none.
  int col(const std::string& name) const {
    auto it = columns.find(name);
    return it == columns.end() ? 0 : it->second;
  }
};

// The metric labels the tables have columns for: the spec's metrics, then
// any other label a design of the result carries, in first-seen order.
std::vector<std::string> metric_labels(const StudySpec& spec, const StudyResult& result);

// Column names of variable `v` and metric `label` in SI ("pinion.module_m",
// "min_stiffness_N_per_m").
std::string var_col(const DesignVariable& v);
std::string metric_col(const std::string& label);

// best.csv: the best design (role "best"; not for pareto, whose chosen point
// is in front.csv) and the least infeasible one; nullopt when neither exists.
std::optional<DesignTable> best_table(const StudySpec& spec, const std::vector<std::string>& labels,
                                      const StudyResult& result);
// front.csv: a pareto study's front, with the point index and the chosen
// flag; nullopt for other kinds and for an empty front.
std::optional<DesignTable> front_table(const StudySpec& spec, const std::vector<std::string>& labels,
                                       const StudyResult& result);
// sweep.csv: every sweep point with its index; nullopt when there is none.
std::optional<DesignTable> sweep_table(const StudySpec& spec, const std::vector<std::string>& labels,
                                       const StudyResult& result);
// history.csv: the best feasible objective 0 after each evaluation (SI, and
// in its display unit when that differs); nullopt without a history or
// without an objective.
std::optional<std::string> history_table(const StudySpec& spec, const StudyResult& result);

}  // namespace rackopt::study_report
