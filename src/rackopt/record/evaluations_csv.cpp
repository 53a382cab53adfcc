// CSV export of a study's evaluations (declared in evaluation_store.hpp).
#include <algorithm>
#include <map>
#include <charconv>
#include <string>
#include <unordered_map>

#include "rackopt/core/atomic_file.hpp"
#include "rackopt/core/text.hpp"
#include "rackopt/record/evaluation_store.hpp"

#include "rackopt/units/units.hpp"

namespace rackopt::record {
namespace {

void put_field(std::string& out, const std::string& field) { out += csv_field(field); }

// Shortest text that reads back to the same double ("inf", "-inf", "nan" for
// the non-finite values a failed evaluation may carry).
void put_number(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

}  // namespace

void write_evaluations_csv(const EvaluationStore& store, const std::vector<std::string>& variable_names,
                           const std::vector<std::string>& metric_names, const std::string& path) {
  if (variable_names.size() != store.dimension()) {
    throw std::invalid_argument("write_evaluations_csv: " + std::to_string(variable_names.size()) +
                                " variable names for a study of " + std::to_string(store.dimension()) +
                                " variables");
  }
  std::size_t n_obj = 0, n_ineq = 0, n_eq = 0;
  store.for_each([&](const RecordedEvaluation& e) {
    n_obj = std::max(n_obj, e.objectives.size());
    n_ineq = std::max(n_ineq, e.inequality.size());
    n_eq = std::max(n_eq, e.equality.size());
  });

  std::string out;
  auto header = [&](const std::string& name, bool first = false) {
    if (!first) out += ',';
    put_field(out, name);
  };
  // Variables and metrics carry their SI unit in the name, as the other
  // CSVs of a study do ("rack.span_m", "wear_life_at_R(0.9)_s"); the
  // solver's own scaled values say so.
  const std::map<std::string, std::string> units = store.column_units();
  auto with_unit = [&](const std::string& name) {
    const auto u = units.find(name);
    return u == units.end() ? name : with_suffix(name, u->second);
  };
  header("id", true);
  for (const char* h : {"phase", "ok", "message", "gradient_probe", "seconds_s"}) header(h);
  for (const auto& v : variable_names) header(with_unit(v));
  for (std::size_t i = 0; i < n_obj; ++i) header("scaled_objective_" + std::to_string(i));
  for (std::size_t i = 0; i < n_ineq; ++i) header("scaled_inequality_" + std::to_string(i));
  for (std::size_t i = 0; i < n_eq; ++i) header("scaled_equality_" + std::to_string(i));
  for (const auto& m : metric_names) header(with_unit(m));
  out += '\n';

  std::unordered_map<std::string, std::size_t> metric_column;
  for (std::size_t i = 0; i < metric_names.size(); ++i) metric_column.emplace(metric_names[i], i);
  std::vector<const double*> metric_cell(metric_names.size());

  store.for_each([&](const RecordedEvaluation& e) {
    out += std::to_string(e.id);
    out += ',';
    put_field(out, e.phase);
    out += e.ok ? ",1," : ",0,";
    put_field(out, e.message);
    out += e.gradient_probe ? ",1," : ",0,";
    put_number(out, e.seconds);
    for (double v : e.x) {
      out += ',';
      put_number(out, v);
    }
    auto padded = [&](const std::vector<double>& v, std::size_t width) {
      for (std::size_t i = 0; i < width; ++i) {
        out += ',';
        if (i < v.size()) put_number(out, v[i]);
      }
    };
    padded(e.objectives, n_obj);
    padded(e.inequality, n_ineq);
    padded(e.equality, n_eq);
    std::fill(metric_cell.begin(), metric_cell.end(), nullptr);
    for (const auto& [name, value] : e.metrics) {
      if (auto it = metric_column.find(name); it != metric_column.end()) metric_cell[it->second] = &value;
    }
    for (const double* cell : metric_cell) {
      out += ',';
      if (cell) put_number(out, *cell);
    }
    out += '\n';
  });
  // Every row, the header included, ends with its newline; the writer checks
  // that every byte reached the disk before the table gets its name.
  write_file_atomically(path, out);
}

}  // namespace rackopt::record
