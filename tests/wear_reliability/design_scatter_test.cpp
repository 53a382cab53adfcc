// Scatter that follows the design: a random input described around the
// design's own value moves with a design change (clearance, wear
// coefficient), by the amount an independent evaluation of the wear model at
// the input's quantile gives; an absolute one next to a changed key is
// refused; a life at R above the nominal life is a warning.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rackopt/wear_reliability/design_scatter.hpp"
#include "rackopt/wear_reliability/life_at_R_check.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Standard normal quantiles (Abramowitz & Stegun 26.2, table 26.5).
constexpr double kZ10 = -1.2815515655446004;  // Phi^-1(0.10)
constexpr double kZ90 = 1.2815515655446004;   // Phi^-1(0.90)

// Standard normal cdf and its inverse by bisection on it: independent of
// statistics/distribution.cpp.
double phi_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double phi_inverse(double p) {
  double lo = -10, hi = 10;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (phi_cdf(mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::string ship_lift_path() { return test_support::shipped_problem_path("ship_lift.yaml"); }

// The shipped problem with only the life at R = 0.9 asked for, exact path.
WearReliabilityResult life_at_090(Drive d) {
  d.reliability.reliabilities = {0.9};
  d.reliability.times.clear();
  WearReliabilityOptions o = wear_reliability_options(d);
  o.samples = 1;  // the exact quantile path is what is compared
  o.life_table = false;
  o.threads = 1;
  return run_wear_reliability(d, o);
}

// The shipped form: the contact ratio around the design's own one.
TEST(DesignScatter, ShippedContactRatioIsAroundTheDesign) {
  const Drive d = load_problem(ship_lift_path());
  ASSERT_EQ(d.reliability.inputs.size(), 1u);
  const RandomInput& in = d.reliability.inputs[0];
  EXPECT_EQ(in.key, "contact_ratio");
  EXPECT_FALSE(in.absolute);
  // At the shipped zero clearance the calibrated mean 1.44 (docs/models/reliability.md).
  const WearModel model(d);
  const auto dist = input_distribution(in, design_value(d, in.key, model.nominal_contact_ratio()));
  EXPECT_NEAR(dist.quantile(0.5), 1.44, 5e-4);
}

// The clearance case: 4 mm of mounting clearance lowers the design's contact
// ratio by 4 mm / (p_b sin a0) and the life at R = 0.9 with it. The
// independent number: one wear-model life at eps_design(4 mm) + shift +
// z_0.1 sd, with z_0.1 from the tables, not from the distribution code.
TEST(DesignScatter, ClearanceMovesTheLifeAtRByTheQuantileLife) {
  const Drive d0 = load_problem(ship_lift_path());
  const Drive d4 = load_problem(ship_lift_path(), {"mounting.clearance=4 mm"});
  const WearModel m0(d0), m4(d4);
  // Rack tip limits the start of contact: eps falls linearly with the clearance.
  const double m = d0.pinion.module, a0 = d0.pinion.pressure_angle;
  const double d_eps = 4e-3 / (kPi * m * std::cos(a0) * std::sin(a0));
  EXPECT_NEAR(m4.nominal_contact_ratio(), m0.nominal_contact_ratio() - d_eps, 1e-6);

  const RandomInput& in = d4.reliability.inputs[0];
  ASSERT_FALSE(in.absolute);
  ASSERT_EQ(in.distribution, RandomInput::Distribution::kNormal);
  // A sample above the largest contact ratio of the pair fails at once
  // (docs/models/reliability.md, the 40-year row): R = 0.9 is reached at the
  // input quantile Phi((eps_max - mu)/sd) - 0.9 (0.1 when eps_max is far).
  auto independent = [&](const WearModel& model) {
    const double mu = model.nominal_contact_ratio() + in.a;
    const double q = phi_cdf((model.max_contact_ratio() - mu) / in.b) - 0.9;
    WearSample s;
    s.contact_ratio = mu + phi_inverse(q) * in.b;
    return model.life(s).life_years;
  };
  EXPECT_NEAR(phi_inverse(0.1), kZ10, 1e-12);
  const double t0 = life_at_090(d0).exact.life_at_R_years.at(0);
  const double t4 = life_at_090(d4).exact.life_at_R_years.at(0);
  EXPECT_NEAR(t0, independent(m0), 1e-6 * t0);
  EXPECT_NEAR(t4, independent(m4), 1e-6 * t4);
  // And it does move: by several years (the nominal life falls 77.6 -> 68.2 y).
  EXPECT_LT(t4, t0 - 3.0);
  std::cout << "life at R = 0.9: clearance 0 mm " << t0 << " y, 4 mm " << t4 << " y; nominal "
            << m0.life().life_years << " -> " << m4.life().life_years << " y\n";
}

// The coefficient case: with the coefficient's scatter a factor (median 1),
// Archard's depth is proportional to K n, so the life at R scales as 1/K
// exactly; and it equals one model life at K F_0.9 with F_0.9 =
// exp(sigma z_0.9) (life falls with K: R = 0.9 is the 90 % quantile of K).
TEST(DesignScatter, CoefficientFactorGivesALifeAtRProportionalToOneOverK) {
  const std::string factor = "reliability.random[0]={input: wear_coefficient, distribution: lognormal, sigma: 0.3}";
  const Drive d1 = load_problem(ship_lift_path(), {"wear.coefficient=1e-6", factor});
  const Drive d2 = load_problem(ship_lift_path(), {"wear.coefficient=1e-4", factor});
  const WearReliabilityResult r1 = life_at_090(d1), r2 = life_at_090(d2);
  ASSERT_TRUE(r1.exact.available);
  const double t1 = r1.exact.life_at_R_years.at(0), t2 = r2.exact.life_at_R_years.at(0);
  EXPECT_NEAR(t2 / t1, 1e-6 / 1e-4, 1e-6 * (1e-6 / 1e-4));
  for (const auto* pair : {&d1, &d2}) {
    Drive dk = *pair;
    dk.wear.coefficient *= std::exp(0.3 * kZ90);
    dk.reliability.inputs.clear();
    const double independent = WearModel(dk).life().life_years;
    const double t = pair == &d1 ? t1 : t2;
    EXPECT_NEAR(t, independent, 1e-6 * independent);
  }
  // Below the nominal life, as a scatter around the design must be at R = 0.9.
  EXPECT_LT(t2, r2.nominal.life_years);
  EXPECT_TRUE(r2.warnings.empty());
  std::cout << "life at R = 0.9: K = 1e-6 " << t1 << " y, K = 1e-4 " << t2 << " y (nominal "
            << r1.nominal.life_years << ", " << r2.nominal.life_years << " y)\n";
}

// The hardness case: a constant surface hardness scattered by a factor
// (median 1). Archard's depth grows as n / H, so the life is proportional to
// H: the life at R = 0.9 is the nominal life times F_0.1 = exp(sigma z_0.1)
// and halves with the design's hardness (it stayed put with an absolute
// hardness distribution).
TEST(DesignScatter, HardnessFactorFollowsTheDesignHardness) {
  const std::string factor = "reliability.random[0]={input: surface_hardness, distribution: lognormal, sigma: 0.1}";
  const Drive hard = load_problem(ship_lift_path(), {"wear.hardness={kind: constant, surface: 600 HB}", factor});
  const Drive soft = load_problem(ship_lift_path(), {"wear.hardness={kind: constant, surface: 300 HB}", factor});
  const WearReliabilityResult a = life_at_090(hard), b = life_at_090(soft);
  ASSERT_TRUE(a.exact.available);
  EXPECT_TRUE(a.exact.life_increases);
  const double ta = a.exact.life_at_R_years.at(0), tb = b.exact.life_at_R_years.at(0);
  EXPECT_NEAR(tb / ta, 0.5, 1e-6);
  EXPECT_NEAR(ta, a.nominal.life_years * std::exp(0.1 * kZ10), 1e-6 * ta);
  EXPECT_NEAR(tb, b.nominal.life_years * std::exp(0.1 * kZ10), 1e-6 * tb);
}

// A normal load with a cv around the design's force: its centre is the
// design's force, its sd cv times it.
TEST(DesignScatter, NormalCvAndShiftAroundTheDesign) {
  RandomInput in;
  in.key = "load";
  in.distribution = RandomInput::Distribution::kNormal;
  in.cv = 0.1;
  in.a = 5e3;  // shift
  const auto d = input_distribution(in, 100e3);
  EXPECT_DOUBLE_EQ(d.quantile(0.5), 105e3);
  EXPECT_NEAR(d.quantile(0.9) - d.quantile(0.5), 10e3 * kZ90, 1e-6);
  RandomInput u;
  u.key = "surface_hardness";
  u.distribution = RandomInput::Distribution::kUniform;
  u.a = -10;
  u.b = 10;
  const auto du = input_distribution(u, 100);
  EXPECT_DOUBLE_EQ(du.quantile(0.0 + 0.25), 95);
  // A shift that leaves no positive load: this design cannot carry it.
  in.a = -200e3;
  EXPECT_THROW((void)input_distribution(in, 100e3), DesignError);
  // An absolute input ignores the design's value.
  RandomInput abs;
  abs.key = "load";
  abs.absolute = true;
  abs.a = 50e3;
  abs.b = 1e3;
  EXPECT_DOUBLE_EQ(input_distribution(abs, 100e3).quantile(0.5), 50e3);
}

// The symptom this form removes, kept reachable with an explicit absolute
// input: the coefficient's distribution fixed at 3e-6 while the design's is
// 1e-4 gives a life at R = 0.9 far above the nominal life: a warning.
TEST(DesignScatter, LifeAtRAboveTheNominalLifeIsAWarning) {
  Drive d = load_problem(ship_lift_path(), {"wear.coefficient=1e-4"});
  RandomInput k;
  k.key = "wear.coefficient";
  k.distribution = RandomInput::Distribution::kLognormal;
  k.absolute = true;
  k.a = 3e-6;
  k.b = 0.3;
  d.reliability.inputs = {k};
  const WearReliabilityResult r = life_at_090(d);
  ASSERT_GT(r.exact.life_at_R_years.at(0), r.nominal.life_years);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("above the nominal wear life"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("R = 0.9"), std::string::npos) << r.warnings[0];
}

TEST(LifeAtRCheck, OnlyAboveTheNominalAndForRAtLeastOneHalf) {
  EXPECT_TRUE(life_at_R_above_nominal(0.9, 12.0, 2.0, "exact"));
  EXPECT_TRUE(life_at_R_above_nominal(0.5, 2.1, 2.0, "exact"));
  EXPECT_FALSE(life_at_R_above_nominal(0.4, 12.0, 2.0, "exact"));   // R < 0.5: may exceed the nominal
  EXPECT_FALSE(life_at_R_above_nominal(0.9, 1.5, 2.0, "exact"));
  EXPECT_FALSE(life_at_R_above_nominal(0.5, 2.0 * (1 + 1e-9), 2.0, "exact"));  // the median of a median-1 factor
  EXPECT_FALSE(life_at_R_above_nominal(0.9, 12.0, 0.0, "exact"));  // no nominal life to compare with
}

}  // namespace
}  // namespace rackopt
