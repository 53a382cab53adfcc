#include "rackopt/study/study_kind_rules.hpp"

#include <algorithm>
#include <vector>

#include "rackopt/solvers/solver_backend.hpp"

#include "rackopt/core/text.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt::study {

namespace {

std::optional<StudyRuleViolation> violation(StudyRulePart part, std::string message, std::size_t variable = 0) {
  return StudyRuleViolation{part, variable, std::move(message)};
}

std::optional<StudyRuleViolation> objective_count(const StudySpec& spec) {
  const std::size_t n = spec.objectives.size();
  if (spec.kind == StudyKind::kOptimize && n != 1)
    return violation(StudyRulePart::kObjectives,
                     "an optimize study needs exactly one objective, found " + std::to_string(n) +
                         (n > 1 ? " (for 2 or 3 objectives use kind: pareto; or turn the others into constraints)"
                                : " (e.g. objectives: [stiffness_fluctuation])"));
  const bool population = spec.pareto.method == solvers::Scalarization::kPopulation;
  const std::size_t most = population ? 4 : 3;
  if (spec.kind == StudyKind::kPareto && (n < 2 || n > most))
    return violation(StudyRulePart::kObjectives,
                     "a pareto study needs 2 " + std::string(population ? "to 4" : "or 3") + " objectives, found " + std::to_string(n) +
                         (n < 2 ? " (for one objective use kind: optimize)"
                                : population ? ""
                                             : " (4 objectives: pareto method population with solver library "
                                               "pagmo, algorithm nsga2 or moead)"));
  return std::nullopt;
}

std::optional<StudyRuleViolation> variables_present(const StudySpec& spec) {
  const bool needs = spec.kind == StudyKind::kOptimize || spec.kind == StudyKind::kPareto ||
                     spec.kind == StudyKind::kSweep;
  if (!needs || !spec.variables.empty()) return std::nullopt;
  return violation(StudyRulePart::kVariables, "a " + std::string(kind_name(spec.kind)) +
                                                  " study needs at least one design variable, e.g. variables: "
                                                  "{pinion.pressure_angle: [14 deg, 25 deg]}");
}

std::optional<StudyRuleViolation> one_design(const StudySpec& spec) {
  if (spec.kind != StudyKind::kEvaluate && spec.kind != StudyKind::kReliability) return std::nullopt;
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    if (spec.variables[i].start) continue;
    return violation(StudyRulePart::kVariable,
                     "an " + std::string(kind_name(spec.kind)) +
                         " study computes one design: give start (e.g. {lower: ..., upper: ..., start: ...}) or a "
                         "single value ({values: [...]})",
                     i);
  }
  return std::nullopt;
}

std::optional<StudyRuleViolation> sweep_size(const StudySpec& spec) {
  if (spec.kind != StudyKind::kSweep) return std::nullopt;
  if (spec.sweep.method != SweepSpec::Method::kGrid) {
    if (spec.sweep.points <= spec.sweep.max_points) return std::nullopt;
    return violation(StudyRulePart::kSweepPoints, std::to_string(spec.sweep.points) +
                                                      " points is more than sweep.max_points = " +
                                                      std::to_string(spec.sweep.max_points) +
                                                      "; lower points or raise max_points");
  }
  double total = 1;
  std::vector<std::string> factors;
  for (const auto& v : spec.variables) {
    const std::size_t n =
        v.discrete() ? v.values.size() : static_cast<std::size_t>(v.levels.value_or(spec.sweep.levels));
    total *= static_cast<double>(n);
    factors.push_back(v.key + " " + std::to_string(n));
  }
  if (total <= static_cast<double>(spec.sweep.max_points)) return std::nullopt;
  return violation(StudyRulePart::kSweepGrid,
                   "the grid has " + format_number(total, 12) + " points (" + join(factors, " x ") +
                       "), more than sweep.max_points = " + std::to_string(spec.sweep.max_points) +
                       "; lower the levels, use method: lhs or sobol with fewer points, or raise max_points");
}

bool enumerates_combinations(const StudySpec& spec) {
  return spec.kind == StudyKind::kOptimize || spec.kind == StudyKind::kPareto;
}

std::optional<StudyRuleViolation> discrete_combinations(const StudySpec& spec) {
  if (!enumerates_combinations(spec) || searches_discrete_as_integers(spec)) return std::nullopt;
  double combinations = 1;
  std::vector<std::string> factors;
  for (const auto& v : spec.variables) {
    if (!v.discrete()) continue;
    combinations *= static_cast<double>(v.values.size());
    factors.push_back(v.key + " (" + std::to_string(v.values.size()) + " values)");
  }
  if (combinations <= static_cast<double>(spec.max_discrete_combinations)) return std::nullopt;
  return violation(StudyRulePart::kVariables,
                   "the discrete variables " + join(factors, " x ") + " make " + format_number(combinations, 12) +
                       " combinations, each optimized separately; more than limits.max_discrete_combinations = " +
                       std::to_string(spec.max_discrete_combinations) +
                       "; drop values, make a variable continuous, search them as integers in one run (solver library "
                       "pagmo, algorithm gaco; nsga2 for a population front), or raise the limit");
}

StudyRulePart part_of(solvers::SolverSetting s, const solvers::SolverSettings& settings) {
  switch (s) {
    case solvers::SolverSetting::kLibrary: return StudyRulePart::kSolverLibrary;
    case solvers::SolverSetting::kLocalAlgorithm: return StudyRulePart::kSolverLocalAlgorithm;
    case solvers::SolverSetting::kOption: return StudyRulePart::kSolverOption;
    case solvers::SolverSetting::kAlgorithm:
    case solvers::SolverSetting::kNumbers:
    case solvers::SolverSetting::kProblem: break;
  }
  // Ipopt has no algorithm setting: whatever it refuses is about the library.
  return lower(settings.library) == "ipopt" ? StudyRulePart::kSolverLibrary : StudyRulePart::kSolverAlgorithm;
}

std::optional<StudyRuleViolation> solver_can_run(const StudySpec& spec) {
  if (!enumerates_combinations(spec)) return std::nullopt;
  const solvers::ProblemShape shape = solver_problem_shape(spec);
  // Every variable discrete: the enumeration is the optimization, no solver runs.
  if (shape.dimension == 0) return std::nullopt;
  const bool pareto = spec.kind == StudyKind::kPareto;
  const bool population = pareto && spec.pareto.method == solvers::Scalarization::kPopulation;
  const bool finds_fronts = solvers::algorithm_finds_fronts(spec.solver);
  if (population && !finds_fronts)
    return violation(StudyRulePart::kParetoMethod,
                     "the population method needs a solver that finds whole fronts (library pagmo, algorithm nsga2 "
                     "or moead); " + spec.solver.library + " " + spec.solver.algorithm +
                         " minimizes one objective: use eps_constraint or weighted_sum with it");
  if (finds_fronts && !population)
    return violation(pareto ? StudyRulePart::kParetoMethod : StudyRulePart::kSolverAlgorithm,
                     spec.solver.algorithm + " finds whole Pareto fronts: " +
                         (pareto ? std::string("use it with pareto method: population (or leave method out), or give "
                                               "the scalarized sub-problems a one-objective algorithm (pagmo cmaes or "
                                               "sade, an NLopt algorithm, Ipopt)")
                                 : std::string("an optimize study needs a one-objective algorithm (pagmo cmaes or "
                                               "sade, an NLopt algorithm, Ipopt), or kind: pareto")));
  if (auto r = solvers::check_solver_settings(spec.solver, shape)) {
    auto v = violation(part_of(r->setting, spec.solver), r->message);
    v->option = r->option;
    return v;
  }
  if (pareto && spec.pareto.method == solvers::Scalarization::kEpsilonConstraint) {
    const std::size_t bounds = spec.objectives.size() - 1;
    solvers::ProblemShape eps = shape;
    eps.inequality += bounds;
    if (auto r = solvers::check_solver_settings(spec.solver, eps))
      return violation(StudyRulePart::kParetoMethod,
                       "the eps_constraint method bounds the other " + std::to_string(bounds) +
                           " objective(s) by inequality constraints: " + r->message +
                           "; or use pareto method: weighted_sum (convex parts of the front only)");
  }
  return std::nullopt;
}

}  // namespace

std::string to_string(StudyRulePart part) {
  switch (part) {
    case StudyRulePart::kObjectives: return "objectives";
    case StudyRulePart::kVariables: return "variables";
    case StudyRulePart::kVariable: return "variable";
    case StudyRulePart::kSweepGrid: return "sweep grid";
    case StudyRulePart::kSweepPoints: return "sweep points";
    case StudyRulePart::kSolverLibrary: return "solver library";
    case StudyRulePart::kSolverAlgorithm: return "solver algorithm";
    case StudyRulePart::kSolverLocalAlgorithm: return "solver local algorithm";
    case StudyRulePart::kSolverOption: return "solver setting";
    case StudyRulePart::kParetoMethod: return "pareto method";
  }
  return "?";
}

std::string study_rule_key(const StudyRuleViolation& violation, const StudySpec& spec) {
  switch (violation.part) {
    case StudyRulePart::kObjectives: return "objectives";
    case StudyRulePart::kVariables: return "variables";
    case StudyRulePart::kVariable:
      return violation.variable < spec.variables.size() ? "variables." + spec.variables[violation.variable].key
                                                        : "variables";
    case StudyRulePart::kSweepGrid: return "sweep.levels";
    case StudyRulePart::kSweepPoints: return "sweep.points";
    case StudyRulePart::kSolverLibrary: return "solver.library";
    case StudyRulePart::kSolverAlgorithm: return "solver.algorithm";
    case StudyRulePart::kSolverLocalAlgorithm: return "solver.local_algorithm";
    case StudyRulePart::kSolverOption: return "solver." + violation.option;
    case StudyRulePart::kParetoMethod: return "pareto.method";
  }
  return "study";
}

bool searches_discrete_as_integers(const StudySpec& spec) {
  const bool population = spec.kind == StudyKind::kPareto && spec.pareto.method == solvers::Scalarization::kPopulation;
  if (spec.kind != StudyKind::kOptimize && !population) return false;
  const auto any_list = std::any_of(spec.variables.begin(), spec.variables.end(),
                                    [](const DesignVariable& v) { return v.discrete() && v.values.size() >= 2; });
  if (!any_list) return false;
  const solvers::SolverBackend* backend = solvers::find_solver_backend(spec.solver.library);
  if (!backend) return false;
  const auto algorithm = backend->find_algorithm(spec.solver.algorithm);
  return algorithm && algorithm->integers;
}

solvers::ProblemShape solver_problem_shape(const StudySpec& spec) {
  solvers::ProblemShape shape;
  if (spec.kind == StudyKind::kPareto && spec.pareto.method == solvers::Scalarization::kPopulation)
    shape.objectives = spec.objectives.size();
  const bool integers = searches_discrete_as_integers(spec);
  for (const auto& v : spec.variables) {
    if (!v.discrete()) {
      ++shape.dimension;
    } else if (integers && v.values.size() >= 2) {
      ++shape.dimension;
      ++shape.integer;
    }
  }
  for (const auto& c : spec.constraints) {
    shape.inequality += (c.min ? 1 : 0) + (c.max ? 1 : 0);
    shape.equality += c.equals ? 1 : 0;
  }
  return shape;
}

std::optional<StudyRuleViolation> check_study_kind_rules(const StudySpec& spec) {
  for (auto rule : {objective_count, variables_present, one_design, sweep_size, discrete_combinations, solver_can_run})
    if (auto v = rule(spec)) return v;
  return std::nullopt;
}

}  // namespace rackopt::study
