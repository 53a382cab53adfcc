// Point sets and the threaded evaluator (rackopt/statistics/sampling.hpp).
// Expected values come from
//  * properties that must hold exactly (bitwise reproducibility for any thread
//    count, points strictly inside (0,1), dimension 41 rejected because
//    gsl_qrng_sobol->max_dimension is 40, docs/dependencies.md, "GSL 2.7");
//  * the known first Sobol points of GSL (0.5; 0.75, 0.25; ... for dimension 1-2,
//    docs/dependencies.md, "GSL 2.7" and Bratley & Fox 1988 direction numbers);
//  * uniform-distribution moments: mean 1/2, variance 1/12, zero correlation
//    between coordinates, within a few standard errors;
//  * the Sobol equidistribution property: the first 2^m points of the
//    randomly shifted net put exactly one point in each 1/2^m interval of
//    every coordinate.
#include "rackopt/statistics/sampling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {
namespace {

TEST(CounterUniform, IsAPureFunctionInsideTheOpenInterval) {
  EXPECT_EQ(counter_uniform(7, 3, 2), counter_uniform(7, 3, 2));
  EXPECT_NE(counter_uniform(7, 3, 2), counter_uniform(8, 3, 2));
  EXPECT_NE(counter_uniform(7, 3, 2), counter_uniform(7, 2, 3));
  for (std::uint64_t i = 0; i < 10000; ++i) {
    const double u = counter_uniform(0, i, 0);
    EXPECT_GT(u, 0.0);
    EXPECT_LT(u, 1.0);
  }
}

TEST(PseudoRandomPoints, HaveUniformMomentsAndUncorrelatedCoordinates) {
  const std::size_t n = 100000, d = 3;
  const auto p = pseudo_random_points(n, d, 42);
  for (std::size_t j = 0; j < d; ++j) {
    double m = 0, v = 0;
    for (std::size_t i = 0; i < n; ++i) m += p.at(i, j) / n;
    for (std::size_t i = 0; i < n; ++i) v += (p.at(i, j) - m) * (p.at(i, j) - m) / n;
    // Standard error of the mean: sqrt(1/12/n) = 9.1e-4; allow 5 of them.
    EXPECT_NEAR(m, 0.5, 5 * 9.1e-4);
    EXPECT_NEAR(v, 1.0 / 12.0, 5 * std::sqrt(1.0 / 180.0 / n));  // var of U^2-type estimator
  }
  // Correlation of coordinates 0 and 1 and of consecutive samples: se 1/sqrt(n).
  double c01 = 0, cseq = 0;
  for (std::size_t i = 0; i < n; ++i) c01 += (p.at(i, 0) - 0.5) * (p.at(i, 1) - 0.5) * 12.0 / n;
  for (std::size_t i = 1; i < n; ++i)
    cseq += (p.at(i, 0) - 0.5) * (p.at(i - 1, 0) - 0.5) * 12.0 / n;
  EXPECT_NEAR(c01, 0.0, 5 / std::sqrt(double(n)));
  EXPECT_NEAR(cseq, 0.0, 5 / std::sqrt(double(n)));
}

TEST(PseudoRandomPoints, SameSeedSamePointsDifferentSeedsDiffer) {
  const auto a = pseudo_random_points(100, 4, 1), b = pseudo_random_points(100, 4, 1);
  const auto c = pseudo_random_points(100, 4, 2);
  EXPECT_EQ(a.u, b.u);
  std::size_t equal = 0;
  for (std::size_t k = 0; k < a.u.size(); ++k) equal += a.u[k] == c.u[k];
  EXPECT_EQ(equal, 0u);
  // A prefix of a larger set is the smaller set (values depend on the index alone).
  const auto big = pseudo_random_points(1000, 4, 1);
  EXPECT_TRUE(std::equal(a.u.begin(), a.u.end(), big.u.begin()));
}

TEST(SobolPoints, MatchGslSequenceAndRejectDimensionBeyond40) {
  const auto p = sobol_points(4, 2, false, 0);
  // GSL skips the origin: (0.5,0.5), (0.75,0.25), (0.25,0.75), (0.375,0.375).
  const double expected[4][2] = {{0.5, 0.5}, {0.75, 0.25}, {0.25, 0.75}, {0.375, 0.375}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_DOUBLE_EQ(p.at(i, j), expected[i][j]);
  EXPECT_EQ(sobol_max_dimension(), 40u);
  EXPECT_NO_THROW(sobol_points(8, 40, false, 0));
  EXPECT_THROW(sobol_points(8, 41, false, 0), InputError);
  EXPECT_THROW(sobol_points(8, 41, true, 0), InputError);
  // Dimension 40 is not all zeros (the failure GSL shows silently at 41).
  const auto p40 = sobol_points(8, 40, false, 0);
  for (std::size_t j = 0; j < 40; ++j) EXPECT_GT(p40.at(3, j), 0.0);
}

TEST(SobolPoints, NeverZeroOrOne) {
  for (bool randomize : {false, true})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const auto p = sobol_points(4096, 40, randomize, seed);
      for (double u : p.u) {
        ASSERT_GT(u, 0.0);
        ASSERT_LT(u, 1.0);
      }
    }
}

TEST(SobolPoints, ShiftedNetIsStratifiedAndSeedDependent) {
  const std::size_t m = 10, n = std::size_t{1} << m;
  const auto p = sobol_points(n, 5, true, 11);
  for (std::size_t j = 0; j < 5; ++j) {
    std::vector<int> hits(n, 0);
    for (std::size_t i = 0; i < n; ++i) hits[static_cast<std::size_t>(p.at(i, j) * n)]++;
    EXPECT_EQ(*std::min_element(hits.begin(), hits.end()), 1) << "dimension " << j;
  }
  const auto q = sobol_points(n, 5, true, 12);
  EXPECT_NE(p.u, q.u);
  EXPECT_EQ(p.u, sobol_points(n, 5, true, 11).u);
}

TEST(EvaluateSamples, IdenticalResultsOnOneTwoAndSevenThreads) {
  const auto pts = pseudo_random_points(5000, 3, 99);
  auto f = [&](std::size_t i) {
    // A nonlinear function of the sample's own point only.
    return std::exp(pts.at(i, 0)) * std::log(pts.at(i, 1)) + pts.at(i, 2);
  };
  const auto r1 = evaluate_samples(pts.count, 1, f);
  const auto r2 = evaluate_samples(pts.count, 2, f);
  std::atomic<std::size_t> done{0};
  const auto r7 = evaluate_samples(pts.count, 7, f, &done);
  EXPECT_EQ(done.load(), pts.count);
  for (std::size_t i = 0; i < pts.count; ++i) {
    ASSERT_TRUE(r1[i].ok());
    EXPECT_EQ(r1[i].value, r2[i].value);
    EXPECT_EQ(r1[i].value, r7[i].value);
    EXPECT_EQ(r1[i].value, f(i));
  }
}

TEST(EvaluateSamples, FailingSamplesAreRecordedNotFatal) {
  auto f = [](std::size_t i) -> double {
    if (i % 10 == 3) throw DesignError("contact_ratio_below_one", "eps = 0.9 < 1");
    if (i % 10 == 5) throw std::runtime_error("solver diverged");
    if (i % 10 == 7) return std::nan("");
    return static_cast<double>(i);
  };
  for (unsigned t : {1u, 3u}) {
    const auto r = evaluate_samples(100, t, f);
    int ok = 0;
    for (std::size_t i = 0; i < 100; ++i) {
      if (i % 10 == 3) {
        EXPECT_EQ(r[i].status, SampleResult::Status::kDesignError);
        EXPECT_EQ(r[i].code, "contact_ratio_below_one");
      } else if (i % 10 == 5) {
        EXPECT_EQ(r[i].status, SampleResult::Status::kFailed);
        EXPECT_EQ(r[i].message, "solver diverged");
      } else if (i % 10 == 7) {
        EXPECT_EQ(r[i].code, "non_finite");
      } else {
        ASSERT_TRUE(r[i].ok());
        EXPECT_EQ(r[i].value, static_cast<double>(i));
        ++ok;
      }
    }
    EXPECT_EQ(ok, 70);
  }
}

}  // namespace
}  // namespace rackopt::statistics
