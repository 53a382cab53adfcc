// One driver per study kind: which designs to evaluate, in which order, and
// what the kind's status is. Every design goes through the evaluation
// ledger (evaluation_ledger.hpp), which records and counts it; run_study
// (study_runner.cpp) checks the set-up, evaluates the start design,
// dispatches to one driver and completes the result. The contract of each
// kind is in study_runner.hpp above run_study.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/solvers/solver.hpp"
#include "rackopt/study/evaluation_ledger.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/study/study_status.hpp"

namespace rackopt::study {

// What every driver works with.
struct KindDriverContext {
  const StudySpec& spec;
  const RunOptions& options;
  StudyProblem& base;              // every discrete combination's problem comes from it
  EvaluationLedger& ledger;        // holds the StudyResult being filled
  const solvers::SolverSettings& solver;  // spec.solver with the study's seed
};

// A set-up error of a StudySpec (no file positions: the loader adds them).
inline InputError study_error(const StudySpec& spec, const std::string& key, const std::string& message) {
  return InputError(SourceMark{spec.file, 0, 0}, key, message);
}

// "combination 2/6 (pinion.module=4 mm)", or "" with a single combination
// or for the view that searches every combination as integers.
std::string combination_phase(const StudyProblem& p);

// evaluate and reliability: the start design is the result (and, for
// reliability, its wear reliability analysis). `start` is empty when the
// study was stopped before it.
StudyStatus drive_single_design(const KindDriverContext& c, const std::optional<Obtained>& start);

// The sweep's designs in sampler order (grid: first variable slowest; LHS
// and Sobol from spec.seed, discrete values snapped to the nearest).
// Throws InputError when the sampler refuses the settings.
std::vector<std::vector<double>> sweep_points(const StudySpec& spec);
StudyStatus drive_sweep(const KindDriverContext& c, const std::vector<std::vector<double>>& points);

// Every discrete combination optimized from the start point.
StudyStatus drive_optimize(const KindDriverContext& c);

// A front per combination, merged by dominance, sorted by objective 0, one
// point chosen.
StudyStatus drive_pareto(const KindDriverContext& c);

}  // namespace rackopt::study
