#include "rackopt/metrics/ks_aggregate.hpp"

#include <algorithm>
#include <cmath>

#include "rackopt/core/error.hpp"

namespace rackopt::metrics {
namespace {

void check(std::span<const double> v, double rho, double scale) {
  const SourceMark where{"<metric>", 0, 0};
  if (v.empty()) throw InputError(where, "ks", "no values to aggregate");
  if (!std::isfinite(rho) || !(rho > 0)) throw InputError(where, "ks", "rho must be > 0 and finite");
  if (!std::isfinite(scale) || !(scale > 0)) throw InputError(where, "ks", "scale must be > 0 and finite");
  for (double x : v) {
    if (!std::isfinite(x)) throw InputError(where, "ks", "non-finite value");
  }
}

// (S/rho) ln sum exp(rho (v_i - top)/S) + top, with top = max of sign*v.
double ks_upper(std::span<const double> v, double rho, double scale, double sign) {
  double top = sign * v[0];
  for (double x : v) top = std::max(top, sign * x);
  double sum = 0;
  for (double x : v) sum += std::exp(rho * (sign * x - top) / scale);  // each term in (0, 1], one is 1
  return top + scale / rho * std::log(sum);
}

// extreme * (sum (v_i / extreme)^p)^(1/p), p = sign * rho, extreme = the
// value with the largest sign * v: every ratio raised is at most 1.
double power_mean(std::span<const double> v, double rho, double sign) {
  double extreme = v[0];
  for (double x : v) extreme = sign * x > sign * extreme ? x : extreme;
  // (v_i / extreme)^p < 1e-20 where p ln(ratio) < ln(1e-20); the values
  // that far from the extreme are told apart without a division.
  const double negligible = std::exp(std::log(1e-20) / rho);
  const double bound = sign > 0 ? extreme * negligible : extreme / negligible;
  double sum = 0;
  for (double x : v) {
    if (sign * x < sign * bound) continue;
    const double ratio = sign > 0 ? x / extreme : extreme / x;  // in (0, 1]
    if (ratio >= negligible) sum += std::pow(ratio, rho);
  }
  return extreme * std::pow(sum, sign / rho);
}

}  // namespace

double power_mean_min(std::span<const double> positive_values, double rho) {
  check(positive_values, rho, 1.0);
  return power_mean(positive_values, rho, -1.0);
}

double power_mean_max(std::span<const double> positive_values, double rho) {
  check(positive_values, rho, 1.0);
  return power_mean(positive_values, rho, 1.0);
}

double ks_min(std::span<const double> values, double rho, double scale) {
  check(values, rho, scale);
  return -ks_upper(values, rho, scale, -1.0);
}

double ks_max(std::span<const double> values, double rho, double scale) {
  check(values, rho, scale);
  return ks_upper(values, rho, scale, 1.0);
}

}  // namespace rackopt::metrics
