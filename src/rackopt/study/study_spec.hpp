// A study: which problem, which design variables, which objectives and
// constraints, which solver or sampler, and where results go. Read from a
// study file (studies/*.yaml, reference in docs/studies.md) by
// load_study_file (rackopt/studyfile/study_loader.hpp); everything here is in SI units and already checked, so
// the runner never meets a bad value.
//
// Example study file (studies/rack_railway_sizing.yaml is the full one):
//   study: {name: railway sizing, kind: optimize, seed: 1}
//   problem: ../problems/rack_railway.yaml      # relative to the study file
//   variables:
//     pinion.pressure_angle: {lower: 14 deg, upper: 25 deg, start: 20 deg}
//     pinion.module: {values: [20 mm, 25 mm, 32 mm]}   # discrete: enumerated
//     rack.span: {lower: 1.2 m, upper: 3 m}
//   objectives: [stiffness_fluctuation]                # or {metric: ..., sense: maximize}
//   constraints:
//     - {metric: contact_ratio, min: 1.3}
//     - {metric: min_stiffness_ks, min: 24 MN/m}
//   solver: {library: nlopt, algorithm: LN_COBYLA, max_evaluations: 400}
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "rackopt/solvers/solver.hpp"
#include "rackopt/study/fe_verify_spec.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt::study {

// evaluate:    the metrics of one design (variables at `start`, or the problem's own values)
// sweep:       metrics over a grid / Latin hypercube / Sobol set of designs
// optimize:    minimize one objective under constraints (NLopt or Ipopt)
// pareto:      2 or 3 objectives, front by eps-constraint or weighted sum
// reliability: wear life at reliability R of one design, full Monte Carlo
//              report (the `rackopt wear` analysis with the study's design)
enum class StudyKind { kEvaluate, kSweep, kOptimize, kPareto, kReliability };

// "evaluate", "sweep", ...
const char* kind_name(StudyKind kind);

// A numeric problem key the study varies.
struct DesignVariable {
  std::string key;              // problem key path, e.g. "pinion.module", "wear.rack_hardness.case_depth"
  QuantityKind kind = QuantityKind::kDimensionless;  // from problem_key_kind(key)
  std::string unit;             // display unit: the unit the study file used for the bounds
                                // (or the kind's default unit); results are shown in it
  // Continuous variable: lower < upper (SI). Discrete variable: lower/upper
  // are the smallest and largest of `values`.
  double lower = 0, upper = 0;
  std::vector<double> values;   // discrete set, SI, strictly ascending; empty = continuous
  std::optional<double> start;  // x0 (SI), inside [lower, upper]; a member of `values` when discrete
  std::optional<int> levels;    // sweep grid levels of a continuous variable (absent: sweep.levels)
  SourceMark mark;              // where the variable is declared

  bool discrete() const { return !values.empty(); }
};

// One objective. The runner minimizes `maximize ? -value : value`
// (scaled, see `scale`); results are reported in the metric's own sense.
struct ObjectiveSpec {
  metrics::MetricRequest metric;  // resolved (default parameter filled in)
  std::string label;              // metrics::to_string(metric)
  bool maximize = false;
  // Divisor applied before the solver sees the value (solvers are happier
  // with objectives of order 1). 0 = automatic: |value at the start design|
  // when that evaluation succeeds and is not 0, else 1.
  double scale = 0;
  SourceMark mark;
};

// A bound on a metric: min <= value <= max, or value == equals. Each given
// bound becomes one constraint of the solver Problem, normalized by `scale`:
//   (min - value) / scale <= 0,   (value - max) / scale <= 0,   (value - equals) / scale == 0.
struct ConstraintSpec {
  metrics::MetricRequest metric;  // resolved
  std::string label;              // metrics::to_string(metric)
  std::optional<double> min, max, equals;  // SI, in the metric's unit
  // > 0; default: |the bound| (or 1 when the bound is 0): a violation of 0.01
  // is then 1 % of the bound, whatever the metric's unit.
  double scale = 0;
  SourceMark mark;
};

struct SweepSpec {
  enum class Method { kGrid, kLatinHypercube, kSobol };
  Method method = Method::kGrid;
  // kGrid: levels per continuous variable (DesignVariable::levels overrides);
  // discrete variables contribute all their values.
  int levels = 5;
  // kLatinHypercube / kSobol: number of points (discrete variables are
  // snapped to the nearest of their values).
  std::size_t points = 64;
  std::size_t max_points = 100000;  // refuse bigger sweeps before running
};

struct OutputSpec {
  bool plots = true;        // PNGs with gnuplot (skipped with a warning when gnuplot is missing)
  bool report = true;       // report.md linking tables and plots
  // Designs whose stiffness curve is written and plotted: the best design
  // (optimize/evaluate), the chosen front point (pareto). The study loader's
  // default: on when one of the study's metrics reads the stiffness curve.
  bool stiffness_curve = true;
};

struct StudySpec {
  std::string name;          // study.name (default: the file stem)
  SourceMark name_mark;      // where study.name is written (else the study file)
  std::string file;          // study file path as given (for messages)
  std::string description;   // study.description (free text for the report; may be empty)
  StudyKind kind = StudyKind::kEvaluate;
  std::uint64_t seed = 1;    // study.seed: every random choice (LHS, Sobol shift, stochastic solvers, multistart, Monte Carlo)

  // The problem file, resolved against the study file's folder; for a
  // problem the study holds in memory, the name its messages carry.
  std::string problem_path;
  // The problem itself when the study holds it: an inline `problem:` map of
  // the study file, or a problem a program gave load_study_text, with the
  // marks of the text it was parsed from. Null: read problem_path.
  std::shared_ptr<const MarkedNode> problem_root;
  std::vector<std::string> problem_overrides;  // `problem_set:` entries, then CLI --set problem.* ones, "key=value"

  std::vector<DesignVariable> variables;    // may be empty for evaluate/reliability
  std::vector<ObjectiveSpec> objectives;    // optimize: 1; pareto: 2-3; sweep/evaluate: optional (for ranking)
  std::vector<ConstraintSpec> constraints;
  // Extra metrics recorded with every evaluation (not steering anything).
  std::vector<metrics::MetricRequest> report_metrics;
  metrics::MetricOptions metric_options;    // `metric_options:` (exact_quantile, reliability_samples, ...)

  solvers::SolverSettings solver;           // optimize, and every pareto sub-problem
  // pareto: method, points, primary (solver is copied from `solver` by the runner)
  solvers::ParetoSettings pareto;
  // pareto: the front point marked as "chosen" in the report: the one closest
  // (normalized) to the ideal point, or the one minimizing `choose_weights`.
  std::vector<double> choose_weights;       // empty = closest to the ideal point
  SweepSpec sweep;
  OutputSpec output;
  // Discrete variables: enumerate every combination of their values and
  // optimize the continuous rest for each (optimize, pareto); refuse above
  // this many combinations with a message naming them.
  std::size_t max_discrete_combinations = 256;
  // `verify: fe`: the best design compared with the FE reference after the
  // study (not part of the fingerprint: it changes no evaluation).
  std::optional<FeVerifySpec> verify_fe;

  // Every metric the study reads, objectives first, then constraints, then
  // report_metrics, without repeats (by label).
  std::vector<metrics::MetricRequest> all_metrics() const;
};

// A hex hash of everything that changes which designs are evaluated and their
// results: kind, seed, variables, objectives, constraints, report metrics
// (they are recorded with every evaluation), metric options,
// solver/pareto/sweep settings and the problem file's content after the
// overrides. Left out on purpose: the study name, output options, the caps
// sweep.max_points and max_discrete_combinations, and the
// budget (max_evaluations, max_seconds), so that a study can be resumed with
// a bigger budget. Used by the recorder to refuse resuming another study's
// results into the same folder. Same inputs => same text.
std::string study_fingerprint(const StudySpec& spec);

// The output folder a study writes to when none is given: out/<name> with
// every character but letters, digits, '-', '_' and '.' made '_' ("railway
// sizing" -> "out/railway_sizing"), "out/study" for an empty name. Throws
// InputError at study.name when the name is longer than kMaxFolderNameBytes,
// the longest file name the system takes: a folder name cut short or hashed
// would be one the user never wrote and could not find, so the user picks.
inline constexpr std::size_t kMaxFolderNameBytes = 255;
std::string default_out_dir(const StudySpec& spec);

// The study's problem as a tree, its problem_overrides applied: from
// problem_root when the study holds it, else read from problem_path. Throws
// what load_problem_tree_file throws.
ProblemTree study_problem_tree(const StudySpec& spec);

// The format of study_fingerprint, stored beside it in the evaluation store:
// "2" is FNV-1a 64 with the historical basis (core/fnv1a.hpp,
// kStudyFingerprintBasis) over the canonical text of study_fingerprint.cpp
// with each solver library's own settings by key ("1" wrote Ipopt's two
// settings among the common numbers).
// Change it with any change to either, so that a store of the old format is
// refused by name instead of being compared with a fingerprint it cannot match.
inline constexpr const char* kStudyFingerprintFormat = "2";

}  // namespace rackopt::study
