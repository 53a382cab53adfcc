// Wear-life reliability from life samples (docs/models/reliability.md):
// R(t) and the life at reliability R, from a fitted
// distribution and empirically, each with a confidence interval.
//
// Lives are in seconds in the summary (any unit elsewhere). Nothing here knows
// about gears: the wear model produces the samples.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rackopt/statistics/distribution.hpp"
#include "rackopt/statistics/goodness_of_fit.hpp"
#include "rackopt/statistics/life_fit.hpp"
#include "rackopt/statistics/sampling.hpp"

namespace rackopt::statistics {

// R(t) = 1 - F(t) = P(life > t), from the survival function (no cancellation
// near R = 1). Any finite t; NaN throws InputError.
double reliability_at(const Distribution& life, double t);

// Life at reliability R: t_R = F^-1(1 - R), computed as the inverse survival
// function. R strictly inside (0,1), else InputError.
double life_at_reliability(const Distribution& life, double reliability);

// Fraction of the lives strictly greater than t (the empirical R(t)).
// Empty sample or non-finite value -> InputError.
double empirical_reliability(std::span<const double> lives, double t);

// A point estimate with a two-sided confidence interval. When the data cannot
// bound one side at the requested confidence, that side is reported as 0
// (lower; lives are >= 0) or +infinity (upper) and the *_bounded flag is false.
struct LifeInterval {
  double estimate = 0;
  double lower = 0;
  double upper = 0;
  bool lower_bounded = true;
  bool upper_bounded = true;
  double confidence = 0.95;
};

// Empirical life at reliability R: the (1-R) sample quantile x_(r), r = ceil(N (1-R))
// (the inverse of the empirical cdf), with the distribution-free order-statistic
// interval [x_(l), x_(u)]: with B ~ Binomial(N, 1-R), l is the largest index with
// P(B <= l-1) <= (1-c)/2 and u the smallest with P(B <= u-1) >= 1-(1-c)/2, so that
// P(x_(l) <= t_R <= x_(u)) >= c for any continuous life distribution.
// R and confidence c strictly inside (0,1), non-empty finite sample, else InputError.
LifeInterval empirical_life_at_reliability(std::span<const double> lives, double reliability,
                                           double confidence = 0.95);

// What the summary is asked for.
struct ReliabilityRequest {
  std::vector<Family> candidates{Family::kGamma, Family::kWeibull, Family::kLognormal};
  double ks_level = 0.05;            // KS significance level alpha
  std::vector<double> reliabilities; // R values (0,1) for the life at R
  std::vector<double> times;         // t >= 0 [s] for R(t)
  double confidence = 0.95;          // of every interval
  int bootstrap_replicates = 200;    // shared by the KS critical value and the fit CIs
  std::uint64_t seed = 1;            // bootstrap seed (results are a function of it)
  unsigned threads = 1;              // results do not depend on it
  // Polled (thread-safe) before each candidate's fit and through its
  // bootstrap (BootstrapOptions::stop): once true, summarize_lives throws
  // rackopt::Interrupted. Empty = never stops.
  std::function<bool()> stop;
};

struct CandidateFit {
  Family family = Family::kGamma;
  std::optional<LifeFit> fit;    // empty when the fit failed (see error)
  std::string error;             // why it failed (DesignError/InputError message)
  KsTest ks;                     // valid when fit is set
  // Per request.reliabilities: life at R of this fit with a parametric-bootstrap
  // percentile interval (the refits of the KS bootstrap, quantiles (1-c)/2 and (1+c)/2).
  std::vector<LifeInterval> life_at_reliability;
};

struct ReliabilityAtTime {
  double t = 0;                  // [s]
  std::optional<double> fit;     // from the chosen fit (empty when nothing could be fitted)
  double empirical = 0;          // fraction of samples surviving t
};

struct LifeAtReliability {
  double reliability = 0;
  std::optional<LifeInterval> fit;  // chosen fit, bootstrap interval
  LifeInterval empirical;           // order statistics, binomial interval
};

struct ReliabilitySummary {
  std::size_t samples_total = 0;
  std::size_t failed_evaluations = 0;  // NaN/inf samples: excluded from everything
  std::size_t immediate_failures = 0;  // lives == 0: in the empirical results, not in the fits
  std::size_t samples_fitted = 0;      // lives > 0 given to the fits
  std::vector<CandidateFit> candidates;
  int chosen = -1;                     // index in candidates, -1 when none could be fitted
  bool chosen_accepted = false;        // chosen fit passed the KS test
  std::vector<std::string> warnings;
  std::vector<ReliabilityAtTime> reliability;
  std::vector<LifeAtReliability> life;
  const CandidateFit* chosen_fit() const { return chosen < 0 ? nullptr : &candidates[chosen]; }
};

// The whole reliability analysis of one set of life samples [s]:
//  1. NaN/inf samples are counted as failed evaluations and dropped; negative
//     lives throw InputError; lives equal to 0 (failure at once, e.g. a
//     contact ratio sampled below 1) are immediate failures: they count in the
//     empirical results, and with p0 their fraction the fitted reliability is
//     (1 - p0) S(t) for the distribution S fitted to the positive lives (life
//     at R is 0 when R >= 1 - p0). The fit intervals ignore p0's own scatter.
//  2. Each candidate is fitted by maximum likelihood and KS-tested at
//     ks_level with a parametric-bootstrap critical value.
//  3. The chosen fit is the accepted candidate of lowest AIC; when none is
//     accepted, the lowest AIC overall, with a warning.
//  4. R(t) at each time and the life at each R, from the chosen fit and
//     empirically, with intervals.
// A sample that cannot be fitted (fewer than 2 positive lives, or all equal)
// gives no fit (chosen = -1, a warning) and the empirical results only.
// Cost: one MLE fit + B bootstrap refits of N values per candidate
// (docs/models/reliability.md gives timings).
ReliabilitySummary summarize_lives(std::span<const double> lives_seconds,
                                   const ReliabilityRequest& request);

// The same from evaluate_samples() results: a sample whose status is not ok
// counts as a failed evaluation.
ReliabilitySummary summarize_lives(std::span<const SampleResult> samples,
                                   const ReliabilityRequest& request);

}  // namespace rackopt::statistics
