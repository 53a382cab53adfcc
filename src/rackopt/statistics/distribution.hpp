// Probability distributions of uncertain inputs and of wear lives
// (docs/models/reliability.md).
//
// One small value type covers the five families the reliability work needs.
// Sampling is ALWAYS done by `quantile(u)` of a uniform u in (0,1): pseudo-random
// and Sobol points then go through the same code, and a model whose life is a
// monotone function of one input keeps that monotonicity sample by sample (the
// life at reliability R is then that input's quantile pushed through the model).
//
// Errors: a parameter that is not finite or out of its range, or a probability
// outside (0,1), throws rackopt::InputError (key "distribution"). No function
// returns NaN. GSL's abort-on-error handler is switched off the first time a
// Distribution is built (the CLI does the same at start-up): GSL failures are
// checked here and never reach abort().
#pragma once

#include <span>
#include <string>

#include "rackopt/core/drive.hpp"

namespace rackopt::statistics {

enum class Family { kNormal, kLognormal, kUniform, kWeibull, kGamma };

// "normal", "lognormal", "uniform", "weibull", "gamma".
const char* family_name(Family family);

// Parses the names above (lower case). Unknown names throw InputError.
Family family_from_name(const std::string& name);

class Distribution {
 public:
  // mean, standard deviation (sd > 0).
  static Distribution normal(double mean, double standard_deviation);
  // median = exp(mu) > 0, sigma = standard deviation of ln X (> 0).
  static Distribution lognormal(double median, double sigma_ln);
  // lower < upper.
  static Distribution uniform(double lower, double upper);
  // F(x) = 1 - exp(-(x/scale)^shape); scale > 0, shape > 0 (GSL's a = scale, b = shape).
  static Distribution weibull(double scale, double shape);
  // f(x) = x^(k-1) e^(-x/theta) / (Gamma(k) theta^k); shape k > 0, scale theta > 0.
  static Distribution gamma(double shape, double scale);

  Family family() const { return family_; }
  // The two parameters in the order of the factory above (normal: mean, sd;
  // lognormal: median, sigma_ln; uniform: lower, upper; weibull: scale, shape;
  // gamma: shape, scale).
  double first() const { return a_; }
  double second() const { return b_; }

  // Density at x (0 outside the support).
  double pdf(double x) const;
  // ln pdf(x), computed directly (no underflow to -inf inside the support);
  // -infinity outside the support.
  double log_pdf(double x) const;
  // P(X <= x), in [0, 1].
  double cdf(double x) const;
  // cdf(x) at each value of an ascending sample, into out (same size; else
  // InputError). Equal to cdf(x) to ~1e-10 absolute. For the gamma (shape >= 2)
  // it integrates the density between consecutive values (3-point Gauss)
  // from anchors computed exactly (the first value, every 128th, after any
  // gap over 0.1 sd): ~10x cheaper than GSL's incomplete gamma per value, which
  // dominated the KS bootstrap (docs/models/reliability.md).
  void cdf_sorted(std::span<const double> ascending, std::span<double> out) const;
  // P(X > x) = 1 - cdf(x), computed without cancellation in the upper tail:
  // this is the reliability R(t) when X is a life.
  double survival(double x) const;
  // Inverse cdf: the x with cdf(x) = p, for p strictly inside (0, 1).
  // Monotone non-decreasing in p. p outside (0,1) throws InputError.
  double quantile(double p) const;
  // Inverse survival: the x with survival(x) = q, q in (0,1); accurate for
  // q near 1 (high reliability) where 1 - q would lose digits.
  double survival_quantile(double q) const;
  double mean() const;
  double standard_deviation() const;
  // Readable form, e.g. "gamma(shape=150, scale=1.2e7)".
  std::string describe() const;

 private:
  Distribution(Family family, double a, double b);
  Family family_;
  double a_;
  double b_;
};

// The distribution of RandomInput::a/b read as the absolute parameters of
// the input (core/drive.hpp), whatever `absolute` says: an input around the
// design goes through wear_reliability/design_scatter.hpp's input_distribution, which
// calls this with the parameters made absolute. Invalid parameters throw
// InputError with key "reliability.inputs.<key>".
Distribution to_distribution(const RandomInput& input);

namespace detail {
// Switches GSL's default error handler (which calls abort()) off, once, thread-safely.
void quiet_gsl_errors();
}  // namespace detail

}  // namespace rackopt::statistics
