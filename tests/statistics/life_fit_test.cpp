// Maximum-likelihood fits (rackopt/statistics/life_fit.hpp).
// Expected values come from
//  * samples drawn with the C++ standard library's own generators
//    (std::gamma_distribution, std::weibull_distribution,
//    std::lognormal_distribution on std::mt19937_64), independent of the
//    library's sampling code; the fit must recover the true parameters within
//    4 asymptotic standard errors, from the Fisher information:
//      gamma  (Choi & Wette 1969): var k = k / (N (k psi'(k) - 1)),
//                                  var theta = theta^2 psi'(k) / (N (k psi'(k) - 1));
//      Weibull (Cohen 1965): var b = 0.6079 b^2 / N, var a = 1.1087 a^2 / (N b^2);
//      lognormal: se(mu) = sigma / sqrt N, se(sigma) = sigma / sqrt(2N);
//  * the likelihood equations themselves, evaluated here with GSL's digamma
//    (gamma: ln k - psi(k) = ln mean - mean ln x) or directly (Weibull profile);
//  * the maximum property: ln L at the fit exceeds ln L at nearby parameters;
//  * docs/models/reliability.md, the wear paper's reliability table.
#include "rackopt/statistics/life_fit.hpp"

#include <gsl/gsl_sf_psi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {
namespace {

template <class Dist>
std::vector<double> draw(Dist dist, std::size_t n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<double> x(n);
  for (double& v : x) v = dist(g);
  return x;
}

TEST(GammaFit, RecoversParametersOfLargeSample) {
  const double k = 150.0, theta = 0.4;  // mean 60, cv 0.082 (a seed-004-like life in years)
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto x = draw(std::gamma_distribution<double>(k, theta), 20000, seed);
    const auto fit = fit_gamma(x);
    const double t1 = gsl_sf_psi_1(k), n = 20000;
    const double se_k = std::sqrt(k / (n * (k * t1 - 1))),
                 se_theta = std::sqrt(theta * theta * t1 / (n * (k * t1 - 1)));
    EXPECT_NEAR(fit.distribution.first(), k, 4 * se_k);
    EXPECT_NEAR(fit.distribution.second(), theta, 4 * se_theta);
  }
  // Shape below 1 (exponential-like) as well.
  const auto x = draw(std::gamma_distribution<double>(0.7, 3.0), 20000, 5);
  const auto fit = fit_gamma(x);
  const double t1 = gsl_sf_psi_1(0.7);
  EXPECT_NEAR(fit.distribution.first(), 0.7, 4 * std::sqrt(0.7 / (20000 * (0.7 * t1 - 1))));
}

TEST(GammaFit, SatisfiesScoreEquation) {
  const auto x = draw(std::gamma_distribution<double>(4.0, 2.0e9), 5000, 7);
  const auto fit = fit_gamma(x);
  double m = 0, ml = 0;
  for (double v : x) m += v / x.size(), ml += std::log(v) / x.size();
  const double k = fit.distribution.first();
  EXPECT_NEAR(std::log(k) - gsl_sf_psi(k), std::log(m) - ml, 1e-11);
  EXPECT_NEAR(fit.distribution.first() * fit.distribution.second(), m, 1e-12 * m);  // scale = mean / k
}

TEST(GammaFit, SmallSpreadKeepsItsDigits) {
  // cv = 1e-4: shape ~ 1e8. ln mean - mean ln x ~ 5e-9 would lose half its
  // digits if formed as a difference of two numbers near ln(2e9) = 21.4.
  const auto x = draw(std::gamma_distribution<double>(1e8, 20.0), 20000, 8);
  const auto fit = fit_gamma(x);
  EXPECT_NEAR(fit.distribution.first(), 1e8, 4 * std::sqrt(2.0 / 20000) * 1e8);  // se k ~ k sqrt(2/N)
}

TEST(WeibullFit, RecoversParametersAndSolvesProfileEquation) {
  const double a = 2.0e9, b = 12.0;
  for (unsigned seed : {1u, 2u}) {
    // std::weibull_distribution(shape, scale).
    const auto x = draw(std::weibull_distribution<double>(b, a), 20000, seed);
    const auto fit = fit_weibull(x);
    const double n = 20000;
    EXPECT_NEAR(fit.distribution.second(), b, 4 * std::sqrt(0.6079 * b * b / n));
    EXPECT_NEAR(fit.distribution.first(), a, 4 * std::sqrt(1.1087 * a * a / (n * b * b)));
    // Profile equation sum x^b ln x / sum x^b - 1/b - mean ln x = 0 (x scaled by a to keep x^b finite).
    const double bh = fit.distribution.second();
    double s0 = 0, s1 = 0, ml = 0;
    for (double v : x) {
      const double w = std::pow(v / a, bh);
      s0 += w, s1 += w * std::log(v), ml += std::log(v) / n;
    }
    EXPECT_NEAR(s1 / s0 - 1 / bh - ml, 0.0, 1e-10);
  }
  // Shape below 1.
  const auto x = draw(std::weibull_distribution<double>(0.5, 3.0), 20000, 3);
  EXPECT_NEAR(fit_weibull(x).distribution.second(), 0.5, 4 * std::sqrt(0.6079 * 0.25 / 20000));
}

TEST(LognormalFit, ClosedForm) {
  const double mu = std::log(1.5e9), s = 0.3;
  const auto x = draw(std::lognormal_distribution<double>(mu, s), 20000, 4);
  const auto fit = fit_lognormal(x);
  EXPECT_NEAR(std::log(fit.distribution.first()), mu, 4 * s / std::sqrt(20000.0));
  EXPECT_NEAR(fit.distribution.second(), s, 4 * s / std::sqrt(40000.0));
}

TEST(LifeFits, AreLikelihoodMaximaAndAicIsConsistent) {
  const auto x = draw(std::gamma_distribution<double>(20.0, 3.0), 2000, 9);
  for (Family f : {Family::kGamma, Family::kWeibull, Family::kLognormal, Family::kNormal}) {
    const auto fit = fit_life_distribution(f, x);
    EXPECT_NEAR(fit.log_likelihood, log_likelihood(fit.distribution, x), 1e-9);
    EXPECT_NEAR(fit.aic, 4.0 - 2.0 * fit.log_likelihood, 1e-9);
    const double p = fit.distribution.first(), q = fit.distribution.second();
    for (double e1 : {-1e-3, 1e-3})
      for (double e2 : {-1e-3, 0.0, 1e-3}) {
        Distribution other = fit.distribution;
        switch (f) {
          case Family::kGamma: other = Distribution::gamma(p * (1 + e1), q * (1 + e2)); break;
          case Family::kWeibull: other = Distribution::weibull(p * (1 + e1), q * (1 + e2)); break;
          case Family::kLognormal: other = Distribution::lognormal(p * (1 + e1), q * (1 + e2)); break;
          default: other = Distribution::normal(p * (1 + e1), q * (1 + e2)); break;
        }
        EXPECT_LT(log_likelihood(other, x), fit.log_likelihood) << family_name(f);
      }
  }
  // The true family wins on AIC for a clearly gamma sample of shape 2 (skewed).
  const auto y = draw(std::gamma_distribution<double>(2.0, 3.0), 5000, 10);
  EXPECT_LT(fit_gamma(y).aic, fit_lognormal(y).aic);
  EXPECT_LT(fit_gamma(y).aic, fit_normal(y).aic);
}

TEST(LifeFits, HardCases) {
  // All equal: no spread, DesignError with a stable code, no NaN.
  const std::vector<double> same(50, 3.0e9);
  for (Family f : {Family::kGamma, Family::kWeibull, Family::kLognormal, Family::kNormal}) {
    try {
      (void)fit_life_distribution(f, same);
      FAIL() << family_name(f);
    } catch (const DesignError& e) {
      EXPECT_EQ(e.code(), "degenerate_life_sample");
    }
  }
  // Spread below 1e-6 of the value (lives that differ in the 8th digit): no
  // fit can resolve it, the same DesignError. Just above, fits exist.
  std::vector<double> tight, resolvable;
  for (int i = 0; i < 50; ++i) {
    tight.push_back(3.0e9 * (1 + 1e-8 * i));
    resolvable.push_back(3.0e9 * (1 + 1e-4 * i));
  }
  for (Family f : {Family::kGamma, Family::kWeibull, Family::kLognormal, Family::kNormal}) {
    try {
      (void)fit_life_distribution(f, tight);
      FAIL() << family_name(f);
    } catch (const DesignError& e) {
      EXPECT_EQ(e.code(), "degenerate_life_sample");
    }
    EXPECT_TRUE(std::isfinite(fit_life_distribution(f, resolvable).aic)) << family_name(f);
  }
  // N = 2 distinct values: fits exist and are finite.
  const std::vector<double> two{1.0, 2.0};
  for (Family f : {Family::kGamma, Family::kWeibull, Family::kLognormal}) {
    const auto fit = fit_life_distribution(f, two);
    EXPECT_TRUE(std::isfinite(fit.log_likelihood));
  }
  EXPECT_NEAR(fit_lognormal(two).distribution.first(), std::sqrt(2.0), 1e-14);  // geometric mean
  // N = 1, non-positive or NaN values.
  EXPECT_THROW(fit_gamma(std::vector<double>{1.0}), DesignError);
  EXPECT_THROW(fit_gamma(std::vector<double>{}), InputError);
  EXPECT_THROW(fit_weibull(std::vector<double>{1.0, 0.0, 2.0}), InputError);
  EXPECT_THROW(fit_lognormal(std::vector<double>{1.0, NAN, 2.0}), InputError);
  // 10^4 samples.
  const auto x = draw(std::weibull_distribution<double>(3.0, 1.0), 10000, 11);
  for (Family f : {Family::kGamma, Family::kWeibull, Family::kLognormal})
    EXPECT_TRUE(std::isfinite(fit_life_distribution(f, x).aic));
}

// docs/models/reliability.md: the wear paper's reliability table (years).
const std::vector<double> kSeedYears{75, 65, 60, 55};
const std::vector<double> kSeedR{0.0135, 0.4054, 0.7949, 0.9743};

TEST(ReliabilityPointFit, WearPaperGammaTable) {
  const auto fit = fit_to_reliability_points(Family::kGamma, kSeedYears, kSeedR);
  const auto& d = fit.distribution;
  std::printf("the wear paper's gamma: shape %.4f scale %.6f y, mean %.4f y, sd %.4f y, cv %.5f, "
              "max |res| %.5f, R(40) = 1 - %.3g\n",
              d.first(), d.second(), d.mean(), d.standard_deviation(),
              d.standard_deviation() / d.mean(), fit.max_abs_residual, d.cdf(40.0));
  for (std::size_t i = 0; i < kSeedYears.size(); ++i)
    EXPECT_NEAR(d.survival(kSeedYears[i]), kSeedR[i], 0.02) << kSeedYears[i] << " y";
  // The table values come from a fitted gamma distribution (docs/models/reliability.md).
  // A 4-decimal table of a gamma reproduces to its rounding (5e-5), with margin.
  EXPECT_LT(fit.max_abs_residual, 2e-4);
  // The 40-year row (R = 0.9992, failure probability 8e-4) is inconsistent:
  // the fit's failure probability at 40 y is orders of magnitude smaller.
  EXPECT_LT(d.cdf(40.0), 0.0008 / 100);
  // Least squares: no nearby point does better (independent check of the minimiser).
  for (double e1 : {-1e-3, 1e-3})
    for (double e2 : {-1e-3, 1e-3}) {
      const auto o = Distribution::gamma(d.first() * (1 + e1), d.second() * (1 + e2));
      double s = 0;
      for (std::size_t i = 0; i < kSeedYears.size(); ++i)
        s += std::pow(o.survival(kSeedYears[i]) - kSeedR[i], 2);
      EXPECT_GE(s, fit.sum_squared_residuals);
    }
}

TEST(ReliabilityPointFit, WearPaperWeibullIsTheWorst) {
  // docs/models/reliability.md: "The Weibull fit is the worst: its residuals are up to 0.019."
  const auto g = fit_to_reliability_points(Family::kGamma, kSeedYears, kSeedR);
  const auto w = fit_to_reliability_points(Family::kWeibull, kSeedYears, kSeedR);
  const auto l = fit_to_reliability_points(Family::kLognormal, kSeedYears, kSeedR);
  std::printf("the wear paper's max |residual|: gamma %.4f, lognormal %.4f, weibull %.4f\n",
              g.max_abs_residual, l.max_abs_residual, w.max_abs_residual);
  EXPECT_GT(w.max_abs_residual, g.max_abs_residual);
  EXPECT_GT(w.max_abs_residual, l.max_abs_residual);
  EXPECT_NEAR(w.max_abs_residual, 0.019, 0.004);
}

TEST(ReliabilityPointFit, RecoversExactPointsOfAKnownDistribution) {
  const auto truth = Distribution::gamma(80.0, 0.75);
  std::vector<double> t{50, 55, 60, 65, 70}, r;
  for (double v : t) r.push_back(truth.survival(v));
  const auto fit = fit_to_reliability_points(Family::kGamma, t, r);
  EXPECT_NEAR(fit.distribution.first(), 80.0, 1e-3 * 80);
  EXPECT_NEAR(fit.distribution.second(), 0.75, 1e-3 * 0.75);
  EXPECT_THROW(fit_to_reliability_points(Family::kGamma, std::vector<double>{1.0},
                                         std::vector<double>{0.5}),
               InputError);
  EXPECT_THROW(fit_to_reliability_points(Family::kGamma, std::vector<double>{1.0, 2.0},
                                         std::vector<double>{0.5, 1.0}),
               InputError);
}

}  // namespace
}  // namespace rackopt::statistics
