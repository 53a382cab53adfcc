// Helpers the tests of tests/study_report share (one unity batch compiles
// several of its files together, so each helper is defined once, here): CSV
// tables, a synthetic study whose metrics are simple functions of the design,
// and report.md's links. Scratch folders and file text come from
// tests/support/.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study/warning_groups.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"
#include "support/shipped_problems.hpp"

namespace {

namespace fs = std::filesystem;
using namespace rackopt;
using namespace rackopt::study;
using namespace rackopt::study_report;

using rackopt::test_support::read_text;
using rackopt::test_support::scratch_path;

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::string cell;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        row.push_back(cell);
        cell.clear();
      } else {
        cell += c;
      }
    }
    row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  return -1;
}

bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

ObjectiveSpec objective(const std::string& text, bool maximize = false) {
  ObjectiveSpec o;
  o.metric = metrics::resolve_request(metrics::parse_metric_request(text));
  o.label = metrics::to_string(o.metric);
  o.maximize = maximize;
  return o;
}

ConstraintSpec constraint_min(const std::string& text, double min) {
  ConstraintSpec c;
  c.metric = metrics::resolve_request(metrics::parse_metric_request(text));
  c.label = metrics::to_string(c.metric);
  c.min = min;
  return c;
}

DesignVariable variable(const std::string& key, QuantityKind kind, const std::string& unit, double lo, double hi) {
  DesignVariable v;
  v.key = key;
  v.kind = kind;
  v.unit = unit;
  v.lower = lo;
  v.upper = hi;
  return v;
}

// Two variables (module in mm, span in m), objective stiffness_fluctuation,
// constraint contact_ratio >= 1.3, extra metric min_stiffness.
StudySpec base_spec(StudyKind kind) {
  StudySpec s;
  s.name = "synthetic";
  s.file = "synthetic.yaml";
  s.description = "A made-up study whose metrics are simple functions of x.";
  s.kind = kind;
  s.problem_path = test_support::shipped_problem_path("rack_railway.yaml");
  s.variables.push_back(variable("pinion.module", QuantityKind::kLength, "mm", 0.02, 0.032));
  s.variables.push_back(variable("rack.span", QuantityKind::kLength, "m", 1.2, 3.0));
  s.objectives.push_back(objective("stiffness_fluctuation"));
  s.constraints.push_back(constraint_min("contact_ratio", 1.3));
  s.report_metrics.push_back(metrics::parse_metric_request("min_stiffness"));
  return s;
}

// A design whose metrics are simple functions of x, so every number in the
// report can be traced back: fluctuation = module*10 + span/100,
// contact_ratio = 1 + span/4, min_stiffness = 1e8 * module.
DesignResult design(const StudySpec& spec, double module, double span, const std::string& label) {
  DesignResult d;
  d.x = {module, span};
  for (const auto& m : spec.all_metrics()) d.metric_labels.push_back(metrics::to_string(m));
  for (const auto& l : d.metric_labels) {
    double v = 0;
    if (l == "stiffness_fluctuation") v = module * 10 + span / 100;
    if (l == "supports_per_metre") v = 1.0 / span;
    if (l == "contact_ratio") v = 1 + span / 4;
    if (l == "min_stiffness") v = 1e8 * module;
    d.metric_values.push_back(v);
    d.metric_ok.push_back(true);
  }
  for (const auto& o : spec.objectives) {
    for (std::size_t i = 0; i < d.metric_labels.size(); ++i) {
      if (d.metric_labels[i] == o.label) d.objectives.push_back(d.metric_values[i]);
    }
  }
  const double cr = 1 + span / 4;
  d.max_violation = std::max(0.0, (1.3 - cr) / 1.3);
  d.ok = true;
  d.feasible = d.max_violation <= 1e-6;
  d.label = label;
  return d;
}

// A front of `points` designs from (20 mm, 3 m) to (32 mm, 1.2 m), point
// `chosen` chosen, over 200 evaluations.
StudyResult pareto_result(const StudySpec& spec, std::size_t points, std::size_t chosen) {
  StudyResult r;
  r.status = study::StudyStatus::kOk;
  for (std::size_t k = 0; k < points; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(points - 1);
    r.front.push_back(design(spec, 0.02 + 0.012 * t, 3.0 - 1.8 * t, "eps " + std::to_string(k)));
  }
  r.chosen = chosen;
  r.evaluations = 200;
  r.seconds = 1.0;
  r.best_history = std::vector<double>(200, 0.3);
  return r;
}

// An optimize study as the runner leaves it after 448 designs that each
// warn of an undercut with their own numbers (the gantry study's case),
// three of which also warn of a cutter tip radius; the best design is
// evaluation 17 and has, besides its undercut, a remark of its own.
StudyResult near_duplicate_warnings_result(const StudySpec& spec) {
  StudyResult r;
  r.status = study::StudyStatus::kConverged;
  r.evaluations = 448;
  r.best = design(spec, 0.025, 2.0, "combination 3");
  r.best->evaluation_id = 17;
  r.best_history = {0.5};
  WarningTally tally;
  std::vector<std::string> distinct;
  for (int id = 1; id <= 448; ++id) {
    std::vector<std::string> w = {"pinion undercut: z = " + std::to_string(10 + id % 9) + " < z_min = " +
                                  std::to_string(17 + id % 5) + "." + std::to_string(id % 10)};
    if (id % 100 == 0) w.push_back("cutter tip radius 0." + std::to_string(id / 100) + " mm is larger than the rack's");
    if (id == 17) {
      w.push_back("the best design's own remark");
      r.best->warnings = w;
    }
    tally.add(w, id);
    for (const auto& m : w)
      if (std::find(distinct.begin(), distinct.end(), m) == distinct.end()) distinct.push_back(m);
  }
  r.warning_groups = tally.groups();
  // The runner's flat list: at most 20 distinct messages and a count of the rest.
  r.warnings.assign(distinct.begin(), distinct.begin() + 20);
  r.warnings.push_back("... and " + std::to_string(distinct.size() - 20) + " more distinct model warnings");
  return r;
}

// How often `what` occurs in `text` (not overlapping).
std::size_t occurrences_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Every link target of report.md, relative to its folder.
std::vector<std::string> markdown_links(const std::string& md) {
  // (no std::regex: GCC 12 warns inside it under the sanitizer build)
  std::vector<std::string> out;
  for (std::size_t at = md.find("]("); at != std::string::npos; at = md.find("](", at + 2)) {
    const std::size_t end = md.find(')', at + 2);
    if (end == std::string::npos) break;
    out.push_back(md.substr(at + 2, end - at - 2));
  }
  return out;
}

void expect_links_exist(const std::string& dir) {
  const std::string md = read_text(dir + "/report.md");
  ASSERT_FALSE(md.empty());
  const auto links = markdown_links(md);
  EXPECT_FALSE(links.empty());
  for (const auto& l : links) {
    const fs::path p = fs::path(l).is_absolute() ? fs::path(l) : fs::path(dir) / l;
    EXPECT_TRUE(fs::exists(p)) << "report.md links a missing file: " << l;
  }
}

}  // namespace
