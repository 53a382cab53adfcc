// Kolmogorov-Smirnov goodness of fit when the parameters are estimated from
// the same sample (docs/models/reliability.md, "Kolmogorov–Smirnov with estimated parameters"), by parametric bootstrap.
//
// Why a bootstrap: the classical critical value c(alpha)/sqrt(N)
// (1.358/sqrt(N) at 5%) assumes a fully specified distribution. A fitted
// distribution follows its own sample more closely, so D_N is smaller and
// that critical value almost never rejects (Lilliefors 1967: for a fitted
// normal the 5% value is about 0.886/sqrt(N)). Refitting each simulated sample
// reproduces the estimation step and gives the right critical value for any
// family (docs/models/reliability.md).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "rackopt/statistics/distribution.hpp"

namespace rackopt::statistics {

// Fewest bootstrap replicates (and successful refits) for a p-value: below
// this the critical value of the KS statistic is read from too few points.
// Every reader of a replicate count (problem files, study files, metric
// options) refuses less.
inline constexpr int kMinBootstrapReplicates = 20;

// D_N = sup_x |F_N(x) - F(x)| for the sample (any order; sorted internally).
// Empty or non-finite sample -> InputError.
double ks_statistic(const Distribution& d, std::span<const double> sample);

// The same for a sample already sorted ascending (no copy).
double ks_statistic_sorted(const Distribution& d, std::span<const double> sorted);

// Known-parameter (classical Kolmogorov) critical value at level alpha, from
// the asymptotic distribution: sqrt(-ln(alpha/2)/2)/sqrt(N) (1.3581/sqrt(N) at
// 5%). Reported for comparison only: it is wrong (far too lenient) for a
// fitted distribution. alpha in (0,1), N >= 1, else InputError.
double ks_known_parameter_critical_value(std::size_t n, double alpha);

// n values drawn from d, a pure function of (seed, stream): counter_uniform
// streams, the quantile for every family except gamma, which uses
// Marsaglia & Tsang (2000) with normal variates from the probit of counter
// uniforms (about 20x cheaper than GSL's gamma inverse, and the bootstrap does
// not need monotonicity).
std::vector<double> draw_sample(const Distribution& d, std::size_t n, std::uint64_t seed,
                                std::uint64_t stream);

struct BootstrapOptions {
  int replicates = 200;      // B >= kMinBootstrapReplicates (else InputError)
  std::uint64_t seed = 1;    // replicate b uses stream b of this seed
  unsigned threads = 1;      // the result does not depend on it
  // Polled (from the worker threads: must be thread-safe) before each
  // replicate and between its steps (draw, sort, refit, KS), so that a stop
  // is noticed within one step over N values: once true, the remaining
  // replicates are skipped and parametric_bootstrap throws
  // rackopt::Interrupted. Empty = never stops.
  std::function<bool()> stop;
};

// One parametric bootstrap replicate: a sample of the original size drawn from
// the fitted distribution, refitted in the same family.
struct BootstrapReplicate {
  std::optional<Distribution> refit;  // empty when the refit failed (degenerate draw)
  double ks_statistic = 0;            // D* of the refit against its own sample
};

// B replicates; cost B * (N draws + one MLE fit + N cdf evaluations + a sort).
std::vector<BootstrapReplicate> parametric_bootstrap(Family family, const Distribution& fitted,
                                                     std::size_t n, const BootstrapOptions& options);

struct KsTest {
  double statistic = 0;                        // D_N of the fit against the sample
  double critical_value = 0;                   // bootstrap (1-alpha) quantile of D*
  double known_parameter_critical_value = 0;   // classical value, for comparison only
  double p_value = 0;                          // (1 + #{D* >= D_N}) / (B_ok + 1)
  int replicates_used = 0;                     // B_ok: replicates whose refit succeeded
  bool accepted = false;                       // D_N <= critical_value (equivalently p > alpha)
};

// KS test of `fitted` (an MLE fit of `family` to `sample`) at level alpha with
// bootstrap critical value. critical_value is the k-th smallest D* with
// k = ceil((1 - alpha)(B_ok + 1)) (clamped to B_ok). Fewer than 20 successful
// replicates -> DesignError "bootstrap_failed".
KsTest ks_test_fitted(Family family, const Distribution& fitted, std::span<const double> sample,
                      double alpha, const BootstrapOptions& options);

// The same from replicates already drawn (the reliability summary shares one
// bootstrap between the KS test and the confidence intervals).
KsTest ks_test_from_bootstrap(const Distribution& fitted, std::span<const double> sample,
                              double alpha, std::span<const BootstrapReplicate> replicates);

}  // namespace rackopt::statistics
