// The rules each study kind sets on a study, checked in one place: the
// study-file loader calls this and points at the offending line; the runner
// calls it again for a StudySpec built in code. Only rules that the spec
// alone decides live here; what the problem must provide (a wear section,
// random inputs, metrics it can compute) is checked where the problem is
// read (studyfile/study_loader.cpp, metrics::check_metric_requests).
//
// Example:
//   if (auto v = check_study_kind_rules(spec)) throw InputError(mark_of(v->part), key_of(v->part), v->message);
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

// The part of the study a broken rule is about (so a loader can point at
// the key that should change).
enum class StudyRulePart {
  kObjectives,          // the objective count for the kind
  kVariables,           // the variables as a whole (none given; too many discrete combinations)
  kVariable,            // one variable (StudyRuleViolation::variable): evaluate/reliability need its start
  kSweepGrid,           // the grid's size (levels x variables) over sweep.max_points
  kSweepPoints,         // sweep.points over sweep.max_points
  kSolverLibrary,       // solver.library, or what it cannot do with the study's shape
  kSolverAlgorithm,     // solver.algorithm (also the budget and tolerances)
  kSolverLocalAlgorithm,
  kSolverOption,        // one of the library's own settings (StudyRuleViolation::option names it)
  kParetoMethod,        // pareto.method: eps_constraint adds constraints the solver cannot take
};
std::string to_string(StudyRulePart part);

struct StudyRuleViolation {
  StudyRulePart part;
  std::size_t variable = 0;  // index into spec.variables when part == kVariable
  std::string message;       // what is wrong and what to do instead
  std::string option;        // the solver setting's key when part == kSolverOption
};

// The first broken rule, in the order a user should fix them, or nullopt:
//  * optimize: exactly one objective; pareto: 2 or 3 (2 to 4 with the
//    population method);
//  * optimize, pareto and sweep: at least one variable;
//  * evaluate and reliability: every variable has a start (one design);
//  * sweep: the grid or the sample within sweep.max_points;
//  * optimize and pareto: discrete combinations within
//    max_discrete_combinations (unless searched as integers), and the
//    solver able to run the problem's shape (its variables, the constraints'
//    inequality/equality counts; for eps_constraint fronts also the
//    objectives turned into bounds).
std::optional<StudyRuleViolation> check_study_kind_rules(const StudySpec& spec);

// The study-file key a violation asks to change ("objectives",
// "variables.pinion.module", "solver.algorithm", ...), for messages about a
// StudySpec that has no file positions.
std::string study_rule_key(const StudyRuleViolation& violation, const StudySpec& spec);

// Whether an optimize or pareto study hands its discrete variables to the
// solver as whole-valued variables (StudyProblem::with_discrete_as_integers)
// in one run, instead of one run per combination: when it has a discrete
// variable of two or more values and its algorithm searches integers
// (pagmo's gaco for optimize, nsga2 for a population front).
bool searches_discrete_as_integers(const StudySpec& spec);

// The shape of the problems the solver sees in an optimize or pareto study
// (one objective, or the pareto study's objectives for the population
// method): the continuous variables (plus the discrete ones when searched
// as integers), and inequality/equality counts of the constraints (a
// constraint with min and max is two inequalities).
solvers::ProblemShape solver_problem_shape(const StudySpec& spec);

}  // namespace rackopt::study
