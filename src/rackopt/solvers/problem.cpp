#include "rackopt/solvers/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rackopt::solvers {

double max_violation(const Evaluation& e) {
  if (!e.ok()) return std::numeric_limits<double>::infinity();
  double v = 0.0;
  for (double g : e.inequality) v = std::max(v, std::isnan(g) ? std::numeric_limits<double>::infinity() : g);
  for (double h : e.equality) v = std::max(v, std::isnan(h) ? std::numeric_limits<double>::infinity() : std::abs(h));
  return v;
}

bool is_feasible(const Evaluation& e, double tolerance) { return e.ok() && max_violation(e) <= tolerance; }

std::vector<std::string> Problem::variable_names() const {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < dimension(); ++i) names.push_back("x" + std::to_string(i));
  return names;
}

std::vector<Evaluation> Problem::evaluate_batch(const std::vector<std::vector<double>>& xs) const {
  std::vector<Evaluation> out;
  out.reserve(xs.size());
  for (const auto& x : xs) out.push_back(evaluate(std::span<const double>(x)));
  return out;
}

}  // namespace rackopt::solvers
