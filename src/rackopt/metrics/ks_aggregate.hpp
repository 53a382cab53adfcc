// Kreisselmeier-Steinhauser (KS) smooth extremes of a set of values.
//
// For values v_1..v_N, a scale S > 0 and a weight rho > 0:
//   ks_min = -(S/rho) ln sum_i exp(-rho v_i / S),   ks_max = (S/rho) ln sum_i exp(rho v_i / S).
// Bounds (exact, any rho > 0):
//   min v - S ln(N)/rho <= ks_min <= min v,   max v <= ks_max <= max v + S ln(N)/rho,
// and ks_min increases (ks_max decreases) monotonically towards the true
// extreme as rho grows. The gap is S ln(N_near)/rho where N_near counts the
// values within about S/rho of the extreme. Unlike min/max, the KS value is a
// smooth function of every v_i, so it has a gradient when the location of the
// extreme jumps. Computed with the extreme factored out: no overflow.
#pragma once

#include <span>

namespace rackopt::metrics {

// Throws InputError for an empty span, a non-finite value, scale <= 0 or rho <= 0.
double ks_min(std::span<const double> values, double rho, double scale);
double ks_max(std::span<const double> values, double rho, double scale);

// The same on the logarithms of positive values, back in the values:
// exp(ks_min(ln v, rho, 1)) = (sum v_i^-rho)^(-1/rho) and
// exp(ks_max(ln v, rho, 1)) = (sum v_i^rho)^(1/rho), the power means, from the
// ratios to the extreme (no logarithm per value). Terms below 1e-20 of the
// extreme's own (which is 1) are left out: together they change the sum by
// less than its rounding. Throws InputError as ks_min for an empty span, a
// non-finite value or rho <= 0; the values must be positive.
double power_mean_min(std::span<const double> positive_values, double rho);
double power_mean_max(std::span<const double> positive_values, double rho);

}  // namespace rackopt::metrics
