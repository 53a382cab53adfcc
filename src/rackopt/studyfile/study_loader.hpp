// Study files (studies/*.yaml) -> StudySpec, with errors that say where and
// why. docs/studies.md is the user-facing reference of every key.
#pragma once

#include <string>
#include <vector>

#include "rackopt/study/study_spec.hpp"

namespace rackopt::studyfile {

// Reads and checks a study file. `overrides` are `--set` assignments:
// "problem.<key>=value" is appended to problem_overrides (so any problem key
// can be changed from the command line), anything else addresses the study
// file itself ("solver.max_evaluations=50", "study.seed=3"). Variable and
// problem_set keys contain dots, so "variables.rack.span.upper=3 m" edits
// the field `upper` of the longest variable of the file that fits
// ("rack.span"; a [lower, upper] shorthand is spelled out first), and
// "variables.rack.span=[1 m, 2 m]" sets, adds or (empty value) removes it.
// `problem_set` entries become problem_overrides "key=value" with the value
// written back as a YAML flow value; an error the problem loader finds in
// one is reported at the entry's line in the study file.
// Also loads the problem once (so that a bad problem or a variable key the
// problem does not know is reported before anything runs) and checks every
// metric's requirements (check_metric_requests) against it.
// Throws InputError with file:line:column and the key path for: unknown keys
// (with "did you mean"), a missing required key, a unit of the wrong kind,
// bounds with lower >= upper, a start outside the bounds, discrete values not
// ascending or not whole for count keys, an unknown metric or a parameter out
// of range, an unknown kind, solver settings check_solver_settings refuses
// (message says what to use instead), too many objectives for the kind,
// a sweep bigger than max_points, too many discrete combinations.
study::StudySpec load_study_file(const std::string& path, const std::vector<std::string>& overrides = {});

// A problem a program holds in memory (problem YAML text, the name its
// messages carry and `--set` assignments over it, applied before the study's
// problem_set), given to a study instead of the file its `problem:` names.
struct InMemoryProblem {
  std::string yaml_text;
  std::string name;
  std::vector<std::string> overrides;
};

// Same, from text. `name_for_messages` is used in marks; relative problem
// paths are resolved against `base_dir`. `problem`, when given, is the
// study's problem and replaces its `problem:` key, which may then be left
// out. A study file may also hold its problem inline: `problem:` as a map of
// the problem file's sections (then errors in it point into the study file).
study::StudySpec load_study_text(const std::string& yaml_text, const std::string& name_for_messages,
                          const std::string& base_dir, const std::vector<std::string>& overrides = {},
                          const InMemoryProblem* problem = nullptr);

}  // namespace rackopt::studyfile
