// The readers of the study file's sections (docs/studies.md is the reference
// of every key), composed by load_study_text in the order the later sections
// need: the problem first (variables and metrics are checked against it),
// then variables, the metrics, and the settings of the solver, pareto front
// and sweep.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/marked_yaml/section_reader.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace rackopt::studyfile {

// --- command-line --set over the study file
// Applies the assignments that address the study file to `root` (dotted
// variable and problem_set keys included); returns the "problem.*" ones
// without their prefix, for the problem loader.
std::vector<std::string> apply_study_overrides(MarkedNode& root, const std::vector<std::string>& overrides);

// --- problem, problem_set
// The problem as the study sees it: its tree (for designs) and its Drive.
struct LoadedProblem {
  ProblemTree tree;
  Drive drive;
};
// Fills spec.problem_path, spec.problem_root (a problem held in memory:
// `given`, else an inline `problem:` map) and spec.problem_overrides
// (problem_set, then `cli_problem_overrides`) and loads the problem; its
// errors in an override are reported where the study file or the command
// line wrote it.
LoadedProblem read_problem_section(const SectionReader& top, const std::string& base_dir,
                                   const std::vector<std::string>& cli_problem_overrides,
                                   const InMemoryProblem* given, study::StudySpec& spec);

// --- variables
// Fills spec.variables; every bound and value is checked by building the
// problem with it, and reported where the study wrote it.
void read_variables(const SectionReader& top, const LoadedProblem& problem, study::StudySpec& spec);

// --- objectives, constraints, report, metric_options
// Where a metric was written, for re-throwing its set-up errors there.
struct MetricSite {
  metrics::MetricRequest request;
  SourceMark mark;
  std::string path;
};
std::vector<MetricSite> read_metric_sections(const SectionReader& top, study::StudySpec& spec);
// Needs spec.seed (the default Monte Carlo seed). Returns the section, whose
// mark is where problems with the options as a whole are reported.
SectionReader read_metric_options(const SectionReader& top, study::StudySpec& spec);
// Checks every metric against the problem: each at its own site, then all of
// them with the options at `options_section`.
void check_metrics_against_problem(const std::vector<MetricSite>& sites, const SectionReader& options_section,
                                   const Drive& drive, const study::StudySpec& spec);

// --- solver, pareto, sweep, output, limits
// The sections the study-kind rules point into.
struct SettingsSections {
  SectionReader solver;
  SectionReader pareto;
  SectionReader sweep;
};
// Needs spec.seed and spec.objectives (pareto.primary names one).
SettingsSections read_settings_sections(const SectionReader& top, study::StudySpec& spec);

}  // namespace rackopt::studyfile
