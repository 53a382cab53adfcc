// Distributions (rackopt/statistics/distribution.hpp) against
//  * closed forms written here independently (normal via std::erfc, Weibull
//    a(-ln R)^(1/b) as docs/dependencies.md, "GSL 2.7" states, uniform, lognormal via the
//    normal of ln x);
//  * GSL's own gsl_cdf_gamma_P (a different code path from the class, which
//    goes through the survival/quantile routines);
//  * the tabulated standard normal quantile z_0.975 = 1.959964 (Abramowitz &
//    Stegun Table 26.5);
//  * numerical integration of the pdf (trapezoid) against the cdf.
#include "rackopt/statistics/distribution.hpp"

#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {
namespace {

std::vector<Distribution> all_families() {
  return {Distribution::normal(10.0, 2.0), Distribution::lognormal(5.0, 0.4),
          Distribution::uniform(-1.0, 3.0), Distribution::weibull(60.0, 12.0),
          Distribution::gamma(150.0, 0.4), Distribution::gamma(0.6, 2.0)};
}

TEST(Distribution, QuantileInvertsCdfAndSurvivalQuantileInvertsSurvival) {
  for (const auto& d : all_families()) {
    for (double p : {1e-6, 0.01, 0.2, 0.5, 0.8, 0.99, 1 - 1e-6}) {
      const double x = d.quantile(p);
      EXPECT_NEAR(d.cdf(x), p, 1e-9 * std::max(1.0, 1.0 / p)) << d.describe() << " p=" << p;
      const double y = d.survival_quantile(p);
      EXPECT_NEAR(d.survival(y), p, 1e-9) << d.describe() << " q=" << p;
      EXPECT_NEAR(d.cdf(x) + d.survival(x), 1.0, 1e-14);
    }
  }
}

TEST(Distribution, QuantileIsMonotone) {
  for (const auto& d : all_families()) {
    double prev = -1e300;
    for (int i = 1; i < 1000; ++i) {
      const double x = d.quantile(i / 1000.0);
      EXPECT_GE(x, prev) << d.describe();
      prev = x;
    }
  }
}

TEST(Distribution, NormalQuantileMatchesTable) {
  // A&S Table 26.5: z such that Phi(z) = 0.975 is 1.959964.
  EXPECT_NEAR(Distribution::normal(0, 1).quantile(0.975), 1.959964, 1e-6);
  EXPECT_NEAR(Distribution::normal(3, 2).quantile(0.975), 3 + 2 * 1.959964, 2e-6);
  // Phi(x) = erfc(-x/sqrt2)/2.
  const auto d = Distribution::normal(3, 2);
  for (double x : {-2.0, 1.0, 3.0, 7.5})
    EXPECT_NEAR(d.cdf(x), 0.5 * std::erfc(-(x - 3) / 2 / std::numbers::sqrt2), 1e-15);
}

TEST(Distribution, WeibullLifeAtReliabilityClosedForm) {
  // docs/dependencies.md, "GSL 2.7": life at reliability R = a (-ln R)^(1/b).
  const double a = 60.0, b = 12.0;
  const auto d = Distribution::weibull(a, b);
  for (double r : {0.999, 0.9, 0.5, 0.1}) {
    EXPECT_NEAR(d.survival_quantile(r), a * std::pow(-std::log(r), 1 / b), 1e-12 * a);
    EXPECT_NEAR(d.quantile(1 - r), a * std::pow(-std::log(r), 1 / b), 1e-10 * a);
  }
  // Mean a Gamma(1 + 1/b).
  EXPECT_NEAR(d.mean(), a * std::tgamma(1 + 1 / b), 1e-12 * a);
  // GSL's own Weibull with a = scale, b = shape.
  EXPECT_NEAR(d.cdf(55.0), gsl_cdf_weibull_P(55.0, a, b), 1e-15);
}

TEST(Distribution, GammaAgreesWithGsl) {
  const auto d = Distribution::gamma(150.0, 0.4);
  for (double x : {40.0, 55.0, 60.0, 65.0, 80.0}) {
    EXPECT_NEAR(d.cdf(x), gsl_cdf_gamma_P(x, 150.0, 0.4), 1e-14);
  }
  EXPECT_DOUBLE_EQ(d.mean(), 60.0);
  EXPECT_NEAR(d.standard_deviation(), std::sqrt(150.0) * 0.4, 1e-12);
}

TEST(Distribution, LognormalIsNormalOfLog) {
  const auto d = Distribution::lognormal(5.0, 0.4);
  const auto n = Distribution::normal(std::log(5.0), 0.4);
  for (double x : {1.0, 4.0, 5.0, 9.0}) {
    EXPECT_NEAR(d.cdf(x), n.cdf(std::log(x)), 1e-14);
    EXPECT_NEAR(d.pdf(x), n.pdf(std::log(x)) / x, 1e-14);
  }
  EXPECT_NEAR(d.quantile(0.5), 5.0, 1e-12);
  EXPECT_NEAR(d.mean(), 5.0 * std::exp(0.08), 1e-12);
}

TEST(Distribution, PdfIntegratesToCdf) {
  for (const auto& d : all_families()) {
    if (d.family() == Family::kGamma && d.first() < 1) continue;  // integrable singularity at 0
    const double a = d.quantile(0.001), b = d.quantile(0.9);
    const int n = 20000;
    double s = 0;
    for (int i = 0; i <= n; ++i) {
      const double x = a + (b - a) * i / n;
      s += (i == 0 || i == n ? 0.5 : 1.0) * d.pdf(x);
    }
    s *= (b - a) / n;
    EXPECT_NEAR(s, d.cdf(b) - d.cdf(a), 1e-6) << d.describe();
  }
}

TEST(Distribution, StandardDeviationMatchesMomentsByQuadrature) {
  for (const auto& d : all_families()) {
    // E[X^2] by the midpoint rule on u: integral_0^1 Q(u)^2 du.
    const int n = 40000;
    double m1 = 0, m2 = 0;
    for (int i = 0; i < n; ++i) {
      const double x = d.quantile((i + 0.5) / n);
      m1 += x / n;
      m2 += x * x / n;
    }
    EXPECT_NEAR(m1, d.mean(), 2e-3 * d.standard_deviation()) << d.describe();
    EXPECT_NEAR(std::sqrt(m2 - m1 * m1), d.standard_deviation(), 1e-2 * d.standard_deviation())
        << d.describe();
  }
}

TEST(Distribution, RejectsBadParametersAndProbabilities) {
  EXPECT_THROW(Distribution::normal(0, 0), InputError);
  EXPECT_THROW(Distribution::lognormal(-1, 1), InputError);
  EXPECT_THROW(Distribution::uniform(2, 1), InputError);
  EXPECT_THROW(Distribution::weibull(1, -2), InputError);
  EXPECT_THROW(Distribution::gamma(NAN, 1), InputError);
  const auto d = Distribution::gamma(2, 1);
  EXPECT_THROW((void)d.quantile(0.0), InputError);
  EXPECT_THROW((void)d.quantile(1.0), InputError);
  EXPECT_THROW((void)d.cdf(NAN), InputError);
  EXPECT_THROW(family_from_name("beta"), InputError);
  EXPECT_EQ(family_from_name("weibull"), Family::kWeibull);
}

TEST(Distribution, RandomInputMapping) {
  RandomInput in;
  in.key = "wear.coefficient";
  in.distribution = RandomInput::Distribution::kLognormal;
  in.a = 3e-6;
  in.b = 0.5;
  const auto d = to_distribution(in);
  EXPECT_EQ(d.family(), Family::kLognormal);
  EXPECT_NEAR(d.quantile(0.5), 3e-6, 1e-18);
  in.b = -1;
  try {
    (void)to_distribution(in);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "reliability.inputs.wear.coefficient");
  }
  in.distribution = RandomInput::Distribution::kWeibull;
  in.a = 2, in.b = 3;
  EXPECT_EQ(to_distribution(in).family(), Family::kWeibull);
}

// cdf_sorted integrates the gamma density between order statistics: it must
// agree with GSL's incomplete gamma at every value, in the bulk (tiny gaps),
// the tails (large gaps: re-anchored) and across shapes, and fall back to
// cdf() for the other families and for shape < 2.
TEST(Distribution, CdfSortedAgreesWithPointwiseCdf) {
  std::vector<Distribution> ds = {Distribution::gamma(2.0, 1.0), Distribution::gamma(5.5, 3.0),
                                  Distribution::gamma(192.0, 1.05e7), Distribution::gamma(5000.0, 0.01),
                                  Distribution::gamma(0.7, 2.0), Distribution::lognormal(64.0, 0.07),
                                  Distribution::weibull(66.0, 14.0)};
  for (const Distribution& d : ds) {
    for (std::size_t n : {3u, 50u, 1000u, 20000u}) {
      std::vector<double> x(n);
      // Deterministic, unevenly spread probabilities including both tails.
      for (std::size_t i = 0; i < n; ++i) {
        const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        x[i] = d.quantile(std::clamp(u * u * (3.0 - 2.0 * u) * 0.999998 + 1e-6, 1e-9, 1.0 - 1e-9));
      }
      std::sort(x.begin(), x.end());
      std::vector<double> f(n);
      d.cdf_sorted(x, f);
      double err = 0;
      for (std::size_t i = 0; i < n; ++i) err = std::max(err, std::fabs(f[i] - d.cdf(x[i])));
      EXPECT_LT(err, 1e-9) << d.describe() << " n = " << n;
    }
  }
  std::vector<double> out(2);
  const std::vector<double> three{1.0, 2.0, 3.0};
  EXPECT_THROW(Distribution::gamma(3, 1).cdf_sorted(three, out), InputError);
  const std::vector<double> descending{3.0, 2.0};
  EXPECT_THROW(Distribution::gamma(3, 1).cdf_sorted(descending, out), InputError);
}

}  // namespace
}  // namespace rackopt::statistics
