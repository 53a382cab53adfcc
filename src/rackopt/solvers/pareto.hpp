// Pareto fronts of 2- or 3-objective Problems by scalarization: every front
// point is one single-objective `minimize` run on a wrapper Problem that maps
// the original evaluation to one scalar objective (plus, for the
// eps-constraint method, bounds on the other objectives). See the "Pareto
// fronts" section of docs/solvers.md for the grid layouts and the limits of
// each method.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/solvers/problem.hpp"
#include "rackopt/solvers/solver.hpp"

namespace rackopt::solvers {

// kEpsilonConstraint: minimize f_primary with f_j <= eps_j for the others;
//   finds non-convex (concave) parts of a front; needs an algorithm that
//   accepts inequality constraints (LN_COBYLA, LD_SLSQP, AUGLAG, Ipopt, ...).
// kWeightedSum: minimize sum_i w_i (f_i - ideal_i) / (nadir_i - ideal_i);
//   works with any algorithm but only finds the convex hull of the front:
//   points on a concave part are never the minimum of a weighted sum.
// kPopulation: no scalarization: the solver's own front algorithm (pagmo's
//   nsga2 or moead) searches the whole front in one run of 2-4 objectives,
//   and front_selection.hpp keeps `points` of its feasible evaluations.
enum class Scalarization { kEpsilonConstraint, kWeightedSum, kPopulation };

// "eps-constraint", "weighted sum", "population search" (for reports).
std::string_view method_title(Scalarization method);

struct ParetoSettings {
  Scalarization method = Scalarization::kEpsilonConstraint;
  // Front points requested, anchors included. With 2 objectives exactly
  // points - 2 sub-problems follow the anchors; with 3 the grid is the
  // largest one that does not exceed `points` (docs/solvers.md). >= 2.
  std::size_t points = 20;
  // eps-constraint: the objective minimized; the others are bounded.
  std::size_t primary = 0;
  // Two front points whose objectives differ by at most this fraction of
  // (nadir - ideal) in every objective are duplicates (the first is kept).
  double duplicate_tolerance = 1e-4;
  SolverSettings solver;  // used for every sub-problem (anchors included)
};

struct ParetoPoint {
  std::vector<double> x;
  Evaluation evaluation;  // of the ORIGINAL problem at x (all its objectives)
  // Which sub-problem produced it: "anchor 0", "eps 3" (2 objectives),
  // "eps 2,1" (3 objectives: levels of the two bounded objectives),
  // "w 0.75/0.25" (weights of objectives 0, 1[, 2]).
  std::string label;
  bool feasible = false;  // is_feasible(evaluation, solver.constraint_tolerance)
};

// How a front computation ended (to_string gives the reported text).
enum class ParetoStatus {
  kOk,                // every sub-problem was solved
  kNoFeasiblePoint,   // no feasible point at all (front empty)
  kAnchorInfeasible,  // some anchor found no feasible point: ideal/nadir come
                      // from the others and the front may be partial
  kStopped,           // callbacks.stop asked to stop; front from what was solved
};
// "ok", "no_feasible_point", "anchor_infeasible", "stopped".
std::string_view to_string(ParetoStatus status);
inline std::ostream& operator<<(std::ostream& out, ParetoStatus status) { return out << to_string(status); }

struct ParetoResult {
  // Feasible, mutually non-dominated, no duplicates, sorted by objective
  // `primary` (ties: by the other objectives in order).
  std::vector<ParetoPoint> front;
  // Feasible sub-problem results removed as dominated or as duplicates.
  std::vector<ParetoPoint> dominated;
  // Sub-problem results that were not feasible (kept for the record).
  std::vector<ParetoPoint> infeasible;
  // From the feasible anchors: ideal_i = min f_i, nadir_i = max f_i over them.
  std::vector<double> ideal, nadir;
  // Sums over every sub-solve; `subproblems` counts the anchors too (a
  // population method's run is one).
  std::size_t evaluations = 0, failed_evaluations = 0, subproblems = 0;
  // Population methods: generations after the first population, and its size.
  std::size_t generations = 0, population = 0;
  ParetoStatus status = ParetoStatus::kOk;
};

struct ParetoCallbacks {
  // Every model evaluation of every sub-solve, in order. `label` names the
  // sub-problem (as ParetoPoint::label); record.index counts from 0 over the
  // WHOLE front computation; record.evaluation is the original problem's
  // evaluation (all objectives, original constraints only).
  std::function<void(const std::string& label, const EvaluationRecord& record)> observer;
  StopRequest stop;  // forwarded to every sub-solve; once it fires no further sub-problem starts
};

// Approximates the Pareto front of `problem` (num_objectives() 2 or 3; 2 to
// 4 for kPopulation, which hands the whole search to the solver's backend).
// Anchors first (minimize each objective alone from x0, constraints kept),
// then the scalarized sub-problems of `settings.method` on a grid between
// ideal and nadir, each warm-started from the previous sub-problem's
// solution. Deterministic: same inputs => same front.
// Throws std::invalid_argument when the problem has not 2 or 3 objectives,
// points < 2, primary out of range, or settings.solver cannot run a
// sub-problem (e.g. LN_BOBYQA with eps-constraint: the bounds on the other
// objectives are inequality constraints). Rethrows what evaluate() or a
// callback threw.
ParetoResult pareto_front(const Problem& problem, std::span<const double> x0, const ParetoSettings& settings,
                          const ParetoCallbacks& callbacks = {});

// a dominates b (minimization): a_i <= b_i for all i and a_i < b_i for one.
// Vectors of different sizes: throws std::invalid_argument.
bool dominates(std::span<const double> a, std::span<const double> b);

// Indices (ascending) of the vectors no other vector dominates. Equal vectors
// do not dominate each other, so all copies of a non-dominated vector stay.
std::vector<std::size_t> non_dominated(const std::vector<std::vector<double>>& objective_vectors);

}  // namespace rackopt::solvers
