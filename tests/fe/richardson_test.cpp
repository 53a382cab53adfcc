// Observed order and Richardson extrapolation on synthetic sequences: exact
// for f* + C h^p, and a clear status for sequences that are not asymptotic.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "rackopt/fe/richardson.hpp"

namespace rackopt::fe {
namespace {

std::vector<double> power_law(double f_star, double c, double p, double h0, double ratio, int levels) {
  std::vector<double> v;
  for (int k = 0; k < levels; ++k) v.push_back(f_star + c * std::pow(h0 / std::pow(ratio, k), p));
  return v;
}

TEST(Richardson, ExactForAPowerLaw) {
  struct Case {
    double f_star, c, p, ratio;
  };
  for (const Case& k : {Case{7.3e8, -2e9, 2.0, 2.0}, Case{1.0, 0.3, 3.7, 2.0}, Case{-4.0, 1e-2, 1.3, 1.5},
                        Case{2.5e-10, 1e-9, 0.8, 3.0}}) {
    const std::vector<double> v = power_law(k.f_star, k.c, k.p, 0.1, k.ratio, 3);
    const RichardsonEstimate e = richardson(v, k.ratio);
    ASSERT_EQ(e.status, ConvergenceStatus::kAsymptotic);
    EXPECT_NEAR(e.order, k.p, 1e-9 * k.p);
    EXPECT_NEAR(e.extrapolated, k.f_star, 1e-11 * std::abs(k.f_star));
    ASSERT_EQ(e.relative_error.size(), 3u);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(e.relative_error[j], std::abs(v[j] - k.f_star) / std::abs(k.f_star), 1e-9);
    }
    EXPECT_GT(e.relative_error[0], e.relative_error[1]);
    EXPECT_GT(e.relative_error[1], e.relative_error[2]);
  }
}

TEST(Richardson, UsesTheLastThreeLevelsAndRatesEveryLevel) {
  // A pre-asymptotic first level does not spoil the estimate from the last three.
  std::vector<double> v = power_law(5.0, 1.0, 2.0, 1.0, 2.0, 4);
  v[0] = 100.0;
  const RichardsonEstimate e = richardson(v);
  ASSERT_EQ(e.status, ConvergenceStatus::kAsymptotic);
  EXPECT_NEAR(e.order, 2.0, 1e-9);
  EXPECT_NEAR(e.extrapolated, 5.0, 1e-12);
  ASSERT_EQ(e.relative_error.size(), 4u);
  EXPECT_NEAR(e.relative_error[0], 19.0, 1e-9);
}

TEST(Richardson, NonAsymptoticSequencesSaySo) {
  const std::vector<double> oscillating = {1.0, 1.1, 1.05};
  const std::vector<double> diverging = {1.0, 1.01, 1.03};
  const std::vector<double> stalled = {1.0, 1.0, 1.02};
  for (const auto& [v, status] : {std::pair{oscillating, ConvergenceStatus::kOscillating},
                                  std::pair{diverging, ConvergenceStatus::kDiverging},
                                  std::pair{stalled, ConvergenceStatus::kDiverging}}) {
    const RichardsonEstimate e = richardson(v);
    EXPECT_EQ(e.status, status) << to_string(e.status);
    EXPECT_TRUE(std::isnan(e.order));
    EXPECT_TRUE(std::isnan(e.extrapolated));
    for (double r : e.relative_error) EXPECT_TRUE(std::isnan(r));
  }
  EXPECT_EQ(to_string(ConvergenceStatus::kOscillating), "oscillating");
}

TEST(Richardson, DifferencesAtTheResolutionAreResolved) {
  // Seven printed digits: a finest change of 3e-8 is noise, the finest value stands.
  const std::vector<double> v = {1.002, 1.0000001, 1.00000007};
  const RichardsonEstimate e = richardson(v, 2, 1e-6);
  EXPECT_EQ(e.status, ConvergenceStatus::kResolved);
  EXPECT_DOUBLE_EQ(e.extrapolated, 1.00000007);
  EXPECT_NEAR(e.relative_error[0], 1.99993e-3, 1e-8);
  // Without a resolution the same numbers are a (very fast) asymptotic sequence.
  EXPECT_EQ(richardson(v).status, ConvergenceStatus::kAsymptotic);
}

TEST(Richardson, BadInputIsRefused) {
  EXPECT_THROW(richardson(std::vector<double>{1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(richardson(std::vector<double>{1.0, NAN, 2.0}), std::invalid_argument);
  EXPECT_THROW(richardson(std::vector<double>{1.0, 2.0, 3.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(richardson(std::vector<double>{1.0, 2.0, 3.0}, 2.0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt::fe
