// Failed samples of the wear-reliability Monte Carlo (docs/models/reliability.md,
// "Failed samples"): a sampled contact ratio out of range is a drive that fails
// at once (life 0, never the nominal life); a value outside its input's domain
// (not finite, <= 0 for a positive input) is a failed evaluation, counted and
// warned about once; a run whose every sample fails reports that as a status,
// never by throwing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "life_test_drives.hpp"
#include "rackopt/wear_reliability/sample_domain.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace rackopt {
namespace {

using test::ship_lift_fixed_profile;

WearReliabilityOptions quick(long samples) {
  WearReliabilityOptions o;
  o.samples = samples;
  o.bootstrap_replicates = 20;
  return o;
}

long count_warnings(const WearReliabilityResult& r, const std::string& part) {
  return std::count_if(r.summary.warnings.begin(), r.summary.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

double phi(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

RandomInput input(const std::string& key, RandomInput::Distribution dist, double a, double b, bool absolute) {
  RandomInput in;
  in.key = key;
  in.distribution = dist;
  in.a = a;
  in.b = b;
  in.absolute = absolute;
  return in;
}

TEST(SampleDomain, OneRuleForEveryInput) {
  for (const char* key : {"load", "wear.coefficient", "surface_hardness"}) {
    EXPECT_TRUE(outside_input_domain(key, 0.0)) << key;
    EXPECT_TRUE(outside_input_domain(key, -1.0)) << key;
    EXPECT_FALSE(outside_input_domain(key, 1e-300)) << key;
  }
  // Every finite contact ratio is a drive (out of range it fails at once).
  EXPECT_FALSE(outside_input_domain("contact_ratio", 0.0));
  EXPECT_FALSE(outside_input_domain("contact_ratio", -3.0));
  for (const char* key : {"contact_ratio", "load", "wear.coefficient", "surface_hardness"}) {
    EXPECT_TRUE(outside_input_domain(key, INFINITY)) << key;
    EXPECT_TRUE(outside_input_domain(key, NAN)) << key;
  }
}

// A contact ratio of exactly 0 is a sampled value, not "no sample": the drive
// fails at once. (It used to give the nominal life.)
TEST(FailedSamples, ContactRatioZeroFailsAtOnceInsteadOfTheNominalLife) {
  const Drive d = ship_lift_fixed_profile();
  const WearModel model(d);
  const WearLifeResult nominal = model.life();
  ASSERT_GT(nominal.life_years, 10.0);
  const WearLifeResult zero = model.life({.contact_ratio = 0.0});
  EXPECT_EQ(zero.life_years, 0.0);
  EXPECT_EQ(zero.criterion, "initial_contact_ratio");
  EXPECT_EQ(model.life({.contact_ratio = std::nullopt}).life_years, nominal.life_years);
  // Through the sample builder too.
  const WearSample s = wear_sample_for(d, d.reliability.inputs, {0.0});
  ASSERT_TRUE(s.contact_ratio.has_value());
  EXPECT_EQ(model.life(s).criterion, "initial_contact_ratio");
}

// A Weibull of tiny shape underflows to exactly 0 for about half its quantiles
// and overflows to +inf for a quarter: no sample may get the nominal life, the
// zeros fail at once, the infinities are failed evaluations counted once.
TEST(FailedSamples, UnderflowingAndOverflowingContactRatiosNeverGiveTheNominalLife) {
  Drive d = ship_lift_fixed_profile();
  d.reliability.inputs = {input("contact_ratio", RandomInput::Distribution::kWeibull, 1.4, 0.001, true)};
  const WearReliabilityResult r = run_wear_reliability(d, quick(200));
  std::size_t zeros = 0, infinite = 0;
  for (std::size_t i = 0; i < r.lives.size(); ++i) {
    const double x = r.input_values[i][0];
    if (x == 0.0) {
      ++zeros;
      ASSERT_TRUE(r.lives[i].ok()) << i;
      EXPECT_EQ(r.lives[i].value, 0.0) << i;
      EXPECT_EQ(r.criteria[i], "initial_contact_ratio") << i;
    } else if (!std::isfinite(x)) {
      ++infinite;
      EXPECT_FALSE(r.lives[i].ok()) << i;
      EXPECT_EQ(r.lives[i].code, "sample_outside_domain") << i;
    }
    if (r.lives[i].ok()) {
      EXPECT_TRUE(std::isfinite(r.lives[i].value));
    }
    // Only an input inside [max(1, [eps]), eps_max] may live.
    if (r.lives[i].ok() && r.lives[i].value > 0) {
      EXPECT_GE(x, 1.2);
      EXPECT_LE(x, 1.5360);
    }
  }
  EXPECT_GT(zeros, 50u);
  EXPECT_GT(infinite, 10u);
  EXPECT_EQ(r.summary.failed_evaluations, infinite);
  EXPECT_EQ(r.outside_domain_samples.at(0), infinite);
  EXPECT_EQ(count_warnings(r, "contact_ratio: " + std::to_string(infinite) + " of 200 samples"), 1);
}

// A normal surface hardness of cv 0.5 reaches below 0 with probability
// Phi(-2) = 2.3 %: those samples are failed evaluations, counted and warned
// once; the exact path is conditional on a positive hardness like the
// summary. (It used to stop the run with an InputError.)
TEST(FailedSamples, NonPositiveHardnessIsAFailedSampleAndTheRunGoesOn) {
  Drive d = ship_lift_fixed_profile();
  RandomInput h = input("surface_hardness", RandomInput::Distribution::kNormal, 0.0, 0.0, false);
  h.cv = 0.5;
  d.reliability.inputs = {h};
  d.reliability.reliabilities = {0.9, 0.99};
  const long n = 2000;
  WearReliabilityResult r;
  ASSERT_NO_THROW(r = run_wear_reliability(d, quick(n)));
  const std::size_t bad = r.outside_domain_samples.at(0);
  EXPECT_GT(bad, 20u);  // expected 45.5
  EXPECT_LT(bad, 75u);
  EXPECT_EQ(r.summary.failed_evaluations, bad);
  EXPECT_EQ(count_warnings(r, "surface_hardness: " + std::to_string(bad) + " of 2000 samples"), 1);
  EXPECT_EQ(r.status, SamplingStatus::kOk);
  for (std::size_t i = 0; i < r.lives.size(); ++i) {
    EXPECT_EQ(r.lives[i].ok(), r.input_values[i][0] > 0) << i;
  }
  ASSERT_TRUE(r.exact.available);
  EXPECT_NEAR(r.exact.outside_domain, phi(-2.0), 1e-9);
  EXPECT_EQ(r.exact.failed_at_start, 0.0);
  ASSERT_EQ(r.exact.life_at_R_years.size(), 2u);
  // Conditional on H > 0 the life at R is one model life at the hardness
  // quantile F^-1(v0 + (1 - R)(1 - v0)), v0 = Phi(-2): H/H0 = 1 + 0.5 z.
  const double v0 = phi(-2.0);
  const WearModel model(d);
  for (std::size_t k = 0; k < 2; ++k) {
    const double R = d.reliability.reliabilities[k];
    const double q = v0 + (1 - R) * (1 - v0);
    double lo = -10, hi = 10;  // z = Phi^-1(q) by bisection on erfc
    for (int it = 0; it < 200; ++it) ((phi(0.5 * (lo + hi)) < q) ? lo : hi) = 0.5 * (lo + hi);
    const double scale = 1 + 0.5 * 0.5 * (lo + hi);
    const double expected = model.life({.surface_hardness_scale = scale}).life_years;
    EXPECT_NEAR(r.exact.life_at_R_years[k], expected, 1e-6 * expected) << R;
    // And the Monte Carlo's empirical life at R (over valid samples) agrees
    // with it within the order-statistic interval.
    const auto& la = r.summary.life.at(k).empirical;
    EXPECT_LE(la.lower / kSecondsPerYear, expected * (1 + 1e-3)) << R;
    EXPECT_GE(la.upper / kSecondsPerYear, expected * (1 - 1e-3)) << R;
  }
}

// The same rule for the load (life decreases with it): non-positive loads are
// failed evaluations, counted and warned once.
TEST(FailedSamples, NonPositiveLoadFollowsTheSameRule) {
  Drive d = ship_lift_fixed_profile();
  RandomInput f = input("load", RandomInput::Distribution::kNormal, 0.0, 0.0, false);
  f.cv = 0.5;
  d.reliability.inputs = {f};
  const WearReliabilityResult r = run_wear_reliability(d, quick(400));
  const std::size_t bad = r.outside_domain_samples.at(0);
  EXPECT_GT(bad, 0u);
  EXPECT_EQ(r.summary.failed_evaluations, bad);
  EXPECT_EQ(count_warnings(r, "load: " + std::to_string(bad) + " of 400 samples"), 1);
  ASSERT_TRUE(r.exact.available);
  EXPECT_NEAR(r.exact.outside_domain, phi(-2.0), 1e-9);
}

// Every sample outside [max(1, [eps]), eps_max], on either side, or with
// [eps] above eps_max: a status and a warning, life 0 at every R, R(t) = 0,
// failed_at_start exactly 1 (it was above 1 when [eps] > eps_max).
TEST(FailedSamples, EveryContactRatioOutOfRangeIsAStatusNotAnError) {
  for (int variant = 0; variant < 3; ++variant) {
    Drive d = ship_lift_fixed_profile();
    if (variant == 0) d.reliability.inputs.front().a = 0.5;   // wholly above eps_max
    if (variant == 1) d.reliability.inputs.front().a = -0.6;  // wholly below 1
    if (variant == 2) d.wear.min_contact_ratio = 1.6;         // [eps] > eps_max = 1.536
    WearReliabilityResult r;
    ASSERT_NO_THROW(r = run_wear_reliability(d, quick(64))) << variant;
    EXPECT_EQ(r.status, SamplingStatus::kEverySampleFailsAtOnce) << variant;
    EXPECT_EQ(r.summary.immediate_failures, 64u) << variant;
    EXPECT_EQ(count_warnings(r, "no life at reliability R"), 1) << variant;
    ASSERT_TRUE(r.exact.available);
    // Below 1 the normal's upper tail keeps a probability of 3e-12 inside.
    EXPECT_LE(r.exact.failed_at_start, 1.0) << variant;
    EXPECT_NEAR(r.exact.failed_at_start, 1.0, 1e-9) << variant;
    if (variant == 2) {
      EXPECT_EQ(r.exact.failed_at_start, 1.0);
    }
    for (double t : r.exact.life_at_R_years) EXPECT_EQ(t, 0.0);
    for (double R : r.exact.R_at_times) EXPECT_NEAR(R, 0.0, 1e-9);
    for (const auto& la : r.summary.life) EXPECT_EQ(la.empirical.estimate, 0.0);
  }
}

// More samples failing at once than 1 - R: the life at R is 0, said once.
TEST(FailedSamples, LifeAtRIsZeroWhenMoreThanOneMinusRFailAtOnce) {
  Drive d = ship_lift_fixed_profile();
  d.reliability.reliabilities = {0.9, 0.999};  // about 0.6 % of the samples start above eps_max
  const WearReliabilityResult r = run_wear_reliability(d, quick(1000));
  ASSERT_GT(r.summary.immediate_failures, 1u);
  EXPECT_EQ(r.status, SamplingStatus::kOk);
  EXPECT_GT(r.summary.life.at(0).empirical.estimate, 0.0);
  EXPECT_EQ(r.summary.life.at(1).empirical.estimate, 0.0);
  if (r.summary.life.at(1).fit) {
    EXPECT_EQ(r.summary.life.at(1).fit->estimate, 0.0);
  }
  EXPECT_GT(r.exact.life_at_R_years.at(0), 0.0);
  EXPECT_EQ(r.exact.life_at_R_years.at(1), 0.0);
  EXPECT_EQ(count_warnings(r, "life at R = 0.999 is 0"), 1);
}

// No sample inside the domain (reachable only from code: the problem loader
// refuses a non-positive absolute mean): a status, no life at R, no throw.
TEST(FailedSamples, NoValidSampleIsAStatusNotAnError) {
  Drive d = ship_lift_fixed_profile();
  d.reliability.inputs = {input("surface_hardness", RandomInput::Distribution::kNormal, -1e9, 1e6, true)};
  WearReliabilityResult r;
  ASSERT_NO_THROW(r = run_wear_reliability(d, quick(32)));
  EXPECT_EQ(r.status, SamplingStatus::kNoValidSample);
  EXPECT_EQ(r.summary.failed_evaluations, 32u);
  EXPECT_TRUE(r.summary.life.empty());
  EXPECT_TRUE(r.summary.reliability.empty());
  EXPECT_FALSE(r.exact.available);
  EXPECT_EQ(count_warnings(r, "no life at reliability R"), 1);
}

// A scatter so narrow that the lives agree to 1e-8 (sd 1e-9 around the
// design's contact ratio, which is eps_max: about half fail at once): no fit
// (the gamma fit gave shape 6e17 and a KS test "accepted" at D = 0.95), the
// empirical results only, all finite.
TEST(FailedSamples, LivesWithoutResolvableSpreadAreNotFitted) {
  Drive d = ship_lift_fixed_profile();
  d.reliability.inputs.front().a = 0.0;
  d.reliability.inputs.front().b = 1e-9;
  const WearReliabilityResult r = run_wear_reliability(d, quick(200));
  ASSERT_GT(r.summary.samples_fitted, 50u);
  EXPECT_EQ(r.summary.chosen, -1);
  EXPECT_EQ(count_warnings(r, "no distribution could be fitted"), 1);
  for (const auto& la : r.summary.life) {
    EXPECT_FALSE(la.fit.has_value());
    EXPECT_TRUE(std::isfinite(la.empirical.estimate));
  }
  for (const auto& t : r.summary.reliability) EXPECT_TRUE(std::isfinite(t.empirical));
}

}  // namespace
}  // namespace rackopt
