// The solver Problem of a study: maps a solver vector to a design, evaluates
// the study's named metrics once per design and turns them into objectives
// and constraints.
//
// Variables as the solver sees them: only the CONTINUOUS design variables,
// each normalized to [0, 1] (u = (x - lower) / (upper - lower)). Module in
// metres and span in metres differ by 100x; on a unit box COBYLA's initial
// step, the relative x tolerance and the finite-difference step mean the
// same for every variable. Discrete variables are either not seen by the
// solver: fixed per enumerated combination (for_combination), the
// continuous rest optimized for each; or, for an algorithm that searches
// whole-valued variables (with_discrete_as_integers), seen as the index into
// their list of values, after the continuous ones.
//
// Mapping of one design (all metric values v in SI):
//   objective i:   (maximize ? -v : v) / scale_i
//   constraint:    (min - v)/s <= 0,  (v - max)/s <= 0,  (v - equals)/s == 0,
//                  in StudySpec::constraints order, min before max;
//                  s = ConstraintSpec::scale, else |bound|, else 1.
// A metric that fails makes the whole evaluation kFailed with its code and
// message (never NaN, never thrown).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/solvers/problem.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

// One design evaluated, with everything the recorder and the report need.
struct DesignEvaluation {
  std::vector<double> x;              // full SI design, one per StudySpec::variables entry
  std::vector<double> metric_values;  // SI, StudySpec::all_metrics() order; 0 where !metric_ok
  std::vector<bool> metric_ok;
  solvers::Evaluation evaluation;     // as the solver sees it (scaled, minimized)
  std::vector<std::string> warnings;  // model warnings of this design
  std::vector<std::string> models;    // the models computed for it ("geometry", "stiffness_curve", ...)
  double seconds = 0;                 // wall time of the model evaluation (0 when rebuilt)
};

// What the models say of one design, before the study maps it to what the
// solver sees: the part of an evaluation that can be computed anywhere (a
// thread, another MPI rank) and sent back as it is (design_wire.hpp).
struct DesignMetrics {
  std::vector<double> x;              // full SI design
  std::vector<double> metric_values;  // SI, StudySpec::all_metrics() order; 0 where !metric_ok
  std::vector<bool> metric_ok;
  std::string failure;                // why the design failed ("" when every metric is ok)
  std::vector<std::string> warnings;  // model warnings of this design
  std::vector<std::string> models;    // the models computed for it ("geometry", "stiffness_curve", ...)
  double seconds = 0;                 // wall time of the models
};

class StudyProblem final : public solvers::Problem {
 public:
  // Loads the problem file (spec.problem_path with spec.problem_overrides)
  // and sets up the combination 0 view. Objective scales are those of the
  // spec; automatic ones (scale 0) stay 1 until set_objective_scales.
  // Throws InputError for a problem file the loader refuses. The spec is
  // copied.
  explicit StudyProblem(const StudySpec& spec);

  // The same study with the discrete variables at combination `c`
  // (0 <= c < num_combinations()); shares the loaded problem.
  StudyProblem for_combination(std::size_t c) const;
  // The same study with every discrete variable of two or more values as a
  // whole-valued solver variable (the index into its values, bounds
  // [0, values - 1]) after the continuous ones; a one-value variable keeps
  // its value. Shares the loaded problem.
  StudyProblem with_discrete_as_integers() const;
  bool discrete_as_integers() const { return integers_; }
  // The combination (as numbered by for_combination) of a full SI design
  // whose discrete variables hold values of their lists.
  std::size_t combination_of(std::span<const double> x_si) const;

  const StudySpec& spec() const;
  const ProblemTree& tree() const;
  const std::vector<metrics::MetricRequest>& metric_requests() const;  // spec.all_metrics()
  const std::vector<std::string>& metric_labels() const;               // their labels
  std::vector<std::string> variable_keys() const;                      // every variable, spec order
  const std::vector<std::size_t>& continuous_indices() const;          // into spec.variables
  const std::vector<std::size_t>& discrete_indices() const;

  // Cartesian product of the discrete variables' values (1 when there is
  // none); the last discrete variable varies fastest.
  std::size_t num_combinations() const;
  std::size_t combination() const;
  // "pinion.module=25 mm, pinion.teeth=22" ("" when there is no discrete variable).
  std::string combination_label() const;

  // The start design (full SI): continuous variables at start, else the
  // midpoint of their bounds; discrete ones at start, else this view's
  // combination value.
  std::vector<double> start_design() const;
  // The start design's continuous part, normalized (the solver's x0).
  std::vector<double> start_unit() const;
  // Solver vector -> full SI design (discrete ones from this combination).
  // u is clamped into [0, 1]; u = 0 and u = 1 give lower/upper exactly.
  std::vector<double> to_design(std::span<const double> u) const;

  // Automatic scales: |value| of each objective metric in `start` when that
  // value is ok and non-zero, else 1; explicit spec scales are kept.
  void set_objective_scales_from(const DesignEvaluation& start);
  const std::vector<double>& objective_scales() const;

  // The Drive of a full SI design. Throws what drive_with_values throws.
  Drive drive_at(std::span<const double> x_si) const;

  // Evaluates a full SI design. Thread-safe, deterministic. A design the
  // loader refuses (InputError from a range check) or a model rejects is a
  // kFailed evaluation with the reason; `metric_options_threads` sets the
  // Monte Carlo threads of wear_life_at_R (results do not depend on it).
  DesignEvaluation evaluate_design(std::span<const double> x_si, unsigned metric_options_threads = 1) const;
  // The two halves of evaluate_design: the models' part, and the mapping
  // with this view's objective scales (to_evaluation(compute_metrics(x))
  // is evaluate_design(x), bit for bit).
  DesignMetrics compute_metrics(std::span<const double> x_si, unsigned metric_options_threads = 1) const;
  DesignEvaluation to_evaluation(DesignMetrics m) const;

  // The solver evaluation from metric values (as evaluate_design maps them);
  // used to rebuild a recorded evaluation bit for bit. `failure` is the
  // message when some metric is not ok.
  solvers::Evaluation map_metrics(std::span<const double> values, const std::vector<bool>& ok,
                                  const std::string& failure) const;

  // solvers::Problem: the normalized continuous variables.
  std::size_t dimension() const override;
  std::vector<std::string> variable_names() const override;
  std::vector<double> lower_bounds() const override;
  std::vector<double> upper_bounds() const override;
  std::size_t num_objectives() const override;
  std::size_t num_inequality() const override;
  std::size_t num_equality() const override;
  std::size_t num_integer() const override;
  solvers::Evaluation evaluate(std::span<const double> u) const override;

 private:
  struct Shared;
  std::shared_ptr<const Shared> shared_;
  bool integers_ = false;
  std::size_t combination_ = 0;
  std::vector<double> combination_values_;  // per discrete index
  std::vector<double> objective_scales_;
};

}  // namespace rackopt::study
