// study_fingerprint: FNV-1a 64 over a canonical text of the study. Doubles are
// written in hex-float (%a) so that two specs that differ in the last bit get
// different fingerprints and the same spec always gives the same text. The
// problem enters as its tree after variant and overrides, without marks, so
// comments and layout of the problem file do not matter, its values do.
#include <cinttypes>
#include <cstdio>
#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/core/fnv1a.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/study/study_spec.hpp"

#include "rackopt/solvers/solver_backend.hpp"

namespace rackopt::study {

namespace {

class Canon {
 public:
  void key(const char* k) {
    text_ += k;
    text_ += '=';
  }
  void num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a;", v);
    text_ += buf;
  }
  void integer(std::uint64_t v) {
    text_ += std::to_string(v);
    text_ += ';';
  }
  void str(const std::string& s) {
    // Length-prefixed: no separator inside a string can fake another field.
    text_ += std::to_string(s.size());
    text_ += ':';
    text_ += s;
    text_ += ';';
  }
  void opt(const std::optional<double>& v) {
    if (v) {
      num(*v);
    } else {
      text_ += "none;";
    }
  }
  void node(const MarkedNode& n) {
    switch (n.type) {
      case MarkedNode::Type::kNull: text_ += "~;"; break;
      case MarkedNode::Type::kScalar: str(n.scalar); break;
      case MarkedNode::Type::kMap:
        text_ += '{';
        for (const auto& e : n.entries) {
          str(e.key);
          node(e.value);
        }
        text_ += '}';
        break;
      case MarkedNode::Type::kSequence:
        text_ += '[';
        for (const auto& i : n.items) node(i);
        text_ += ']';
        break;
    }
  }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace

std::string study_fingerprint(const StudySpec& spec) {
  Canon c;
  c.key("format");
  c.integer(1);
  // The physics the recorded evaluations came from: a store made with an
  // earlier stiffness model must not be resumed as if it were this one.
  c.key("models");
  c.str(kDefaultModelsVersion);
  c.key("kind");
  c.str(kind_name(spec.kind));
  c.key("seed");
  c.integer(spec.seed);
  for (const auto& v : spec.variables) {
    c.key("variable");
    c.str(v.key);
    c.integer(static_cast<std::uint64_t>(v.kind));
    c.num(v.lower);
    c.num(v.upper);
    c.integer(v.values.size());
    for (double x : v.values) c.num(x);
    c.opt(v.start);
    // An absent value is written as the 0 that stood for it, so that the
    // fingerprints of existing records stay what they are.
    c.integer(static_cast<std::uint64_t>(static_cast<std::int64_t>(v.levels.value_or(0))));
  }
  for (const auto& o : spec.objectives) {
    c.key("objective");
    c.str(metrics::to_string(o.metric));
    c.integer(o.maximize ? 1 : 0);
    c.num(o.scale);
  }
  for (const auto& k : spec.constraints) {
    c.key("constraint");
    c.str(metrics::to_string(k.metric));
    c.opt(k.min);
    c.opt(k.max);
    c.opt(k.equals);
    c.num(k.scale);
  }
  for (const auto& r : spec.report_metrics) {
    c.key("report_metric");
    c.str(metrics::to_string(r));
  }
  const metrics::MetricOptions& m = spec.metric_options;
  c.key("metric_options");
  for (double v : {m.load_factors.application, m.load_factors.dynamic, m.load_factors.face_bending,
                   m.load_factors.transverse_bending, m.load_factors.face_contact, m.load_factors.transverse_contact,
                   m.allowable_bending_pinion, m.allowable_bending_rack, m.allowable_contact_pinion,
                   m.allowable_contact_rack, m.rack_root_radius})
    c.num(v);
  c.integer(m.exact_quantile ? 1 : 0);
  // Absent values as the -1, -1 and 0 that stood for them, so that the
  // fingerprints of existing records stay what they are.
  c.integer(static_cast<std::uint64_t>(m.reliability_samples.value_or(-1)));
  c.integer(static_cast<std::uint64_t>(m.reliability_seed.value_or(-1)));
  c.integer(static_cast<std::uint64_t>(m.bootstrap_replicates.value_or(0)));
  // Cost weights only when not the defaults, so the fingerprints of studies
  // that do not use them stay what their records hold.
  const metrics::CostWeights default_cost;
  if (m.cost.rack_per_kg != default_cost.rack_per_kg || m.cost.pinion_per_kg != default_cost.pinion_per_kg ||
      m.cost.per_support != default_cost.per_support || m.cost.rack_length != default_cost.rack_length) {
    c.key("cost");
    for (double v : {m.cost.rack_per_kg, m.cost.pinion_per_kg, m.cost.per_support, m.cost.rack_length}) c.num(v);
  }
  // Only when given, so the fingerprints of studies without it stay what
  // their records hold.
  if (m.positions_per_period) {
    c.key("metric_positions_per_period");
    c.integer(static_cast<std::uint64_t>(*m.positions_per_period));
  }
  // threads: results do not depend on it.

  auto solver = [&](const solvers::SolverSettings& s) {
    // max_evaluations and max_seconds left out: a study may be resumed with a
    // bigger budget. The library's own settings follow, each with its value
    // or default (so spelling a default out changes nothing); settings that
    // only change console output stay out.
    c.str(s.library);
    c.str(s.algorithm);
    c.str(s.local_algorithm);
    for (double v : {s.xtol_rel, s.xtol_abs, s.ftol_rel, s.ftol_abs, s.constraint_tolerance, s.gradient_step})
      c.num(v);
    c.integer(static_cast<std::uint64_t>(s.starts));
    c.integer(s.seed);
    c.integer(s.central_differences ? 1 : 0);
    if (const solvers::SolverBackend* backend = solvers::find_solver_backend(s.library)) {
      for (const solvers::BackendOption& o : backend->options()) {
        if (o.output_only) continue;
        c.key(o.key.c_str());
        c.num(backend->option(s, o.key));
      }
    }
  };
  c.key("solver");
  solver(spec.solver);
  c.key("pareto");
  c.integer(static_cast<std::uint64_t>(spec.pareto.method));
  c.integer(spec.pareto.points);
  c.integer(spec.pareto.primary);
  c.num(spec.pareto.duplicate_tolerance);
  c.key("choose_weights");
  for (double w : spec.choose_weights) c.num(w);
  c.key("sweep");
  c.integer(static_cast<std::uint64_t>(spec.sweep.method));
  c.integer(static_cast<std::uint64_t>(static_cast<std::int64_t>(spec.sweep.levels)));
  c.integer(spec.sweep.points);

  c.key("problem");
  const ProblemTree tree = study_problem_tree(spec);
  c.str(tree.variant);
  c.node(tree.root);

  const std::uint64_t h = fnv1a64(c.text(), kStudyFingerprintBasis);
  char out[17];
  std::snprintf(out, sizeof out, "%016" PRIx64, h);
  return out;
}

}  // namespace rackopt::study
