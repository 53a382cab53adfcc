// WearReliabilityOptions::exact_only (what the wear_life_at_R metric's exact
// path asks for): no Monte Carlo sample when the exact quantile map exists,
// with the exact results and the nominal life of a run that samples, bit for
// bit; the samples as usual when there is no exact map.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "life_test_drives.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt {
namespace {

// The metric's exact path: one sample, no life table, one thread.
WearReliabilityOptions exact_path_options(bool exact_only) {
  WearReliabilityOptions o;
  o.samples = 1;
  o.life_table = false;
  o.threads = 1;
  o.bootstrap_replicates = 20;
  o.exact_only = exact_only;
  return o;
}

RandomInput relative_normal(const std::string& key, double cv) {
  RandomInput in;
  in.key = key;
  in.distribution = RandomInput::Distribution::kNormal;
  in.cv = cv;
  return in;
}

// Without a life table the direction of life(input) takes two model lives.
// At the first R's two candidate quantiles one of them is that life at R:
// two lives for the exact map, and the same life at R as when the direction
// comes from the quartiles (R = 0.5 first: its candidates are too close to
// tell a direction) and the life at 0.9 is a life of its own.
TEST(ExactOnly, TheDirectionProbesServeTheFirstLifeAtR) {
  Drive d = test::ship_lift_fixed_profile();  // one input: the contact ratio
  d.reliability.reliabilities = {0.9};
  d.reliability.times.clear();
  const WearReliabilityResult at_candidates = run_wear_reliability(d, exact_path_options(true));
  d.reliability.reliabilities = {0.5, 0.9};
  const WearReliabilityResult at_quartiles = run_wear_reliability(d, exact_path_options(true));
  ASSERT_TRUE(at_candidates.exact.available && at_quartiles.exact.available);
  EXPECT_EQ(at_candidates.exact.model_evaluations, 2);
  EXPECT_EQ(at_quartiles.exact.model_evaluations, 4);
  EXPECT_EQ(at_candidates.exact.life_increases, at_quartiles.exact.life_increases);
  ASSERT_EQ(at_candidates.exact.life_at_R_years.size(), 1u);
  ASSERT_EQ(at_quartiles.exact.life_at_R_years.size(), 2u);
  EXPECT_EQ(at_candidates.exact.life_at_R_years[0], at_quartiles.exact.life_at_R_years[1]);
  EXPECT_GT(at_candidates.exact.life_at_R_years[0], 0.0);
}

TEST(ExactOnly, SkipsTheSamplesAndKeepsTheExactResults) {
  Drive d = test::ship_lift_fixed_profile();  // one input: the contact ratio
  d.reliability.reliabilities = {0.9, 0.5};
  d.reliability.times = {60 * kSecondsPerYear};
  const WearReliabilityResult sampled = run_wear_reliability(d, exact_path_options(false));
  const WearReliabilityResult exact = run_wear_reliability(d, exact_path_options(true));
  ASSERT_TRUE(sampled.exact.available);
  ASSERT_TRUE(exact.exact.available);
  EXPECT_EQ(exact.exact.life_at_R_years, sampled.exact.life_at_R_years);
  EXPECT_EQ(exact.exact.R_at_times, sampled.exact.R_at_times);
  EXPECT_EQ(exact.exact.life_increases, sampled.exact.life_increases);
  EXPECT_EQ(exact.exact.failed_at_start, sampled.exact.failed_at_start);
  EXPECT_EQ(exact.exact.model_evaluations, sampled.exact.model_evaluations);
  EXPECT_EQ(exact.nominal.life_cycles, sampled.nominal.life_cycles);
  EXPECT_EQ(exact.warnings, sampled.warnings);
  // Nothing sampled.
  EXPECT_EQ(sampled.lives.size(), 1u);
  EXPECT_TRUE(exact.lives.empty());
  EXPECT_TRUE(exact.input_values.empty());
  EXPECT_EQ(exact.samples_used, 0);
  EXPECT_FALSE(exact.status.has_value());
  EXPECT_EQ(exact.summary.samples_total, 0u);
  EXPECT_TRUE(exact.summary.warnings.empty());
}

TEST(ExactOnly, SeveralInputsAreSampledAsUsual) {
  Drive d = test::ship_lift_fixed_profile();
  d.reliability.inputs.push_back(relative_normal("wear.coefficient", 0.1));
  WearReliabilityOptions with = exact_path_options(true), without = exact_path_options(false);
  with.samples = without.samples = 8;
  const WearReliabilityResult a = run_wear_reliability(d, with), b = run_wear_reliability(d, without);
  EXPECT_FALSE(a.exact.available);
  ASSERT_EQ(a.lives.size(), 8u);
  ASSERT_EQ(b.lives.size(), 8u);
  for (std::size_t i = 0; i < a.lives.size(); ++i) EXPECT_EQ(a.lives[i].value, b.lives[i].value) << i;
  EXPECT_EQ(a.status, b.status);
}

// No valid value (every sampled hardness negative): no exact map, so the
// sample is drawn and the run says why there is no life at R.
TEST(ExactOnly, NoExactMapStillSamplesAndReportsTheStatus) {
  Drive d = test::ship_lift_fixed_profile();
  RandomInput in;
  in.key = "surface_hardness";
  in.distribution = RandomInput::Distribution::kNormal;
  in.a = -1e9;
  in.b = 1e6;
  in.absolute = true;
  d.reliability.inputs = {in};
  const WearReliabilityResult r = run_wear_reliability(d, exact_path_options(true));
  EXPECT_FALSE(r.exact.available);
  EXPECT_EQ(r.lives.size(), 1u);
  EXPECT_EQ(r.status, SamplingStatus::kNoValidSample);
}

}  // namespace
}  // namespace rackopt
