// Maximum-likelihood fits of life distributions (docs/models/reliability.md, "Maximum-likelihood fits").
//
// Samples are lives (any positive unit; the reliability summary uses seconds).
// Every fit is scale-equivariant: fitting c*x gives the same shapes and c times
// the scales, so the unit does not matter.
//
// Errors:
//  * an empty sample, or a value that is not finite or not > 0 (normal: not
//    finite) -> InputError (key "life samples") naming the first bad index;
//  * fewer than 2 values, or a sample with no spread (all values equal, to a
//    relative 1e-12): the maximum-likelihood spread is zero and no
//    two-parameter density exists -> DesignError code "degenerate_life_sample".
//    Nothing is returned in that case (never a NaN or an infinite shape); the
//    reliability summary then reports the empirical results only.
#pragma once

#include <span>

#include "rackopt/statistics/distribution.hpp"

namespace rackopt::statistics {

struct LifeFit {
  Distribution distribution;   // the fitted distribution
  double log_likelihood = 0;   // sum of ln pdf over the sample
  double aic = 0;              // 2 k - 2 ln L with k = 2 parameters
  int iterations = 0;          // Newton/bracketing steps used (0 for closed forms)
};

// Sum of ln pdf(x_i). A value outside the support gives -infinity.
double log_likelihood(const Distribution& d, std::span<const double> sample);

// Gamma MLE: the shape k solves ln k - psi(k) = s with
// s = ln(mean x) - mean(ln x) > 0 (Newton on ln k with GSL's digamma/trigamma,
// from the Choi-Wette / Minka starting value, converged to 1e-12 relative);
// scale = mean / k. s is computed as mean(d - ln(1+d)) with d = x/mean - 1 so
// that it keeps its digits for samples of small spread.
LifeFit fit_gamma(std::span<const double> sample);

// Weibull MLE: the shape b solves the profile-likelihood equation
// sum x^b ln x / sum x^b - 1/b - mean(ln x) = 0 (increasing in b); the root is
// bracketed by doubling/halving and found by Newton steps kept inside the
// bracket (bisection when a step leaves it). scale = (mean x^b)^(1/b).
// Values are divided by their maximum first so that x^b cannot overflow.
LifeFit fit_weibull(std::span<const double> sample);

// Lognormal MLE (closed form): median = exp(mean ln x), sigma^2 = mean (ln x - mu)^2
// (divisor N, the MLE, not N-1).
LifeFit fit_lognormal(std::span<const double> sample);

// Normal MLE (closed form): mean, sd with divisor N. Values need only be finite.
LifeFit fit_normal(std::span<const double> sample);

// Dispatches on the family (uniform: min and max, the MLE).
LifeFit fit_life_distribution(Family family, std::span<const double> sample);

// Least-squares fit of a family to reliability points (t_i, R_i): minimises
// sum (R_i - survival(t_i))^2 over the two parameters (Nelder-Mead on their
// logarithms from a probit-line starting point, restarted until it stops
// improving). For calibrating against published reliability tables (the wear paper)
// where only R(t) values, not samples, are known. Needs >= 2 points with
// t > 0 and 0 < R < 1, else InputError. Families: gamma, weibull, lognormal, normal.
struct ReliabilityPointFit {
  Distribution distribution;
  double sum_squared_residuals = 0;
  double max_abs_residual = 0;
};
ReliabilityPointFit fit_to_reliability_points(Family family, std::span<const double> times,
                                              std::span<const double> reliabilities);

}  // namespace rackopt::statistics
