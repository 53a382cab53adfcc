// Inputs that scale the wear life exactly (wear_reliability/life_scaling.hpp)
// and the Monte Carlo over several inputs that uses it: the life of a sample
// with the wear coefficient and the hardness scaled is the unscaled life times
// sigma / k up to rounding, whatever the criterion; with at most one input
// that shapes the life the samples come from the table along it (or the
// nominal life) times that factor, within the table's tolerance of the direct
// lives (two shaping inputs: two_shaping_inputs_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "life_test_drives.hpp"
#include "rackopt/wear/wear_life.hpp"
#include "rackopt/wear_reliability/life_scaling.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt {
namespace {

RandomInput scaled_normal(const std::string& key, double cv) {
  RandomInput in;
  in.key = key;
  in.distribution = RandomInput::Distribution::kNormal;
  in.cv = cv;
  return in;
}

WearReliabilityOptions scaling_run(long samples, bool table) {
  WearReliabilityOptions o;
  o.samples = samples;
  o.bootstrap_replicates = 20;
  o.threads = 1;
  o.life_table = table;
  return o;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

TEST(LifeScaling, WhichInputsScale) {
  EXPECT_TRUE(input_scales_life("wear.coefficient"));
  EXPECT_TRUE(input_scales_life("surface_hardness"));
  EXPECT_FALSE(input_scales_life("contact_ratio"));
  EXPECT_FALSE(input_scales_life("load"));
  EXPECT_EQ(life_scale({.wear_coefficient_scale = 2.0, .surface_hardness_scale = 0.5}), 0.25);
}

// Profile update off (one block) and on (many blocks, and with a high
// allowable contact ratio the contact-ratio criterion, ended by a root
// search), each at several contact ratios and loads.
TEST(LifeScaling, CoefficientAndHardnessScaleTheLifeUpToRounding) {
  Drive frozen = test::ship_lift_fixed_profile();
  Drive updated = test::ship_lift_fixed_profile();
  updated.wear.update_profile = true;
  updated.wear.profile_points = 60;
  Drive contact_ratio_ends = updated;
  contact_ratio_ends.wear.min_contact_ratio = 1.49;
  double worst = 0;
  std::vector<std::string> criteria;
  for (const Drive& d : {frozen, updated, contact_ratio_ends}) {
    const WearModel model(d);
    for (const WearSample base : {WearSample{}, WearSample{.contact_ratio = 1.42}, WearSample{.contact_ratio = 1.52},
                                  WearSample{.force_scale = 1.15, .contact_ratio = 1.5}}) {
      const WearLifeResult r0 = model.life(base);
      criteria.push_back(r0.criterion);
      for (const auto& [k, sigma] : {std::pair{1.3, 1.0}, {0.6, 1.0}, {1.0, 0.85}, {2.7, 1.2}, {0.9, 0.7}}) {
        WearSample s = base;
        s.wear_coefficient_scale = k;
        s.surface_hardness_scale = sigma;
        const WearLifeResult r = model.life(s);
        EXPECT_EQ(r.criterion, r0.criterion);
        EXPECT_EQ(r.limiting_member, r0.limiting_member);
        const double err = relative(r0.life_years * life_scale(s), r.life_years);
        EXPECT_LT(err, 1e-12) << r0.criterion << " k " << k << " sigma " << sigma;
        worst = std::max(worst, err);
      }
    }
  }
  // Each criterion that can end a life was met at least once.
  EXPECT_NE(std::find(criteria.begin(), criteria.end(), "max_depth"), criteria.end());
  EXPECT_NE(std::find(criteria.begin(), criteria.end(), "contact_ratio"), criteria.end());
  std::cout << "largest relative difference of a scaled life: " << worst << "\n";
}

// Contact ratio and wear coefficient: the table along the contact ratio
// times each sample's factor, against one direct life per sample.
TEST(LifeScaling, OneShapingInputUsesTheTableTimesTheFactor) {
  Drive d = test::ship_lift_fixed_profile();
  d.reliability.inputs.push_back(scaled_normal("wear.coefficient", 0.15));
  d.reliability.inputs.push_back(scaled_normal("surface_hardness", 0.05));
  const WearReliabilityResult fast = run_wear_reliability(d, scaling_run(300, true));
  const WearReliabilityResult direct = run_wear_reliability(d, scaling_run(300, false));
  ASSERT_TRUE(fast.table.used);
  EXPECT_EQ(fast.table.input, "contact_ratio");
  EXPECT_EQ(fast.table.scaling_inputs, (std::vector<std::string>{"wear.coefficient", "surface_hardness"}));
  EXPECT_GT(fast.table.samples_interpolated, 250u);
  EXPECT_FALSE(direct.table.used);
  ASSERT_EQ(fast.lives.size(), direct.lives.size());
  double worst = 0;
  for (std::size_t i = 0; i < fast.lives.size(); ++i) {
    ASSERT_EQ(fast.lives[i].ok(), direct.lives[i].ok()) << i;
    EXPECT_EQ(fast.criteria[i], direct.criteria[i]) << i;
    if (direct.lives[i].value == 0) {
      EXPECT_EQ(fast.lives[i].value, 0.0) << i;  // failed at once, in both
      continue;
    }
    const double err = relative(fast.lives[i].value, direct.lives[i].value);
    EXPECT_LT(err, 1e-3) << i;  // the table's check tolerance (5e-4) with the model's own jitter
    worst = std::max(worst, err);
  }
  std::cout << "largest relative life error, table x factor against direct: " << worst << " (table: "
            << fast.table.nodes << " nodes, " << fast.table.evaluations << " model lives, "
            << fast.table.samples_direct << " samples direct)\n";
  ASSERT_FALSE(fast.summary.life.empty());
  ASSERT_FALSE(direct.summary.life.empty());
  EXPECT_LT(relative(fast.summary.life[0].empirical.estimate, direct.summary.life[0].empirical.estimate), 1e-3);
}

// Only scaling inputs: every sample is the nominal life times its factor.
TEST(LifeScaling, NoShapingInputUsesTheNominalLife) {
  Drive d = test::ship_lift_fixed_profile();
  d.reliability.inputs = {scaled_normal("wear.coefficient", 0.2), scaled_normal("surface_hardness", 0.05)};
  const WearReliabilityResult fast = run_wear_reliability(d, scaling_run(40, true));
  const WearReliabilityResult direct = run_wear_reliability(d, scaling_run(40, false));
  EXPECT_FALSE(fast.table.used);
  EXPECT_EQ(fast.table.samples_interpolated, 40u);
  EXPECT_EQ(fast.table.samples_direct, 0u);
  for (std::size_t i = 0; i < fast.lives.size(); ++i) {
    EXPECT_LT(relative(fast.lives[i].value, direct.lives[i].value), 1e-12) << i;
    EXPECT_EQ(fast.criteria[i], direct.criteria[i]) << i;
  }
}

}  // namespace
}  // namespace rackopt
