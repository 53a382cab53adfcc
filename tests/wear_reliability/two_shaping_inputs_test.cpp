// The contact ratio and the load together: both shape the wear life, so the
// samples come from the verified two-input table (statistics/function_table_2d.hpp)
// where its checks passed and from direct lives elsewhere, within the check
// tolerance of one direct life per sample, the same on any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "life_test_drives.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt {
namespace {

RandomInput two_input_normal(const std::string& key, double cv) {
  RandomInput in;
  in.key = key;
  in.distribution = RandomInput::Distribution::kNormal;
  in.cv = cv;
  return in;
}

WearReliabilityOptions two_input_run(long samples, bool table, unsigned threads) {
  WearReliabilityOptions o;
  o.samples = samples;
  o.bootstrap_replicates = 20;
  o.threads = threads;
  o.life_table = table;
  return o;
}

Drive contact_ratio_and_load() {
  Drive d = test::ship_lift_fixed_profile();
  d.reliability.inputs.push_back(two_input_normal("load", 0.05));
  return d;
}

double two_input_relative(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

TEST(TwoShapingInputs, TableLivesAgreeWithDirectLives) {
  const Drive d = contact_ratio_and_load();
  const WearReliabilityResult fast = run_wear_reliability(d, two_input_run(200, true, 1));
  const WearReliabilityResult direct = run_wear_reliability(d, two_input_run(200, false, 1));
  ASSERT_TRUE(fast.table.used) << fast.table.not_used;
  EXPECT_EQ(fast.table.input, "contact_ratio");
  EXPECT_EQ(fast.table.input2, "load");
  EXPECT_FALSE(direct.table.used);
  EXPECT_GT(fast.table.samples_interpolated, 180u);
  EXPECT_EQ(fast.table.samples_interpolated + fast.table.samples_direct, 200u);
  EXPECT_LE(fast.table.max_check_error, 5e-4);
  double worst = 0;
  for (std::size_t i = 0; i < fast.lives.size(); ++i) {
    EXPECT_EQ(fast.criteria[i], direct.criteria[i]) << i;
    if (direct.lives[i].value > 0) {
      worst = std::max(worst, two_input_relative(fast.lives[i].value, direct.lives[i].value));
    } else {
      EXPECT_EQ(fast.lives[i].value, direct.lives[i].value) << i;
    }
  }
  EXPECT_LT(worst, 5e-4);
  ASSERT_FALSE(direct.summary.life.empty());
  ASSERT_TRUE(fast.summary.life[0].fit && direct.summary.life[0].fit);
  EXPECT_LT(two_input_relative(fast.summary.life[0].fit->estimate, direct.summary.life[0].fit->estimate), 1e-4);
}

TEST(TwoShapingInputs, SameLivesOnAnyThreadCount) {
  const Drive d = contact_ratio_and_load();
  const WearReliabilityResult one = run_wear_reliability(d, two_input_run(120, true, 1));
  const WearReliabilityResult three = run_wear_reliability(d, two_input_run(120, true, 3));
  ASSERT_TRUE(one.table.used);
  EXPECT_EQ(one.table.evaluations, three.table.evaluations);
  EXPECT_EQ(one.table.samples_interpolated, three.table.samples_interpolated);
  for (std::size_t i = 0; i < one.lives.size(); ++i) {
    EXPECT_EQ(one.lives[i].value, three.lives[i].value) << i;
    EXPECT_EQ(one.criteria[i], three.criteria[i]) << i;
  }
}

// Samples in cells that failed their check, or that the table does not
// reach, get direct lives: with a tolerance no cell can meet, every sample is
// a direct life, bit for bit the life of the run without the table.
TEST(TwoShapingInputs, UnverifiedCellsGiveDirectLives) {
  const Drive d = contact_ratio_and_load();
  WearReliabilityOptions strict = two_input_run(60, true, 1);
  strict.life_table_tolerance = 1e-15;
  const WearReliabilityResult fast = run_wear_reliability(d, strict);
  const WearReliabilityResult direct = run_wear_reliability(d, two_input_run(60, false, 1));
  ASSERT_TRUE(fast.table.used);
  EXPECT_EQ(fast.table.cells_verified, 0);
  EXPECT_EQ(fast.table.samples_interpolated, 0u);
  for (std::size_t i = 0; i < fast.lives.size(); ++i) EXPECT_EQ(fast.lives[i].value, direct.lives[i].value) << i;
}

// Where the contact-ratio criterion takes over from the depth (the drive of
// WearReliability.LifeTableDoesNotSmearAFailureModeSwitch, with the load
// scattered too), the cells across the switch are never interpolated; their
// samples get their direct lives and criteria.
TEST(TwoShapingInputs, FailureModeSwitchInACellFallsBackToDirectLives) {
  Drive d = contact_ratio_and_load();
  d.wear.update_profile = true;
  d.wear.profile_points = 60;  // cost
  d.wear.min_contact_ratio = 1.46;
  RandomInput& eps = d.reliability.inputs.at(0);
  ASSERT_EQ(eps.key, "contact_ratio");
  eps.absolute = true;  // N(1.50, 0.015)
  eps.a = 1.50;
  eps.b = 0.015;
  WearReliabilityOptions o = two_input_run(100, true, 2);
  o.life_table_max_evaluations = 200;
  const WearReliabilityResult fast = run_wear_reliability(d, o);
  o.life_table = false;
  const WearReliabilityResult direct = run_wear_reliability(d, o);
  ASSERT_TRUE(fast.table.used) << fast.table.not_used;
  EXPECT_GT(fast.table.cells_with_switch, 0);
  EXPECT_GT(fast.table.samples_direct, 0u);
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < fast.lives.size(); ++i) {
    EXPECT_EQ(fast.criteria[i], direct.criteria[i]) << i;
    if (std::find(seen.begin(), seen.end(), direct.criteria[i]) == seen.end()) seen.push_back(direct.criteria[i]);
    if (direct.lives[i].value > 0) {
      EXPECT_LT(two_input_relative(fast.lives[i].value, direct.lives[i].value), 5e-4) << i;
    } else {
      EXPECT_EQ(fast.lives[i].value, 0.0) << i;
    }
  }
  EXPECT_GE(seen.size(), 2u);  // the samples do straddle the switch
}

}  // namespace
}  // namespace rackopt
