// Kolmogorov-Smirnov with estimated parameters (goodness_of_fit.hpp).
// Expected values come from
//  * Lilliefors (1967), JASA 62:399, Table 1: the 5% critical value of D_N for
//    a normal with mean and variance estimated is 0.886/sqrt(N) for N > 30
//    (the same holds for a lognormal: it is a normal in ln x);
//  * the classical Kolmogorov asymptotic value sqrt(-ln(alpha/2)/2)/sqrt(N),
//    1.3581/sqrt(N) at 5% (docs/models/reliability.md; Smirnov 1948 table);
//  * the definition of a level-alpha test: on samples from the fitted family,
//    the rejection rate is alpha (coarse check with a binomial tolerance);
//  * a hand-computable D_N for a tiny sample.
#include "rackopt/statistics/goodness_of_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/statistics/life_fit.hpp"

namespace rackopt::statistics {
namespace {

TEST(KsStatistic, TinySampleByHand) {
  // Uniform(0,1), sample {0.1, 0.4, 0.7}: F_N jumps to 1/3, 2/3, 1.
  // Gaps: |1/3-0.1|=0.2333, |0.4-1/3|=0.0667, |2/3-0.4|=0.2667, |0.7-2/3|=0.0333, |1-0.7|=0.3.
  const auto u = Distribution::uniform(0, 1);
  EXPECT_NEAR(ks_statistic(u, std::vector<double>{0.7, 0.1, 0.4}), 0.3, 1e-15);
  EXPECT_THROW(ks_statistic(u, std::vector<double>{}), InputError);
}

TEST(KsCriticalValue, ClassicalAsymptotic) {
  EXPECT_NEAR(ks_known_parameter_critical_value(1000, 0.05), 1.3581 / std::sqrt(1000.0), 1e-5);
  EXPECT_NEAR(ks_known_parameter_critical_value(1000, 0.05), 0.043, 5e-4);  // docs/models/reliability.md
  EXPECT_NEAR(ks_known_parameter_critical_value(100, 0.01), 1.6276 / 10, 1e-4);
  EXPECT_THROW(ks_known_parameter_critical_value(10, 0.0), InputError);
}

TEST(KsBootstrap, CriticalValueForFittedNormalAndLognormalMatchesLilliefors) {
  const std::size_t n = 1000;
  std::mt19937_64 g(1);
  std::normal_distribution<double> z(0.0, 1.0);
  std::vector<double> xn(n), xl(n);
  for (std::size_t i = 0; i < n; ++i) {
    xn[i] = 100 + 10 * z(g);
    xl[i] = 2e9 * std::exp(0.1 * z(g));
  }
  BootstrapOptions opt;
  opt.replicates = 600;
  opt.threads = 2;
  const double lilliefors = 0.886 / std::sqrt(double(n));
  for (auto [f, x] : {std::pair{Family::kNormal, &xn}, std::pair{Family::kLognormal, &xl}}) {
    const auto fit = fit_life_distribution(f, *x);
    const auto t = ks_test_fitted(f, fit.distribution, *x, 0.05, opt);
    // 600 replicates: the 95% quantile is known to about +-5%; allow 12%.
    std::printf("%s: bootstrap 5%% critical value * sqrt(N) = %.4f (Lilliefors 0.886)\n",
                family_name(f), t.critical_value * std::sqrt(double(n)));
    EXPECT_NEAR(t.critical_value, lilliefors, 0.12 * lilliefors) << family_name(f);
    EXPECT_LT(t.critical_value, 0.75 * t.known_parameter_critical_value);
    EXPECT_EQ(t.replicates_used, 600);
    EXPECT_TRUE(t.accepted);  // a true normal/lognormal sample
    EXPECT_GT(t.p_value, 0.05);
  }
}

TEST(KsBootstrap, GammaPassesBimodalFails) {
  std::mt19937_64 g(2);
  std::gamma_distribution<double> life(150.0, 0.4);
  std::vector<double> x(1000);
  for (double& v : x) v = life(g);
  BootstrapOptions opt;
  const auto fit = fit_gamma(x);
  EXPECT_TRUE(ks_test_fitted(Family::kGamma, fit.distribution, x, 0.05, opt).accepted);
  // Two well-separated modes (means 40 and 80): no gamma fits.
  std::gamma_distribution<double> early(100.0, 0.4), late(100.0, 0.8);
  std::vector<double> y(1000);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = i % 2 ? early(g) : late(g);
  const auto bad = fit_gamma(y);
  const auto t = ks_test_fitted(Family::kGamma, bad.distribution, y, 0.05, opt);
  EXPECT_FALSE(t.accepted);
  EXPECT_LT(t.p_value, 0.05);
  EXPECT_GT(t.statistic, t.critical_value);
}

TEST(KsBootstrap, RejectionRateOnTrueModelIsNominal) {
  // 200 samples of N = 100 from a lognormal, each tested with B = 99 (so that
  // (B+1) alpha is an integer and the Monte Carlo test has exact size 5%).
  // Rejections ~ Binomial(200, 0.05): mean 10, sd 3.1. Accept 3..20.
  // The classical critical value rejects almost never (its size is ~0.1% for
  // a fitted normal family): fewer than 3 of 200.
  std::mt19937_64 g(3);
  std::lognormal_distribution<double> life(std::log(60.0), 0.08);
  int reject_boot = 0, reject_classical = 0;
  for (int rep = 0; rep < 200; ++rep) {
    std::vector<double> x(100);
    for (double& v : x) v = life(g);
    const auto fit = fit_lognormal(x);
    BootstrapOptions opt;
    opt.replicates = 99;
    opt.seed = 1000 + rep;
    const auto t = ks_test_fitted(Family::kLognormal, fit.distribution, x, 0.05, opt);
    reject_boot += t.accepted ? 0 : 1;
    reject_classical += t.statistic > t.known_parameter_critical_value ? 1 : 0;
  }
  std::printf("lognormal N=100: bootstrap rejects %d of 200, classical %d of 200\n", reject_boot,
              reject_classical);
  EXPECT_GE(reject_boot, 3);
  EXPECT_LE(reject_boot, 20);
  EXPECT_LT(reject_classical, 3);
}

TEST(KsBootstrap, GammaRejectionRateOnTrueModelIsNominal) {
  // As above for the gamma family (its null distribution depends on the shape).
  std::mt19937_64 g(4);
  std::gamma_distribution<double> life(5.0, 2.0);
  int reject = 0;
  for (int rep = 0; rep < 100; ++rep) {
    std::vector<double> x(60);
    for (double& v : x) v = life(g);
    const auto fit = fit_gamma(x);
    BootstrapOptions opt;
    opt.replicates = 99;
    opt.seed = 7 + rep;
    reject += ks_test_fitted(Family::kGamma, fit.distribution, x, 0.05, opt).accepted ? 0 : 1;
  }
  // Binomial(100, 0.05): mean 5, sd 2.2.
  std::printf("gamma N=60: %d of 100 rejected at 5%%\n", reject);
  EXPECT_GE(reject, 1);  // P(0) = 0.006
  EXPECT_LE(reject, 12);
}

TEST(KsBootstrap, DeterministicForAnyThreadCount) {
  std::mt19937_64 g(5);
  std::weibull_distribution<double> life(10.0, 60.0);
  std::vector<double> x(300);
  for (double& v : x) v = life(g);
  const auto fit = fit_weibull(x);
  BootstrapOptions a, b, c;
  a.threads = 1, b.threads = 3, c.threads = 1;
  c.seed = 2;
  const auto ta = ks_test_fitted(Family::kWeibull, fit.distribution, x, 0.05, a);
  const auto tb = ks_test_fitted(Family::kWeibull, fit.distribution, x, 0.05, b);
  const auto tc = ks_test_fitted(Family::kWeibull, fit.distribution, x, 0.05, c);
  EXPECT_EQ(ta.critical_value, tb.critical_value);
  EXPECT_EQ(ta.p_value, tb.p_value);
  EXPECT_NE(ta.critical_value, tc.critical_value);
}

TEST(DrawSample, GammaVariatesHaveTheRightDistribution) {
  // Marsaglia-Tsang draws (shape >= 1 and < 1) against the exact gamma cdf:
  // the known-parameter KS test applies here (nothing is estimated).
  for (double k : {0.5, 3.0, 180.0}) {
    const auto d = Distribution::gamma(k, 2.0);
    const auto x = draw_sample(d, 20000, 9, 0);
    EXPECT_LT(ks_statistic(d, x), ks_known_parameter_critical_value(20000, 0.001)) << k;
  }
  EXPECT_EQ(draw_sample(Distribution::gamma(3, 1), 10, 1, 4),
            draw_sample(Distribution::gamma(3, 1), 10, 1, 4));
}

}  // namespace
}  // namespace rackopt::statistics
