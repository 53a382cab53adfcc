// What a study run produces, as the report, the CLI and the tests read it:
// one design (DesignResult), one discrete combination's outcome, the whole
// StudyResult, and the progress the runner reports while it works. The run
// itself is study_runner.hpp; presenting it is study_report/study_report.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/study/front_summary.hpp"
#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study/study_status.hpp"
#include "rackopt/study/sweep_sensitivity.hpp"
#include "rackopt/study/warning_groups.hpp"

namespace rackopt::study {

// One design as the report shows it.
struct DesignResult {
  std::vector<double> x;                 // SI, one per StudySpec::variables entry
  std::vector<std::string> metric_labels;  // StudySpec::all_metrics() labels, in order
  std::vector<double> metric_values;     // SI, same order; 0 where !metric_ok
  std::vector<bool> metric_ok;
  std::vector<double> objectives;        // in the metric's own sense and unit (not negated, not scaled)
  double max_violation = 0;              // largest normalized constraint violation (0 = feasible), +inf when failed
  bool ok = false;                       // every metric computed
  bool feasible = false;                 // ok and max_violation <= solver.constraint_tolerance
  std::string message;                   // why it failed, or remarks
  std::vector<std::string> warnings;     // this design's own model warnings (also when taken from the store)
  std::string label;                     // "start 0", "front 3 (eps 2)", "sweep 17", "combination 2: pinion.module=25 mm"
  std::int64_t evaluation_id = 0;        // its `id` in evaluations.csv; 0 when not recorded
};

// One discrete combination's outcome in an optimize study.
struct CombinationOutcome {
  std::string label;                         // "pinion.module=4 mm"
  std::optional<solvers::SolverStatus> status;  // how its solve ended; nullopt when not run (stopped before it)
  std::optional<DesignResult> best;          // best feasible design of the combination
  std::optional<DesignResult> least_infeasible;  // when none is feasible
};

struct StudyResult {
  StudyStatus status = StudyStatus::kOk;  // how the study ended (study_status.hpp)
  std::optional<DesignResult> best;            // optimize: best feasible design; evaluate/reliability:
                                               // the design (even when infeasible or failed);
                                               // sweep: best feasible by objective 0 (if any objective);
                                               // pareto: the chosen front point
  std::optional<DesignResult> least_infeasible;  // when no feasible design was found
  std::vector<DesignResult> front;             // pareto: feasible, non-dominated, sorted by objective 0
  std::optional<std::size_t> chosen;           // pareto: index into front of the chosen design
  std::optional<FrontSummary> front_summary;   // pareto: quality, hypervolume history, shortfall
  std::vector<DesignResult> sweep_points;      // sweep: every point in sampler order
  std::vector<double> best_history;            // best feasible objective 0 (own sense) after each evaluation
  std::size_t evaluations = 0;                 // model evaluations this study needed (recorded + new)
  std::size_t reused_evaluations = 0;          // of which taken from the store on --resume
  std::size_t damaged_records = 0;             // recorded rows that failed their checksum on --resume:
                                               // removed, their designs evaluated again
  std::size_t unchecked_records = 0;           // recorded rows from before checksums, reused unchecked
  std::size_t failed_evaluations = 0;
  std::string solver_message;
  // With status kStopped: what the stop interrupted when it was not the
  // evaluations themselves ("the reliability analysis of the design", "the
  // FE verification of the best design"), for the report; else empty.
  std::string stopped_during;
  std::vector<std::string> warnings;           // model warnings, listed once, in the order the designs
                                               // were first used (the same after --resume)
  std::vector<WarningGroup> warning_groups;    // every design's model warnings by kind, first-use order
  std::size_t warning_kinds_dropped = 0;       // warnings of kinds beyond kMaxWarningKinds (only counted)
  double seconds = 0;                          // wall time of this run
  std::string database_path;                   // <out>/evaluations.sqlite
  std::string evaluations_csv_path;            // <out>/evaluations.csv, written by run_study from the store
  // The drive of `best` (optimize/evaluate/reliability) or of the chosen
  // front point (pareto): the report writes and plots its stiffness curve.
  std::shared_ptr<const Drive> best_drive;
  // The stiffness curve of best_drive, computed by the runner
  // (best_design_curve.hpp) so that the report never runs a model. Empty
  // unless spec.output.stiffness_curve is on and best_drive is set, and
  // empty when the model refused the design: best_curve_error then holds
  // the warning the report lists ("no stiffness curve of the best design
  // (<code>): <message>").
  std::shared_ptr<const StiffnessCurve> best_curve;
  std::string best_curve_error;
  // reliability: the full wear reliability analysis of the design, for the
  // same CSVs and plots as `rackopt wear` (output/wear_report.hpp).
  std::shared_ptr<const WearReliabilityResult> reliability;
  // optimize with discrete variables: the best design of each combination
  // (feasible, else the least infeasible, else none), combination order.
  std::vector<CombinationOutcome> per_combination;
  // optimize: why the best design is the optimum (binding constraints,
  // variables at bounds, gradients, multipliers).
  std::optional<OptimumExplanation> explanation;
  // The fidelity settings the models ran with (name, value as text).
  std::vector<std::pair<std::string, std::string>> fidelity;
  // sweep: Sobol ranking of the variables for every metric, from the points.
  std::vector<MetricSensitivity> sensitivity;
  // `verify: fe` (study/fe_verification.hpp): the FE comparison of best_drive,
  // or why there is none (no design to verify, the solver missing or failed).
  std::shared_ptr<const fe::FeComparison> fe_verification;
  std::string fe_verification_error;
};

// Progress as the runner reports it (for the progress bar).
struct Progress {
  std::size_t done = 0, budget = 0;     // evaluations done, planned total (0 = unknown)
  std::size_t failed = 0;
  std::optional<double> best;           // best feasible objective 0 so far, own sense
  std::string phase;                    // "anchor 1", "combination 2/6", "sweep"
};

}  // namespace rackopt::study
