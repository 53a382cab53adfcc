// Why the optimum is where it is: which constraints bind and which variables
// sit at a bound, the finite-difference gradients of the objective and of
// every constraint there, and the Lagrange-multiplier sensitivity of the
// objective to each binding constraint's bound (how much objective one unit
// of that bound costs). docs/studies.md, "Explaining the optimum".
//
// The runner computes it after an optimize study on its best design (the
// report never runs a model). It costs at most two evaluations per
// continuous variable, not recorded in the store; being deterministic, a
// resumed run computes the same numbers.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

// A metric's value at the design against one refinement of its model's
// discretization (study/wear_discretization_check.hpp).
struct DiscretizationError {
  std::string setting;       // the refined setting, e.g. "wear.profile_points"
  int points = 0;            // its value in the study
  int refined_points = 0;    // the refinement's
  double refined_value = 0;  // SI
  double relative_error = 0;  // (value - refined_value) / |refined_value|: the value's error, estimated
};

struct ConstraintStatus {
  std::string label;             // metric label
  std::string side;              // "min", "max" or "equals": the bound nearest the value
  double value = 0;              // SI
  double bound = 0;              // SI
  double relative_slack = 0;     // (value - bound)/scale on the feasible side positive (min: v - b; max: b - v)
  bool active = false;           // |relative slack| <= kActiveTolerance (or an equality)
  // d objective* / d bound [objective unit per metric unit] when active and
  // the gradients allow: the objective's change when the bound moves by one
  // unit (positive = tightening a min bound or relaxing a max bound costs).
  std::optional<double> bound_sensitivity;
  std::vector<std::optional<double>> gradient;  // d value / d x_i per continuous variable (SI per SI)
  // Active wear-life constraints: the value against one refinement of the
  // profile points (check_wear_discretization); empty otherwise.
  std::optional<DiscretizationError> discretization;
};

struct VariableStatus {
  std::string key;
  double value = 0;          // SI
  bool discrete = false;
  // Continuous only: within bound_tolerance of the lower / upper bound.
  bool at_lower = false, at_upper = false;
  double bound_tolerance = 0;  // SI: bound_tolerance_fraction(spec.solver) of the range; 0 for discrete
  // At a bound: whether the objective's one-sided gradient, plus the active
  // constraints' times their multipliers, pushes into that bound (the bound
  // holds the optimum: moving off it makes the design worse); nullopt when
  // not at a bound or a difference failed.
  std::optional<bool> pushed_into_bound;
  double step = 0;           // finite-difference step used [SI]; 0 for discrete
  std::string difference;    // "central", "forward", "backward", or "" (discrete)
};

struct OptimumExplanation {
  std::string objective;                                 // label of objective 0
  std::vector<std::optional<double>> objective_gradient;  // d objective / d x_i per continuous variable
  std::vector<std::string> gradient_variables;           // their keys
  std::vector<VariableStatus> variables;                 // every variable, spec order
  std::vector<ConstraintStatus> constraints;             // spec order
  double kkt_residual = 0;  // |grad F + sum lambda grad g| / |grad F| on the free variables (0 = exact)
  std::string note;         // how it was computed, and what could not be
};

// A constraint counts as active within this relative slack (its scale:
// ConstraintSpec::scale, else |bound|, else 1). Solvers stop within ~1e-4 of
// a bound at their default tolerances.
inline constexpr double kActiveTolerance = 1e-3;
// A continuous variable is at a bound when it is this close to it, as a
// fraction of its range, at least: solvers stop short of a bound by about
// their step tolerance, and COBYLA and the population methods do not step
// onto it at all.
inline constexpr double kBoundToleranceFloor = 1e-3;

// The at-a-bound tolerance as a fraction of a variable's range for a
// solver (its variables are the ranges scaled to [0, 1]): NLopt stops
// within xtol_abs + xtol_rel |u| of its point, |u| <= 1 on that box, so
// max(kBoundToleranceFloor, xtol_abs, xtol_rel); the other libraries have
// no step tolerance, so the floor.
double bound_tolerance_fraction(const solvers::SolverSettings& solver);

// Finite-difference step as a fraction of each continuous variable's range:
// large enough to step over the wear lives' block-wise steps (docs/metrics.md).
inline constexpr double kGradientStep = 1e-2;

// Explains the design x (full SI, e.g. the best design of an optimize
// study) of `problem`. Objective 0 is explained (the runner minimizes it).
OptimumExplanation explain_optimum(const StudyProblem& problem, const std::vector<double>& x, unsigned threads = 1);

}  // namespace rackopt::study
