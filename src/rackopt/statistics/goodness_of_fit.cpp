#include "rackopt/statistics/goodness_of_fit.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/parallel_for.hpp"
#include "rackopt/statistics/life_fit.hpp"
#include "rackopt/statistics/sampling.hpp"

namespace rackopt::statistics {

namespace {
[[noreturn]] void bad(const std::string& message) {
  throw InputError(SourceMark{}, "goodness of fit", message);
}
// Keeps bootstrap draws independent of Monte Carlo points made with the same seed.
constexpr std::uint64_t kDrawTag = 0x5EEDB0075742A9ULL;

// Sequential uniforms of one (seed, stream): u_0, u_1, ...
struct UniformStream {
  std::uint64_t seed, stream, counter = 0;
  double next() { return counter_uniform(seed, stream, counter++); }
};

// Marsaglia & Tsang (2000), "A simple method for generating gamma variables",
// ACM TOMS 26(3): exact rejection sampler for shape >= 1; shape < 1 through
// Gamma(k) = Gamma(k+1) U^(1/k).
double gamma_variate(double shape, UniformStream& rng) {
  if (shape < 1.0) {
    const double g = gamma_variate(shape + 1.0, rng);
    return g * std::pow(rng.next(), 1.0 / shape);
  }
  const double d = shape - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
  for (;;) {
    double x, v;
    do {
      x = gsl_cdf_ugaussian_Pinv(rng.next());
      v = 1.0 + c * x;
    } while (v <= 0.0);
    v = v * v * v;
    const double u = rng.next();
    if (u < 1.0 - 0.0331 * x * x * x * x) return d * v;
    if (std::log(u) < 0.5 * x * x + d * (1.0 - v + std::log(v))) return d * v;
  }
}
}  // namespace

double ks_statistic_sorted(const Distribution& d, std::span<const double> x) {
  if (x.empty()) bad("KS statistic of an empty sample");
  for (double v : x)
    if (!std::isfinite(v)) bad("KS statistic of a non-finite value");
  std::vector<double> f(x.size());
  d.cdf_sorted(x, f);
  const double n = static_cast<double>(x.size());
  double dmax = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    dmax = std::max({dmax, static_cast<double>(i + 1) / n - f[i], f[i] - static_cast<double>(i) / n});
  }
  return dmax;
}

double ks_statistic(const Distribution& d, std::span<const double> sample) {
  std::vector<double> x(sample.begin(), sample.end());
  std::sort(x.begin(), x.end());
  return ks_statistic_sorted(d, x);
}

double ks_known_parameter_critical_value(std::size_t n, double alpha) {
  if (!(alpha > 0 && alpha < 1)) bad("KS level alpha must be inside (0, 1)");
  if (n < 1) bad("KS critical value needs N >= 1");
  return std::sqrt(-0.5 * std::log(0.5 * alpha)) / std::sqrt(static_cast<double>(n));
}

std::vector<double> draw_sample(const Distribution& d, std::size_t n, std::uint64_t seed,
                                std::uint64_t stream) {
  UniformStream rng{mix64(seed ^ kDrawTag), stream};
  std::vector<double> x(n);
  if (d.family() == Family::kGamma) {
    for (double& v : x) v = d.second() * gamma_variate(d.first(), rng);
  } else {
    for (double& v : x) v = d.quantile(rng.next());
  }
  return x;
}

std::vector<BootstrapReplicate> parametric_bootstrap(Family family, const Distribution& fitted,
                                                     std::size_t n,
                                                     const BootstrapOptions& options) {
  if (options.replicates < kMinBootstrapReplicates)
    bad("the bootstrap needs at least " + std::to_string(kMinBootstrapReplicates) + " replicates");
  if (n < 2) bad("the bootstrap needs a sample of at least 2 values");
  std::vector<BootstrapReplicate> out(static_cast<std::size_t>(options.replicates));
  auto stopped = [&] { return options.stop && options.stop(); };
  ParallelControl control;
  control.stop = stopped;
  parallel_for(out.size(), options.threads, [&](std::size_t b) {
    // A replicate cut short is left empty: the whole bootstrap is abandoned below.
    std::vector<double> x = draw_sample(fitted, n, options.seed, b);
    if (stopped()) return;
    std::sort(x.begin(), x.end());
    if (stopped()) return;
    try {
      const LifeFit fit = fit_life_distribution(family, x);
      if (stopped()) return;
      out[b].refit = fit.distribution;
      out[b].ks_statistic = ks_statistic_sorted(fit.distribution, x);
    } catch (const InputError&) {   // a draw underflowed to 0
      out[b].refit.reset();
    } catch (const DesignError&) {  // a degenerate draw (all equal)
      out[b].refit.reset();
    }
  }, control);
  if (stopped()) throw Interrupted("parametric bootstrap: stopped by " + stop_reason());
  return out;
}

KsTest ks_test_from_bootstrap(const Distribution& fitted, std::span<const double> sample,
                              double alpha, std::span<const BootstrapReplicate> replicates) {
  KsTest t;
  t.statistic = ks_statistic(fitted, sample);
  t.known_parameter_critical_value = ks_known_parameter_critical_value(sample.size(), alpha);
  std::vector<double> dstar;
  for (const auto& r : replicates)
    if (r.refit) dstar.push_back(r.ks_statistic);
  if (dstar.size() < static_cast<std::size_t>(kMinBootstrapReplicates))
    throw DesignError("bootstrap_failed", "only " + std::to_string(dstar.size()) + " of " +
                                              std::to_string(replicates.size()) + " bootstrap refits succeeded (" +
                                              std::to_string(kMinBootstrapReplicates) + " needed)");
  std::sort(dstar.begin(), dstar.end());
  const std::size_t b = dstar.size();
  t.replicates_used = static_cast<int>(b);
  std::size_t k = static_cast<std::size_t>(std::ceil((1.0 - alpha) * static_cast<double>(b + 1)));
  k = std::clamp<std::size_t>(k, 1, b);
  t.critical_value = dstar[k - 1];
  const auto at_least = static_cast<double>(
      dstar.end() - std::lower_bound(dstar.begin(), dstar.end(), t.statistic));
  t.p_value = (1.0 + at_least) / static_cast<double>(b + 1);
  t.accepted = t.statistic <= t.critical_value;
  return t;
}

KsTest ks_test_fitted(Family family, const Distribution& fitted, std::span<const double> sample,
                      double alpha, const BootstrapOptions& options) {
  if (!(alpha > 0 && alpha < 1)) bad("KS level alpha must be inside (0, 1)");
  const auto reps = parametric_bootstrap(family, fitted, sample.size(), options);
  return ks_test_from_bootstrap(fitted, sample, alpha, reps);
}

}  // namespace rackopt::statistics
