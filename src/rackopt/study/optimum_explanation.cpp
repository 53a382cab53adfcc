#include "rackopt/study/optimum_explanation.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <cmath>

namespace rackopt::study {
namespace {

std::size_t label_index(const StudyProblem& p, const std::string& label) {
  const auto& labels = p.metric_labels();
  return static_cast<std::size_t>(std::find(labels.begin(), labels.end(), label) - labels.begin());
}

std::optional<double> metric_at(const StudyProblem& p, const DesignEvaluation& d, const std::string& label) {
  const std::size_t i = label_index(p, label);
  if (i >= d.metric_ok.size() || !d.metric_ok[i]) return std::nullopt;
  return d.metric_values[i];
}

double scale_of(const ConstraintSpec& c, double bound) {
  if (c.scale > 0) return c.scale;
  return bound != 0 ? std::abs(bound) : 1.0;
}

// d objective / d u_q + sum over active constraints lambda_c A(q, c) in
// the normalized variable u_q (the Lagrangian's gradient), as the multiplier
// step defines A; nullopt when a needed difference failed.
std::optional<double> lagrangian_gradient(const OptimumExplanation& e, std::size_t q, double sense, double range,
                                          const std::vector<std::size_t>& act, const std::vector<double>& lambda) {
  if (q >= e.objective_gradient.size() || !e.objective_gradient[q]) return std::nullopt;
  double r = sense * *e.objective_gradient[q] * range;
  for (std::size_t c = 0; c < act.size(); ++c) {
    const ConstraintStatus& s = e.constraints[act[c]];
    if (!s.gradient[q]) return std::nullopt;
    const double dv = *s.gradient[q] * range;
    r += lambda[c] * (s.side == "min" ? -dv : dv);
  }
  return r;
}

}  // namespace

double bound_tolerance_fraction(const solvers::SolverSettings& solver) {
  double f = kBoundToleranceFloor;
  std::string library = solver.library;
  std::transform(library.begin(), library.end(), library.begin(), [](unsigned char c) { return std::tolower(c); });
  if (library == "nlopt") f = std::max({f, solver.xtol_abs, solver.xtol_rel});
  return f;
}

OptimumExplanation explain_optimum(const StudyProblem& problem, const std::vector<double>& x, unsigned threads) {
  const StudySpec& spec = problem.spec();
  OptimumExplanation out;
  if (!spec.objectives.empty()) out.objective = spec.objectives[0].label;
  const DesignEvaluation at = problem.evaluate_design(x, threads);

  // Variables and the difference scheme of each continuous one.
  const std::vector<std::size_t>& cont = problem.continuous_indices();
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const DesignVariable& v = spec.variables[i];
    VariableStatus s;
    s.key = v.key;
    s.value = x.at(i);
    s.discrete = v.discrete();
    if (!s.discrete) {
      const double range = v.upper - v.lower;
      s.bound_tolerance = bound_tolerance_fraction(spec.solver) * range;
      s.at_lower = x[i] <= v.lower + s.bound_tolerance;
      s.at_upper = !s.at_lower && x[i] >= v.upper - s.bound_tolerance;
      s.step = kGradientStep * range;
      const bool up = x[i] + s.step <= v.upper, down = x[i] - s.step >= v.lower;
      s.difference = up && down ? "central" : up ? "forward" : "backward";
    }
    out.variables.push_back(s);
  }

  // Finite differences: one or two evaluations per continuous variable.
  std::vector<std::string> labels;
  if (!out.objective.empty()) labels.push_back(out.objective);
  for (const ConstraintSpec& c : spec.constraints) labels.push_back(c.label);
  std::vector<std::vector<std::optional<double>>> grad(labels.size());
  for (std::size_t k : cont) {
    const VariableStatus& s = out.variables[k];
    out.gradient_variables.push_back(s.key);
    std::vector<double> xp = x, xm = x;
    if (s.difference != "backward") xp[k] += s.step;
    if (s.difference != "forward") xm[k] -= s.step;
    const DesignEvaluation ep = s.difference == "backward" ? at : problem.evaluate_design(xp, threads);
    const DesignEvaluation em = s.difference == "forward" ? at : problem.evaluate_design(xm, threads);
    const double h = xp[k] - xm[k];
    for (std::size_t j = 0; j < labels.size(); ++j) {
      const auto a = metric_at(problem, ep, labels[j]), b = metric_at(problem, em, labels[j]);
      grad[j].push_back(a && b ? std::optional<double>((*a - *b) / h) : std::nullopt);
    }
  }
  const std::size_t off = out.objective.empty() ? 0 : 1;
  if (off) out.objective_gradient = grad[0];

  // Constraint status at the design.
  for (std::size_t j = 0; j < spec.constraints.size(); ++j) {
    const ConstraintSpec& c = spec.constraints[j];
    ConstraintStatus s;
    s.label = c.label;
    s.gradient = grad[off + j];
    const auto v = metric_at(problem, at, c.label);
    if (v) s.value = *v;
    if (c.equals) {
      s.side = "equals";
      s.bound = *c.equals;
      s.relative_slack = -std::abs(s.value - s.bound) / scale_of(c, s.bound);
      s.active = true;
    } else {
      // The nearer of the two bounds (a min and a max on one metric).
      double best = INFINITY;
      for (const auto& [side, bound] : {std::pair{"min", c.min}, std::pair{"max", c.max}}) {
        if (!bound) continue;
        const double slack = (std::string(side) == "min" ? s.value - *bound : *bound - s.value) / scale_of(c, *bound);
        if (std::abs(slack) < best) {
          best = std::abs(slack);
          s.side = side;
          s.bound = *bound;
          s.relative_slack = slack;
        }
      }
      s.active = v && std::abs(s.relative_slack) <= kActiveTolerance;
    }
    out.constraints.push_back(std::move(s));
  }

  // Multipliers on the free continuous variables: minimize F = +-objective,
  // g_j = b - v (min) or v - b (max) or v - b (equals); at a KKT point
  // grad F + sum lambda_j grad g_j = 0, and dF*/db_j = lambda_j (min),
  // -lambda_j (max, equals). Least squares in the normalized variables.
  if (off && !cont.empty()) {
    const double sense = spec.objectives[0].maximize ? -1.0 : 1.0;
    std::vector<std::size_t> free_cols;  // positions in `cont`
    for (std::size_t q = 0; q < cont.size(); ++q) {
      const VariableStatus& s = out.variables[cont[q]];
      if (!s.at_lower && !s.at_upper) free_cols.push_back(q);
    }
    std::vector<std::size_t> act;
    bool complete = true;
    for (std::size_t j = 0; j < out.constraints.size(); ++j) {
      if (!out.constraints[j].active) continue;
      act.push_back(j);
      for (std::size_t q : free_cols) complete = complete && out.constraints[j].gradient[q].has_value();
    }
    for (std::size_t q : free_cols) complete = complete && out.objective_gradient[q].has_value();
    std::vector<double> multipliers;  // of `act`, when identified
    if (!complete) {
      out.note = "some finite differences failed (a perturbed design could not be evaluated): no multipliers";
    } else if (free_cols.empty() || act.empty()) {
      out.note = act.empty() ? "no active constraint: the optimum is interior or held by variable bounds"
                             : "every continuous variable is at a bound: the binding constraints' multipliers are "
                               "not identified";
    } else {
      Eigen::MatrixXd A(free_cols.size(), act.size());
      Eigen::VectorXd g(free_cols.size());
      for (std::size_t r = 0; r < free_cols.size(); ++r) {
        const std::size_t q = free_cols[r];
        const DesignVariable& v = spec.variables[cont[q]];
        const double range = v.upper - v.lower;
        g(static_cast<Eigen::Index>(r)) = sense * *out.objective_gradient[q] * range;
        for (std::size_t c = 0; c < act.size(); ++c) {
          const ConstraintStatus& s = out.constraints[act[c]];
          const double dv = *s.gradient[q] * range;
          A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = s.side == "min" ? -dv : dv;
        }
      }
      const Eigen::VectorXd lambda = A.completeOrthogonalDecomposition().solve(-g);
      multipliers.assign(lambda.data(), lambda.data() + lambda.size());
      const double gnorm = g.norm();
      out.kkt_residual = gnorm > 0 ? (g + A * lambda).norm() / gnorm : 0.0;
      for (std::size_t c = 0; c < act.size(); ++c) {
        ConstraintStatus& s = out.constraints[act[c]];
        const double l = lambda(static_cast<Eigen::Index>(c));
        s.bound_sensitivity = sense * (s.side == "min" ? l : -l);
      }
      out.note = "central differences (one-sided at a bound), step " + std::to_string(kGradientStep) +
                 " of each range; multipliers by least squares on the " + std::to_string(free_cols.size()) +
                 " free continuous variables";
      if (A.cols() > A.rows()) out.note += " (more active constraints than free variables: minimum-norm multipliers)";
    }
    // Which bounds hold the optimum: the Lagrangian's one-sided slope at
    // the bound points out of the box (with no active constraint, the
    // objective's own slope). Unknown when the multipliers are not.
    if (act.empty() || multipliers.size() == act.size()) {
      for (std::size_t q = 0; q < cont.size(); ++q) {
        VariableStatus& s = out.variables[cont[q]];
        if (!s.at_lower && !s.at_upper) continue;
        const DesignVariable& v = spec.variables[cont[q]];
        const std::optional<double> slope = lagrangian_gradient(out, q, sense, v.upper - v.lower, act, multipliers);
        if (slope) s.pushed_into_bound = s.at_lower ? *slope > 0 : *slope < 0;
      }
    }
  } else if (cont.empty()) {
    out.note = "no continuous variable: no gradients";
  }
  return out;
}

}  // namespace rackopt::study
