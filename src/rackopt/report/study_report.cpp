#include "rackopt/report/study_report.hpp"

#include "rackopt/report/optimum_report.hpp"
#include "rackopt/report/fe_verification_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "rackopt/core/error.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/plot.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt::study {

std::string ReportFiles::get(const std::string& role) const {
  for (const auto& [r, p] : entries) {
    if (r == role) return p;
  }
  return "";
}

namespace {

std::size_t feasible_points(const StudyResult& r) {
  return static_cast<std::size_t>(std::count_if(r.sweep_points.begin(), r.sweep_points.end(),
                                                [](const DesignResult& p) { return p.feasible; }));
}

namespace fs = std::filesystem;

// ---- units ------------------------------------------------------------------

std::string si_unit(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kDimensionless:
    case QuantityKind::kCount: return "";
    case QuantityKind::kLength: return "m";
    case QuantityKind::kAngle: return "rad";
    case QuantityKind::kModulus: return "Pa";
    case QuantityKind::kForce: return "N";
    case QuantityKind::kTorque: return "N*m";
    case QuantityKind::kStiffness: return "N/m";
    case QuantityKind::kArea: return "m^2";
    case QuantityKind::kSecondMoment: return "m^4";
    case QuantityKind::kTime: return "s";
    case QuantityKind::kHardness: return "Pa";
    case QuantityKind::kRate: return "1/s";
    case QuantityKind::kMass: return "kg";
    case QuantityKind::kDensity: return "kg/m^3";
    case QuantityKind::kSpeed: return "m/s";
    case QuantityKind::kPower: return "W";
  }
  return "";
}

// A unit as a column-name suffix: "N/m" -> "N_per_m", "1/m" -> "per_m",
// "m^2" -> "m2", "N*m" -> "N_m", "-" and "" -> "".
std::string unit_suffix(const std::string& unit) {
  if (unit.empty() || unit == "-") return "";
  std::string u = unit;
  if (u.rfind("1/", 0) == 0) u = u.substr(1);
  std::string out;
  for (char c : u) {
    if (c == '/') {
      out += out.empty() ? "per_" : "_per_";
    } else if (c == '*' || c == '.' || c == ' ') {
      out += '_';
    } else if (c == '^') {
      continue;
    } else {
      out += c;
    }
  }
  return out;
}

std::string with_suffix(const std::string& name, const std::string& unit) {
  const std::string s = unit_suffix(unit);
  return s.empty() ? name : name + "_" + s;
}

struct MetricUnit {
  std::string si;       // "N/m", "-", "1/m"
  std::string display;  // "MN/m", "" (dimensionless), "1/m"
  double factor = 1;    // SI value of one display unit
  const metrics::MetricDefinition* def = nullptr;
};

MetricUnit metric_unit(const std::string& label) {
  MetricUnit u;
  try {
    const metrics::MetricRequest req = metrics::parse_metric_request(label);
    const metrics::MetricDefinition& def = metrics::find_metric(req.name);
    u.def = &def;
    u.si = std::string(def.unit);
    if (def.kind && !def.display_unit.empty()) {
      u.display = std::string(def.display_unit);
      u.factor = unit_factor(def.display_unit, *def.kind);
    } else {
      u.display = u.si == "-" ? "" : u.si;
    }
  } catch (const InputError&) {
    u.si = "";  // a label we do not know (a test's synthetic metric): plain number
  }
  return u;
}

struct VariableUnit {
  std::string si, display;
  double factor = 1;
};

VariableUnit variable_unit(const DesignVariable& v) {
  VariableUnit u;
  u.si = si_unit(v.kind);
  u.display = v.unit.empty() ? std::string(default_unit(v.kind)) : v.unit;
  if (!u.display.empty()) {
    try {
      u.factor = unit_factor(u.display, v.kind);
    } catch (const InputError&) {
      u.display = u.si;
      u.factor = 1;
    }
  }
  return u;
}

std::string num(double v) {
  if (!std::isfinite(v)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string short_num(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  return format_number(v, 6);
}



std::string axis_label(const std::string& name, const std::string& display_unit) {
  return display_unit.empty() ? name : name + " [" + display_unit + "]";
}

// ---- designs ----------------------------------------------------------------

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

// The CSV layout shared by best.csv, front.csv and sweep.csv; `columns` maps
// a column name to its 1-based index (for the gnuplot scripts).
struct DesignTable {
  std::vector<std::string> header;
  std::map<std::string, int> columns;
  std::string text;

  int col(const std::string& name) const {
    auto it = columns.find(name);
    return it == columns.end() ? 0 : it->second;
  }
};

std::string var_col(const DesignVariable& v) { return with_suffix(v.key, variable_unit(v).si); }
std::string metric_col(const std::string& label) { return with_suffix(label, metric_unit(label).si); }

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
    for (std::size_t i = 0; i < spec.variables.size(); ++i) row.push_back(i < d.x.size() ? num(d.x[i]) : "");
    for (const auto& l : labels) {
      const auto v = metric_of(d, l);
      row.push_back(v ? num(*v) : "");
    }
    row.push_back(d.ok ? "1" : "0");
    row.push_back(d.feasible ? "1" : "0");
    row.push_back(num(d.max_violation));
    for (std::size_t i = 0; i < spec.variables.size(); ++i) {
      if (!var_display[i]) continue;
      row.push_back(i < d.x.size() ? num(d.x[i] / variable_unit(spec.variables[i]).factor) : "");
    }
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (!metric_display_col[i]) continue;
      const auto v = metric_of(d, labels[i]);
      row.push_back(v ? num(*v / metric_unit(labels[i]).factor) : "");
    }
    row.push_back(d.message);
    for (std::size_t i = 0; i < row.size(); ++i) o << (i ? "," : "") << csv_field(row[i]);
    o << "\n";
  }
  t.text = o.str();
  return t;
}

// ---- JSON -------------------------------------------------------------------

void json_design(JsonWriter& j, const StudySpec& spec, const DesignResult& d, std::optional<bool> chosen) {
  j.begin_object();
  j.key("label").value(d.label);
  if (chosen) j.key("chosen").value(*chosen);
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
    j.key("unit").value(si_unit(v.kind));
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

// The best (pareto: chosen) design's own warnings, then those of `run_warnings`
// not among them: the optimum's remarks are the ones a reader acts on.
std::vector<std::string> best_first(const StudyResult& r, const std::vector<std::string>& run_warnings) {
  std::vector<std::string> out = r.best ? r.best->warnings : std::vector<std::string>{};
  for (const auto& w : run_warnings)
    if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
  return out;
}

// ---- plots ------------------------------------------------------------------

std::string gp_header(const std::string& png, int width, int height) {
  return "# Generated by rackopt (columns: docs/output.md, \"Study results\")\n"
         "set datafile separator ','\n"
         "set terminal pngcairo size " +
         std::to_string(width) + "," + std::to_string(height) +
         " noenhanced font ',11'\n"
         "set output '" +
         png + ".tmp'\nset grid\n"
         // points on the edge of the range would sit on the frame
         "set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06\n";
}

// `(column(n)/f)` for gnuplot, with rows where `gate` (a 1-based column) is
// not 1 dropped (1/0 is gnuplot's "no point").
std::string gp_value(int col, double factor, int gate = 0) {
  std::ostringstream o;
  o.precision(17);
  std::string v = "column(" + std::to_string(col) + ")";
  if (factor != 1) {
    o << "(" << v << "/" << factor << ")";
    v = o.str();
  }
  if (gate > 0) v = "(column(" + std::to_string(gate) + ")==1 ? " + v + " : 1/0)";
  return "(" + v + ")";
}

// Columns of evaluations.csv (written by the runner) holding the objective
// metrics and the ok flag: every evaluation drawn grey behind the front. Empty
// when the file or a column is missing.
std::vector<int> evaluations_columns(const std::string& path, const std::vector<std::string>& names) {
  if (path.empty()) return {};
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return {};
  std::vector<std::string> header;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      header.push_back(cell);
      cell.clear();
    } else if (c != '\r') {
      cell += c;
    }
  }
  header.push_back(cell);
  std::vector<int> cols;
  for (const auto& n : names) {
    auto it = std::find(header.begin(), header.end(), n);
    if (it == header.end()) return {};
    cols.push_back(static_cast<int>(it - header.begin()) + 1);
  }
  return cols;
}

std::string pareto_gnuplot(const StudySpec& spec, const DesignTable& front, const std::string& evaluations_csv) {
  const std::size_t n = spec.objectives.size();
  std::vector<int> col(n);
  std::vector<MetricUnit> unit(n);
  for (std::size_t i = 0; i < n; ++i) {
    col[i] = front.col(metric_col(spec.objectives[i].label));
    unit[i] = metric_unit(spec.objectives[i].label);
  }
  std::vector<std::string> wanted{"ok", "gradient_probe"};
  for (const auto& o : spec.objectives) wanted.push_back(o.label);
  const std::vector<int> ecols = evaluations_columns(evaluations_csv, wanted);
  const std::string eval_name = fs::path(evaluations_csv).filename().string();

  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (n == 2) {
    pairs = {{0, 1}};
  } else {
    pairs = {{0, 1}, {0, 2}, {1, 2}};
  }
  std::ostringstream o;
  o << gp_header("pareto.png", n == 2 ? 1100 : 1800, n == 2 ? 800 : 650);
  o << "set key outside bottom center horizontal\n";
  if (pairs.size() > 1) {
    o << "set multiplot layout 1," << pairs.size() << " title " << gnuplot_quote(spec.name + ": Pareto front") << "\n";
  } else {
    o << "set title " << gnuplot_quote(spec.name + ": Pareto front") << "\n";
  }
  const int chosen = front.col("chosen");
  for (const auto& [a, b] : pairs) {
    o << "set xlabel " << gnuplot_quote(axis_label(spec.objectives[a].label, unit[a].display)) << "\n";
    o << "set ylabel " << gnuplot_quote(axis_label(spec.objectives[b].label, unit[b].display)) << "\n";
    o << "plot ";
    if (!ecols.empty()) {
      // ok and not a finite-difference probe
      const std::string gate = "(column(" + std::to_string(ecols[0]) + ")==1 && column(" +
                               std::to_string(ecols[1]) + ")==0)";
      auto ev = [&](std::size_t k) {
        std::ostringstream e;
        e.precision(17);
        e << "(" << gate << " ? column(" << ecols[2 + k] << ")/" << unit[k].factor << " : 1/0)";
        return e.str();
      };
      o << gnuplot_quote(eval_name) << " skip 1 using " << ev(a) << ":" << ev(b)
        << " with points pt 7 ps 0.5 lc rgb '#c8c8c8' title 'every evaluation', \\\n     ";
    }
    o << "'front.csv' skip 1 using " << gp_value(col[a], unit[a].factor) << ":" << gp_value(col[b], unit[b].factor)
      // a 2-objective front sorted by objective 0 is a curve; projections of a 3-objective one are not
      << (n == 2 ? " with linespoints" : " with points") << " pt 7 ps 1.2 lc rgb '#1f77b4' title 'front', \\\n     "
      << "'' skip 1 using " << gp_value(col[a], unit[a].factor, chosen) << ":"
      << gp_value(col[b], unit[b].factor, chosen) << " with points pt 6 ps 3.5 lw 3 lc rgb '#d62728' title 'chosen'\n";
  }
  if (pairs.size() > 1) o << "unset multiplot\n";
  return o.str();
}

std::string history_gnuplot(const StudySpec& spec, const std::string& label, std::size_t evaluations) {
  const MetricUnit u = metric_unit(label);
  std::ostringstream o;
  o << gp_header("history.png", 1100, 700);
  o << "set title " << gnuplot_quote(spec.name + ": convergence") << "\n";
  o << "set xlabel 'evaluation'\nset xrange [0:" << std::max<std::size_t>(evaluations, 1) << "]\n";
  o << "set ylabel " << gnuplot_quote("best feasible " + axis_label(label, u.display)) << "\n";
  o << "set key top right\n";
  o << "plot 'history.csv' skip 1 using 1:" << gp_value(2, u.factor) << " with steps lw 2 title 'best feasible so far'\n";
  return o.str();
}

// Small multiples: one panel per (metric, variable), metrics in rows.
std::string sweep_gnuplot(const StudySpec& spec, const DesignTable& t, const std::vector<std::string>& labels) {
  const std::size_t nv = std::min<std::size_t>(spec.variables.size(), 6);
  const std::size_t nm = std::min<std::size_t>(labels.size(), 6);
  const int feasible = t.col("feasible");
  std::ostringstream o;
  o << gp_header("sweep.png", static_cast<int>(std::max<std::size_t>(2, nv) * 450),
                 static_cast<int>(std::max<std::size_t>(1, nm) * 330 + 60));
  o << "set multiplot layout " << nm << "," << nv << " title " << gnuplot_quote(spec.name + ": sweep responses") << "\n";
  o << "unset key\n";
  for (std::size_t m = 0; m < nm; ++m) {
    const MetricUnit mu = metric_unit(labels[m]);
    const int mc = t.col(metric_col(labels[m]));
    for (std::size_t v = 0; v < nv; ++v) {
      const VariableUnit vu = variable_unit(spec.variables[v]);
      const int vc = t.col(var_col(spec.variables[v]));
      o << "set xlabel " << gnuplot_quote(axis_label(spec.variables[v].key, vu.display)) << "\n";
      o << "set ylabel " << gnuplot_quote(axis_label(labels[m], mu.display)) << "\n";
      // infeasible grey behind, feasible on top
      o << "plot 'sweep.csv' skip 1 using " << gp_value(vc, vu.factor) << ":"
        << "(column(" << feasible << ")==0 ? " << gp_value(mc, mu.factor) << " : 1/0)"
        << " with points pt 7 ps 0.6 lc rgb '#b0b0b0', \\\n     '' skip 1 using " << gp_value(vc, vu.factor)
        << ":" << gp_value(mc, mu.factor, feasible) << " with points pt 7 ps 0.8 lc rgb '#1f77b4'\n";
    }
  }
  o << "unset multiplot\n";
  return o.str();
}

// ---- report.md --------------------------------------------------------------


std::string md_cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::string link_target(const fs::path& out_dir, const std::string& path) {
  const fs::path rel = fs::path(path).lexically_normal().lexically_relative(out_dir.lexically_normal());
  if (!rel.empty() && rel.native().rfind("..", 0) != 0) return rel.generic_string();
  return fs::absolute(path).generic_string();
}

std::string bound_text(const ConstraintSpec& c) {
  std::string s;
  if (c.equals) return c.label + " = " + metric_display(c.label, *c.equals);
  if (c.min) s += metric_display(c.label, *c.min) + " ≤ ";
  s += c.label;
  if (c.max) s += " ≤ " + metric_display(c.label, *c.max);
  return s;
}

void md_design(std::ostringstream& o, const StudySpec& spec, const DesignResult& d) {
  o << "| | |\n|---|---|\n";
  for (std::size_t i = 0; i < spec.variables.size() && i < d.x.size(); ++i) {
    o << "| `" << spec.variables[i].key << "` | " << md_cell(variable_display(spec.variables[i], d.x[i])) << " |\n";
  }
  for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
    const bool ok = i < d.metric_ok.size() && d.metric_ok[i] && i < d.metric_values.size();
    o << "| " << md_cell(d.metric_labels[i]) << " | "
      << (ok ? md_cell(metric_display(d.metric_labels[i], d.metric_values[i])) : std::string("failed")) << " |\n";
  }
  o << "| feasible | " << (d.feasible ? "yes" : "no") << " |\n";
  o << "| max violation | " << (std::isfinite(d.max_violation) ? short_num(d.max_violation) : "– (failed)")
    << " |\n";
  if (!d.message.empty()) o << "| message | " << md_cell(d.message) << " |\n";
  o << "\n";
}

std::string report_markdown(const StudySpec& spec, const StudyResult& result, const ReportFiles& files,
                            const std::vector<std::string>& warnings, const fs::path& out_dir) {
  std::ostringstream o;
  o << "# Study: " << spec.name << "\n\n";
  if (!trim(spec.description).empty()) o << trim(spec.description) << "\n\n";
  o << "- kind: " << kind_name(spec.kind) << "\n";
  if (!spec.file.empty()) o << "- study file: `" << spec.file << "`\n";
  if (!spec.problem_path.empty()) o << "- problem: `" << spec.problem_path << "`\n";
  for (const auto& ov : spec.problem_overrides) o << "- problem override: `" << ov << "`\n";
  o << "- seed: " << spec.seed << "\n";
  if (spec.kind == StudyKind::kOptimize || spec.kind == StudyKind::kPareto) {
    o << "- solver: " << spec.solver.library;
    if (spec.solver.library != "ipopt") o << " " << spec.solver.algorithm;
    if (!spec.solver.local_algorithm.empty()) o << " (local " << spec.solver.local_algorithm << ")";
    o << ", at most " << spec.solver.max_evaluations << " evaluations";
    if (spec.solver.starts > 1) o << ", " << spec.solver.starts << " starts";
    o << "\n";
  }
  if (spec.kind == StudyKind::kPareto) {
    o << "- front: "
      << (spec.pareto.method == solvers::Scalarization::kEpsilonConstraint ? "eps-constraint" : "weighted sum")
      << ", " << spec.pareto.points << " points requested\n";
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
      o << "| `" << v.key << "` | " << variable_display(v, v.lower) << " | " << variable_display(v, v.upper)
        << " | " << (v.start ? variable_display(v, *v.start) : "–") << " | " << (values.empty() ? "continuous" : values)
        << " |\n";
    }
    o << "\n";
  }
  if (!spec.objectives.empty()) {
    o << "## Objectives\n\n";
    for (const auto& ob : spec.objectives) o << "- " << (ob.maximize ? "maximize " : "minimize ") << ob.label << "\n";
    o << "\n";
  }
  if (!spec.constraints.empty()) {
    o << "## Constraints\n\n";
    for (const auto& c : spec.constraints) o << "- " << bound_text(c) << "\n";
    o << "\n";
  }

  o << "## Outcome\n\n";
  o << "**Status: " << result.status << "**: " << status_message(spec, result) << "\n\n";
  if (!result.solver_message.empty()) o << "Solver: " << md_cell(result.solver_message) << "\n\n";
  if (spec.kind == StudyKind::kPareto && !result.front.empty()) {
    o << "### Pareto front (" << result.front.size() << " points)\n\n| # | chosen |";
    for (const auto& v : spec.variables) o << " `" << v.key << "` |";
    for (const auto& ob : spec.objectives) o << " " << ob.label << " |";
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
    if (result.chosen && *result.chosen < result.front.size()) {
      o << "### Chosen design (front point " << *result.chosen << ")\n\n";
      md_design(o, spec, result.front[*result.chosen]);
    }
  } else if (result.best) {
    const bool single = spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability;
    o << (single ? "### Design" : "### Best design") << (result.best->label.empty() ? "" : " (" + result.best->label + ")") << "\n\n";
    md_design(o, spec, *result.best);
    o << explanation_markdown(spec, result) << per_combination_markdown(spec, result);
  }
  if (result.least_infeasible) {
    o << "### Least infeasible design"
      << (result.least_infeasible->label.empty() ? "" : " (" + result.least_infeasible->label + ")") << "\n\n";
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
  const std::size_t fresh = result.evaluations >= result.reused_evaluations
                                ? result.evaluations - result.reused_evaluations
                                : 0;
  o << "- evaluations: " << result.evaluations << " (" << result.failed_evaluations << " failed, "
    << result.reused_evaluations << " taken from the store on resume)\n";
  o << "- wall time of this run: " << short_num(result.seconds) << " s";
  if (fresh > 0) o << " (" << short_num(result.seconds * 1000.0 / static_cast<double>(fresh)) << " ms per new evaluation)";
  o << "\n\n";

  {
    const std::vector<std::string> listed = best_first(result, warnings);
    const std::size_t own = result.best ? result.best->warnings.size() : 0;
    if (own > 0) o << "## Warnings of the best design\n\n";
    for (std::size_t i = 0; i < listed.size(); ++i) {
      if (i == own) o << (own > 0 ? "\n## Other warnings of the run\n\n" : "## Warnings\n\n");
      o << "- " << md_cell(listed[i]) << "\n";
    }
    if (!listed.empty()) o << "\n";
  }

  o << "## Files\n\n";
  for (const auto& [role, path] : files.entries) {
    if (role == "report_md" || !fs::exists(path)) continue;
    const std::string target = link_target(out_dir, path);
    o << "- [" << fs::path(path).filename().string() << "](" << target << "): " << role << "\n";
  }
  o << "\n";
  bool any_plot = false;
  for (const auto& [role, path] : files.entries) {
    if (fs::path(path).extension() != ".png" || !fs::exists(path)) continue;
    if (!any_plot) o << "## Plots\n\n";
    any_plot = true;
    o << "![" << role << "](" << link_target(out_dir, path) << ")\n\n";
  }
  return o.str();
}

}  // namespace

// ---- public -------------------------------------------------------------------

std::string metric_display(const std::string& label, double value_si) {
  const MetricUnit u = metric_unit(label);
  if (!std::isfinite(value_si)) return short_num(value_si);
  if (u.def != nullptr && u.def->kind) return format_quantity(value_si, *u.def->kind, u.display, 4);
  const std::string n = format_number(value_si, 4);
  return u.display.empty() ? n : n + " " + u.display;
}

std::string variable_display(const DesignVariable& v, double value_si) {
  if (!std::isfinite(value_si)) return short_num(value_si);
  if (v.kind == QuantityKind::kCount) return format_number(std::round(value_si), 12);
  const VariableUnit u = variable_unit(v);
  return format_quantity(value_si, v.kind, u.display, 6);
}

std::string status_message(const StudySpec& spec, const StudyResult& r) {
  const std::string n = std::to_string(r.evaluations) + " evaluation" + (r.evaluations == 1 ? "" : "s");
  if (r.status == "stopped") {
    return "stopped after " + n + "; the results so far are written. Continue with --resume (same --out).";
  }
  if (r.status == "no_feasible_point") {
    std::string s = "no feasible design in " + n + ".";
    if (r.least_infeasible) {
      s += " The least infeasible design (" + r.least_infeasible->label + ") violates the constraints by " +
           short_num(r.least_infeasible->max_violation) + " (normalized).";
    }
    return s;
  }
  if (r.status == "all_failed") {
    std::string s = "every one of the " + n + " failed.";
    const DesignResult* d = r.least_infeasible ? &*r.least_infeasible : (r.best ? &*r.best : nullptr);
    if (d != nullptr && !d->message.empty()) s += " First reason: " + d->message;
    return s;
  }
  std::string s;
  if (r.status == "ok") {
    s = "done, " + n + ".";
  } else if (r.status == "converged") {
    s = "converged after " + n + ".";
  } else if (r.status == "max_evaluations") {
    s = "evaluation budget reached (" + n + ").";
  } else if (r.status == "max_time") {
    s = "time limit reached after " + n + ".";
  } else {
    s = r.status + " after " + n + ".";
  }
  if (spec.kind == StudyKind::kSweep) {
    const std::size_t feasible = feasible_points(r);
    s += " " + std::to_string(feasible) + " of " + std::to_string(r.sweep_points.size()) + " points feasible.";
  }
  if (spec.kind == StudyKind::kPareto) {
    s += " " + std::to_string(r.front.size()) + " front point" + (r.front.size() == 1 ? "" : "s") + ".";
  } else if (r.best && (spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability)) {
    s += r.best->ok ? (r.best->feasible ? " The design is feasible." : " The design violates the constraints.")
                    : " The design failed: " + r.best->message;
  } else if (r.best) {
    s += r.best->feasible ? " Best feasible design shown." : " Best design shown.";
  } else if (r.least_infeasible) {
    s += " No feasible design: the least infeasible one is shown.";
  }
  return s;
}

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
  j.key("status").value(result.status);
  j.key("message").value(status_message(spec, result));
  j.key("solver_message").value(result.solver_message);
  j.key("feasible").value(result.best.has_value() && result.best->feasible);

  j.key("variables").begin_array();
  for (const auto& v : spec.variables) {
    j.begin_object();
    j.key("name").value(v.key);
    j.key("unit").value(si_unit(v.kind));
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
  }
  if (spec.kind == StudyKind::kSweep) {
    const std::size_t feasible = feasible_points(result);
    j.key("sweep_points").value(static_cast<long>(result.sweep_points.size()));
    j.key("feasible_points").value(static_cast<long>(feasible));
  }
  if (result.reliability && result.best_drive) {
    // The same object `rackopt wear --json` prints for this design: life,
    // life at R, R(t), the chosen fit with its KS statistic, exact quantiles.
    WearFiles wf;
    wf.wear_profile_csv = files.get("wear_profile_csv");
    wf.life_samples_csv = files.get("life_samples_csv");
    wf.reliability_csv = files.get("reliability_csv");
    wf.histogram_csv = files.get("life_histogram_csv");
    wf.wear_profile_png = files.get("wear_profile_png");
    wf.histogram_png = files.get("life_histogram_png");
    wf.reliability_png = files.get("reliability_png");
    j.key("reliability").raw(wear_json(*result.best_drive, *result.reliability, wf, 0.0));
  }
  optimum_json(j, spec, result, [](JsonWriter& w, const StudySpec& sp, const DesignResult& d) {
    json_design(w, sp, d, std::nullopt);
  });
  fe_verification_json(j, spec, result);
  j.key("evaluations").value(static_cast<long>(result.evaluations));
  j.key("failed_evaluations").value(static_cast<long>(result.failed_evaluations));
  j.key("reused_evaluations").value(static_cast<long>(result.reused_evaluations));
  j.key("warnings").begin_array();
  for (const auto& w : best_first(result, warnings.empty() ? result.warnings : warnings)) j.value(w);
  j.end_array();
  const std::size_t fresh =
      result.evaluations >= result.reused_evaluations ? result.evaluations - result.reused_evaluations : 0;
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

StudyReport write_study_report(const StudySpec& spec, const StudyResult& result, const std::string& out_dir_text) {
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path dir(out_dir_text.empty() ? std::string(".") : out_dir_text);
  fs::create_directories(dir);
  StudyReport rep;
  rep.warnings = result.warnings;
  std::vector<std::string> plot_warnings;

  auto write = [&](const std::string& name, const std::string& content) {
    const std::string path = (dir / name).string();
    write_file_atomic(path, content);
    rep.written.push_back(path);
    return path;
  };
  auto plot = [&](const std::string& role, const std::string& script_name, const std::string& script,
                  const std::string& png) {
    if (!spec.output.plots) return;
    write(script_name, script);
    const std::string p = render_plot(dir.string(), script_name, png, plot_warnings);
    if (!p.empty()) {
      rep.files.add(role, p);
      rep.written.push_back(p);
    }
  };

  const std::vector<std::string> labels = metric_labels(spec, result);
  const std::string title = spec.name.empty() ? std::string("study") : spec.name;

  // best.csv: the best design, or the least infeasible one when none is feasible.
  {
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
    if (!rows.empty()) {
      rep.files.add("best_csv", write("best.csv", design_table(spec, labels, rows, {"role"}, roles).text));
    }
  }

  DesignTable front_table;
  if (spec.kind == StudyKind::kPareto && !result.front.empty()) {
    std::vector<const DesignResult*> rows;
    std::vector<std::vector<std::string>> lead;
    for (std::size_t k = 0; k < result.front.size(); ++k) {
      rows.push_back(&result.front[k]);
      lead.push_back({std::to_string(k), result.chosen && *result.chosen == k ? "1" : "0"});
    }
    front_table = design_table(spec, labels, rows, {"point", "chosen"}, lead);
    rep.files.add("front_csv", write("front.csv", front_table.text));
  }

  DesignTable sweep_table;
  if (!result.sweep_points.empty()) {
    std::vector<const DesignResult*> rows;
    std::vector<std::vector<std::string>> lead;
    for (std::size_t k = 0; k < result.sweep_points.size(); ++k) {
      rows.push_back(&result.sweep_points[k]);
      lead.push_back({std::to_string(k)});
    }
    sweep_table = design_table(spec, labels, rows, {"point"}, lead);
    rep.files.add("sweep_csv", write("sweep.csv", sweep_table.text));
  }

  bool any_history = false;
  for (double h : result.best_history) any_history = any_history || std::isfinite(h);
  if (!result.best_history.empty() && !spec.objectives.empty()) {
    const std::string& label = spec.objectives[0].label;
    const MetricUnit u = metric_unit(label);
    const bool display_col = !u.display.empty() && u.display != u.si && u.factor != 1;
    std::ostringstream o;
    o << "evaluation," << csv_field("best_" + metric_col(label));
    if (display_col) o << "," << csv_field("best_" + with_suffix(label, u.display));
    o << "\n";
    for (std::size_t i = 0; i < result.best_history.size(); ++i) {
      const double h = result.best_history[i];
      o << (i + 1) << "," << num(h);
      if (display_col) o << "," << (std::isfinite(h) ? num(h / u.factor) : "");
      o << "\n";
    }
    rep.files.add("history_csv", write("history.csv", o.str()));
  }

  // Stiffness curve of the best / chosen design.
  if (spec.output.stiffness_curve && result.best_drive) {
    try {
      const MeshStiffnessModel model(*result.best_drive);
      const StiffnessCurve curve = model.curve();
      rep.files.add("stiffness_csv", write("stiffness.csv", stiffness_csv(curve)));
      const std::string which = spec.kind == StudyKind::kPareto ? "chosen design" : "best design";
      plot("stiffness_png", "stiffness.gp",
           stiffness_gnuplot(curve, title + ": stiffness of the " + which, "stiffness.csv", "stiffness.png.tmp"),
           "stiffness.png");
    } catch (const DesignError& e) {
      plot_warnings.push_back(std::string("no stiffness curve of the best design (") + e.code() + "): " + e.what());
    }
  }

  // reliability: the files of `rackopt wear` for the study's design.
  if (result.reliability && result.best_drive) {
    const Drive& drive = *result.best_drive;
    const WearReliabilityResult& r = *result.reliability;
    rep.files.add("wear_profile_csv", write("wear_profile.csv", wear_profile_csv(r.nominal)));
    plot("wear_profile_png", "wear_profile.gp", wear_profile_gnuplot(title), "wear_profile.png");
    if (!r.lives.empty()) {
      rep.files.add("life_samples_csv", write("life_samples.csv", life_samples_csv(r)));
      rep.files.add("reliability_csv", write("reliability.csv", reliability_csv(drive, r)));
      rep.files.add("life_histogram_csv", write("life_histogram.csv", life_histogram_csv(r)));
      plot("life_histogram_png", "life_histogram.gp", life_histogram_gnuplot(title), "life_histogram.png");
      plot("reliability_png", "reliability.gp", reliability_gnuplot(title), "reliability.png");
    }
  }

  write_fe_verification_files(spec, result, rep.files, write, plot);

  const std::size_t n_obj = spec.objectives.size();
  if (!front_table.text.empty() && (n_obj == 2 || n_obj == 3)) {
    plot("pareto_png", "pareto.gp", pareto_gnuplot(spec, front_table, result.evaluations_csv_path), "pareto.png");
  }
  if (any_history && !spec.objectives.empty()) {
    plot("history_png", "history.gp", history_gnuplot(spec, spec.objectives[0].label, result.best_history.size()), "history.png");
  }
  if (!sweep_table.text.empty() && !spec.variables.empty() && !labels.empty()) {
    plot("sweep_png", "sweep.gp", sweep_gnuplot(spec, sweep_table, labels), "sweep.png");
  }
  if (!result.evaluations_csv_path.empty() && fs::exists(result.evaluations_csv_path)) {
    rep.files.add("evaluations_csv", result.evaluations_csv_path);
  }
  if (!result.database_path.empty() && fs::exists(result.database_path)) {
    rep.files.add("database", result.database_path);
  }
  for (const auto& w : plot_warnings) rep.warnings.push_back(w);

  const std::string report_path = (dir / "report.md").string();
  const std::string summary_path = (dir / "summary.json").string();
  if (spec.output.report) {
    std::string md = report_markdown(spec, result, rep.files, rep.warnings, dir);
    // summary.json does not exist yet: link it by hand (it will, below).
    md += "Summary for programs: [summary.json](summary.json)\n";
    rep.files.add("report_md", write("report.md", md));
  }
  rep.files.add("summary_json", summary_path);
  ReportTimings timings;
  timings.run_seconds = result.seconds;
  timings.report_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rep.summary_json = study_summary_json(spec, result, rep.files, timings, rep.warnings);
  write("summary.json", rep.summary_json + "\n");
  return rep;
}

}  // namespace rackopt::study
