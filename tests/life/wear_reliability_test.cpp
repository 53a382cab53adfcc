// Monte Carlo wear life at R: thread-count independence and agreement of the
// sampled life at R with the exact single-input quantile (issue 3).
#include "rackopt/life/wear_reliability.hpp"

#include <gtest/gtest.h>

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

// One monotone input: the exact life at R must lie inside the empirical
// order-statistic confidence interval of the Monte Carlo sample.
TEST(WearReliability, ExactQuantileInsideMonteCarloInterval) {
  const Drive d = ship_lift();
  ASSERT_EQ(d.reliability.inputs.size(), 1u);
  WearReliabilityOptions o;
  o.samples = 400;
  o.bootstrap_replicates = 20;
  const WearReliabilityResult r = run_wear_reliability(d, o);
  ASSERT_TRUE(r.exact.available);
  EXPECT_TRUE(r.exact.life_increases);  // more contact ratio margin, longer life
  ASSERT_EQ(r.summary.life.size(), d.reliability.reliabilities.size());
  for (std::size_t i = 0; i < r.summary.life.size(); ++i) {
    const reliability::LifeInterval& e = r.summary.life[i].empirical;
    const double exact_s = r.exact.life_at_R_years[i] * kSecondsPerYear;
    if (e.lower_bounded) {
      EXPECT_GE(exact_s, e.lower * (1 - 1e-9)) << "R = " << r.summary.life[i].reliability;
    }
    if (e.upper_bounded) {
      EXPECT_LE(exact_s, e.upper * (1 + 1e-9)) << "R = " << r.summary.life[i].reliability;
    }
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
