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

}  // namespace

double ks_min(std::span<const double> values, double rho, double scale) {
  check(values, rho, scale);
  return -ks_upper(values, rho, scale, -1.0);
}

double ks_max(std::span<const double> values, double rho, double scale) {
  check(values, rho, scale);
  return ks_upper(values, rho, scale, 1.0);
}

}  // namespace rackopt::metrics
