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

#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/study/design_executor.hpp"
#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

struct RunOptions {
  std::string out_dir;                  // created if missing; holds evaluations.sqlite
  bool resume = false;
  unsigned threads = 0;                 // sweeps and Monte Carlo; 0 = all cores. Results do not depend on it.
  std::function<void(const Progress&)> progress;  // after every evaluation (may be empty)
  std::function<bool()> stop;           // polled between evaluations and by the Monte Carlo of a reliability
                                        // study (from its worker threads: must be thread-safe); true = stop cleanly (Ctrl-C)
  fe::FeCalls fe_calls;                 // `verify: fe`: the FE solves (empty members = the real ones; tests inject fakes)
  // Who evaluates batches of designs (design_executor.hpp); empty = this
  // process's `threads`. An MPI job passes its rank executor. Results do not
  // depend on it.
  std::shared_ptr<DesignExecutor> executor;
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
