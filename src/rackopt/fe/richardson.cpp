#include "rackopt/fe/richardson.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rackopt::fe {

std::string to_string(ConvergenceStatus status) {
  switch (status) {
    case ConvergenceStatus::kAsymptotic: return "asymptotic";
    case ConvergenceStatus::kResolved: return "resolved";
    case ConvergenceStatus::kOscillating: return "oscillating";
    case ConvergenceStatus::kDiverging: return "diverging";
  }
  return "?";
}

RichardsonEstimate richardson(std::span<const double> values, double ratio, double resolution) {
  if (values.size() < 3) throw std::invalid_argument("richardson: at least three levels are needed");
  for (double v : values) {
    if (!std::isfinite(v)) throw std::invalid_argument("richardson: a value is not finite");
  }
  if (!(ratio > 1) || !std::isfinite(ratio)) throw std::invalid_argument("richardson: the refinement ratio must be > 1");
  if (!(resolution >= 0)) throw std::invalid_argument("richardson: the resolution must be >= 0");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = values.size();
  const double f0 = values[n - 3], f1 = values[n - 2], f2 = values[n - 1];
  const double d01 = f1 - f0, d12 = f2 - f1;
  const double tol = resolution * std::abs(f2);
  RichardsonEstimate e;
  e.order = nan;
  e.extrapolated = nan;
  if (std::abs(d12) <= tol) {
    e.status = ConvergenceStatus::kResolved;
    e.extrapolated = f2;
  } else if (std::abs(d01) <= tol || (d01 > 0) != (d12 > 0)) {
    // A coarse difference at the resolution but a larger fine one is no
    // convergence either way; opposite signs are oscillation.
    e.status = std::abs(d01) <= tol ? ConvergenceStatus::kDiverging : ConvergenceStatus::kOscillating;
  } else if (std::abs(d12) >= std::abs(d01)) {
    e.status = ConvergenceStatus::kDiverging;
  } else {
    e.status = ConvergenceStatus::kAsymptotic;
    e.order = std::log(d01 / d12) / std::log(ratio);
    e.extrapolated = f2 + d12 / (std::pow(ratio, e.order) - 1);
  }
  for (double v : values) e.relative_error.push_back(std::abs(v - e.extrapolated) / std::abs(e.extrapolated));
  return e;
}

}  // namespace rackopt::fe
