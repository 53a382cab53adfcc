// Runs a StudySpec: builds the solver Problem from named metrics, drives the
// sampler / optimizer / Pareto scalarization, records every evaluation in
// <out>/evaluations.sqlite as it happens, and returns what the report needs.
// Writing summary.json, CSVs, plots and report.md is study_report's job.
//
// Resume: with RunOptions::resume the same deterministic driver runs again;
// every design already in the store is taken from it instead of being
// evaluated, so nothing recorded is lost or evaluated twice, and the result
// equals that of an uninterrupted run.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/life/wear_reliability.hpp"
#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study/sweep_sensitivity.hpp"

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
};

// One discrete combination's outcome in an optimize study.
struct CombinationOutcome {
  std::string label;                         // "pinion.module=4 mm"
  std::string status;                        // the solver's status for this combination
  std::optional<DesignResult> best;          // best feasible design of the combination
  std::optional<DesignResult> least_infeasible;  // when none is feasible
};

struct StudyResult {
  std::string status;   // "ok" (evaluate/sweep/reliability done), the SolverResult / ParetoResult status
                        // (optimize: "converged", "max_evaluations", ...; pareto: "ok", "anchor_infeasible", ...),
                        // "no_feasible_point", "all_failed", "stopped"
  std::optional<DesignResult> best;            // optimize: best feasible design; evaluate/reliability:
                                               // the design (even when infeasible or failed);
                                               // sweep: best feasible by objective 0 (if any objective);
                                               // pareto: the chosen front point
  std::optional<DesignResult> least_infeasible;  // when no feasible design was found
  std::vector<DesignResult> front;             // pareto: feasible, non-dominated, sorted by objective 0
  std::optional<std::size_t> chosen;           // pareto: index into front of the chosen design
  std::vector<DesignResult> sweep_points;      // sweep: every point in sampler order
  std::vector<double> best_history;            // best feasible objective 0 (own sense) after each evaluation
  std::size_t evaluations = 0;                 // model evaluations this study needed (recorded + new)
  std::size_t reused_evaluations = 0;          // of which taken from the store on --resume
  std::size_t failed_evaluations = 0;
  std::string solver_message;
  std::vector<std::string> warnings;           // model warnings, listed once, in the order the designs
                                               // were first used (the same after --resume)
  double seconds = 0;                          // wall time of this run
  std::string database_path;                   // <out>/evaluations.sqlite
  std::string evaluations_csv_path;            // <out>/evaluations.csv, written by run_study from the store
  // The drive of `best` (optimize/evaluate/reliability) or of the chosen
  // front point (pareto): the report writes and plots its stiffness curve.
  std::shared_ptr<const Drive> best_drive;
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

struct RunOptions {
  std::string out_dir;                  // created if missing; holds evaluations.sqlite
  bool resume = false;
  unsigned threads = 0;                 // sweeps and Monte Carlo; 0 = all cores. Results do not depend on it.
  std::function<void(const Progress&)> progress;  // after every evaluation (may be empty)
  std::function<bool()> stop;           // polled between evaluations and by the Monte Carlo of a reliability
                                        // study (from its worker threads: must be thread-safe); true = stop cleanly (Ctrl-C)
  fe::FeCalls fe_calls;                 // `verify: fe`: the FE solves (empty members = the real ones; tests inject fakes)
};

// Runs the study; at the end writes <out>/evaluations.csv from the store
// (write_evaluations_csv) and sets the store's meta "status". Throws InputError for a set-up error found only now (a
// metric requirement, a solver combination), std::runtime_error when the
// store cannot be opened (another study's results in out_dir, a folder
// already used without --resume). A design the models reject never throws:
// it is a failed evaluation in the store and in the counts.
//
// What each kind does (StudyProblem, study_problem.hpp, has the mapping of
// metrics to objectives and constraints):
//  * The start design (continuous variables at start or mid-range, discrete
//    at start or their first value) is evaluated first, phase "start": it
//    sets the automatic objective scales and is the design of evaluate and
//    reliability. A sweep evaluates it only when an objective has an
//    automatic scale, and never ranks it.
//  * sweep: grid (first variable slowest) / Latin hypercube / Sobol from
//    spec.seed, discrete values snapped to the nearest; evaluated in
//    parallel by chunks, recorded in sampler order (phase "sweep k"), so the
//    store and the result are the same on any thread count. Stop is polled
//    between chunks.
//  * optimize: every combination of the discrete values (last one fastest),
//    solver from the start point with seed = spec.seed; best = best feasible
//    design over every evaluation (our re-check). status: "stopped",
//    "no_feasible_point" / "all_failed", else the solver status of the best
//    design's combination.
//  * pareto: pareto_front per combination, fronts merged with non_dominated;
//    `best` is the chosen front point too.
//  * reliability: run_wear_reliability on the start design with
//    metric_options' samples/seed/bootstrap overrides.
// Counting: a design is evaluated at most once per store; a design asked
// for again (another start or sub-problem, a sweep duplicate) is answered
// from the store and not counted again. best_history holds +inf (minimize) or
// -inf (maximize) until the first feasible design.
StudyResult run_study(const StudySpec& spec, const RunOptions& options);

}  // namespace rackopt::study
