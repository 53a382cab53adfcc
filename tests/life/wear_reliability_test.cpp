// Monte Carlo wear life at R: thread-count independence and agreement of the
// sampled life at R with the exact single-input quantile (issue 3).
#include "rackopt/life/wear_reliability.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

Drive ship_lift() {
  Drive d = load_problem(std::string(RACKOPT_SOURCE_DIR) + "/problems/ship_lift.yaml");
  d.wear.update_profile = false;  // cheaper; the statistics are what is tested here
  return d;
}

TEST(WearReliability, SameResultOnAnyThreadCount) {
  const Drive d = ship_lift();
  WearReliabilityOptions o;
  o.samples = 64;
  o.bootstrap_replicates = 20;
  o.threads = 1;
  const WearReliabilityResult a = run_wear_reliability(d, o);
  o.threads = 2;
  const WearReliabilityResult b = run_wear_reliability(d, o);
  ASSERT_EQ(a.lives.size(), b.lives.size());
  for (std::size_t i = 0; i < a.lives.size(); ++i) {
    EXPECT_EQ(a.lives[i].value, b.lives[i].value) << i;
    EXPECT_EQ(a.input_values[i][0], b.input_values[i][0]) << i;
  }
}

// One monotone input: R(t) from the exact quantile map (which counts the
// samples drawn outside [max(1, [eps]), eps_max] as failed at t = 0) must
// agree with the Monte Carlo survival fraction within 3 binomial standard
// deviations. The 40-year point checks the bounds: without them the exact
// R(40 y) would be 1 while about 1 % of the samples start above eps_max.
TEST(WearReliability, ExactQuantileAgreesWithMonteCarlo) {
  const Drive d = ship_lift();
  ASSERT_EQ(d.reliability.inputs.size(), 1u);
  WearReliabilityOptions o;
  o.samples = 2000;
  o.bootstrap_replicates = 20;
  const WearReliabilityResult r = run_wear_reliability(d, o);
  ASSERT_TRUE(r.exact.available);
  EXPECT_TRUE(r.exact.life_increases);  // more contact ratio, lower tooth loads, longer life
  EXPECT_GT(r.exact.failed_at_start, 0.0);
  EXPECT_GT(r.summary.immediate_failures, 0u);
  ASSERT_EQ(r.summary.reliability.size(), r.exact.R_at_times.size());
  const double n = static_cast<double>(o.samples);
  for (std::size_t i = 0; i < r.exact.R_at_times.size(); ++i) {
    const double R = r.exact.R_at_times[i];
    const double tol = 3.0 * std::sqrt(std::max(R * (1 - R), 1.0 / n) / n) + 1.0 / n;
    EXPECT_NEAR(r.summary.reliability[i].empirical, R, tol) << "t = " << r.summary.reliability[i].t / kSecondsPerYear << " yr";
  }
  // Life at R inverts R(t): R(t_R) = R.
  ASSERT_EQ(r.exact.life_at_R_years.size(), d.reliability.reliabilities.size());
  for (std::size_t i = 0; i < r.exact.life_at_R_years.size(); ++i) {
    const double tR = r.exact.life_at_R_years[i];
    const double R = d.reliability.reliabilities[i];
    if (R > 1.0 - r.exact.failed_at_start) {
      EXPECT_EQ(tR, 0.0) << "R = " << R << " is above the probability of starting inside the bounds";
      continue;
    }
    std::size_t survive = 0, counted = 0;
    for (const auto& s : r.lives) {
      ++counted;
      if (s.value > tR * kSecondsPerYear) ++survive;
    }
    EXPECT_NEAR(static_cast<double>(survive) / counted, R, 3.0 * std::sqrt(R * (1 - R) / n) + 1.0 / n) << "R = " << R;
  }
}

TEST(WearReliability, ImpossibleSamplesFailAtOnceWithoutStoppingTheRun) {
  Drive d = ship_lift();
  d.reliability.inputs.front().a = 1.536;  // half the samples above the largest possible contact ratio
  d.reliability.inputs.front().b = 0.05;
  WearReliabilityOptions o;
  o.samples = 64;
  o.bootstrap_replicates = 20;
  const WearReliabilityResult r = run_wear_reliability(d, o);
  EXPECT_GT(r.summary.immediate_failures, 10u);
  EXPECT_EQ(r.summary.failed_evaluations, 0u);
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// Hard case (issue 3): 10^4 samples complete, every one evaluated, and the
// survival fractions match the exact quantile map to 3 binomial sd (0.3 %
// at R = 0.5): a test of both the sampler and the exact path at a sample
// size where a bias of half a percent would show.
TEST(WearReliability, TenThousandSamples) {
  Drive d = ship_lift();
  d.wear.profile_points = 60;  // cost; the statistics are what is tested
  WearReliabilityOptions o;
  o.samples = 10000;
  o.bootstrap_replicates = 10;
  const WearReliabilityResult r = run_wear_reliability(d, o);
  ASSERT_EQ(r.lives.size(), 10000u);
  EXPECT_EQ(r.summary.failed_evaluations, 0u);
  EXPECT_EQ(r.summary.samples_total, 10000u);
  for (const auto& s : r.lives) ASSERT_TRUE(std::isfinite(s.value));
  ASSERT_EQ(r.summary.reliability.size(), r.exact.R_at_times.size());
  for (std::size_t i = 0; i < r.exact.R_at_times.size(); ++i) {
    const double R = r.exact.R_at_times[i];
    EXPECT_NEAR(r.summary.reliability[i].empirical, R, 3.0 * std::sqrt(std::max(R * (1 - R), 1e-4) / 1e4) + 1e-4)
        << "t = " << r.summary.reliability[i].t / kSecondsPerYear << " yr";
  }
}

}  // namespace
}  // namespace rackopt
