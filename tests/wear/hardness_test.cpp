// Hardness-depth profiles (docs/models/wear.md): the wear paper's measured polynomial,
// tables, and the ISO 18203 parametric case-hardening profile.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/core/error.hpp"
#include "rackopt/wear/hardness.hpp"
#include "wear_drives.hpp"

namespace rackopt {
namespace {

double hb(double pa) { return pa / kPaPerHB; }

// docs/models/wear.md: the cubic peaks at 596.55 HB at h = 0.53 mm.
TEST(Hardness, WearPaperPolynomialMaximum) {
  const HardnessModel m(test::wear_paper_polynomial());
  double best = 0, at = 0;
  for (int i = 0; i <= 60000; ++i) {
    const double h = 6e-3 * i / 60000;
    if (m(h) > best) best = m(h), at = h;
  }
  EXPECT_NEAR(hb(best), 596.55, 0.01);
  EXPECT_NEAR(at * 1e3, 0.53, 0.01);
  EXPECT_NEAR(hb(m(0)), 596.0, 1e-9);
  // Over h_max = 1.5 mm it drops only to 594.4 HB (docs/models/wear.md).
  EXPECT_NEAR(hb(m(1.5e-3)), 594.4, 0.05);
}

// docs/models/wear.md: 0.8 H0 = 476.8 HB at h = 6.35 mm (the ISO 3754 SHD criterion).
TEST(Hardness, WearPaperPolynomialSurfaceHardeningDepth) {
  const HardnessModel m(test::wear_paper_polynomial(6.5e-3));
  // Bisection for H = 0.8 * 596 HB on [3, 6.5] mm.
  double lo = 3e-3, hi = 6.5e-3;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (hb(m(mid)) > 0.8 * 596 ? lo : hi) = mid;
  }
  EXPECT_NEAR(lo * 1e3, 6.35, 0.01);
  EXPECT_FALSE(m.evaluate(6.35e-3).outside_data);
}

// Beyond the measured range: clamp to the core, flag it, never <= 0.
TEST(Hardness, ClampedOutsideDataNeverZero) {
  // core 0 = the value at valid_depth.
  const HardnessModel m(test::wear_paper_polynomial(6.5e-3));
  const double at_valid = m(6.5e-3);
  EXPECT_NEAR(m.core(), at_valid, 1e-9);
  for (double h : {6.6e-3, 8e-3, 11.6e-3, 20e-3, 1.0}) {
    const auto v = m.evaluate(h);
    EXPECT_TRUE(v.outside_data) << h;
    EXPECT_DOUBLE_EQ(v.hardness, at_valid) << h;
    EXPECT_GT(v.hardness, 0);
  }
  EXPECT_DOUBLE_EQ(m.first_clamped_depth(), 6.5e-3);
  // A fit declared valid to 12 mm (past its zero at 11.6 mm) with a 300 HB
  // core: clamped from 8.95 mm on (docs/models/wear.md: H = 300 HB at 8.95 mm).
  const HardnessModel deep(test::wear_paper_polynomial(12e-3, 300 * kPaPerHB));
  EXPECT_NEAR(deep.first_clamped_depth() * 1e3, 8.95, 0.01);
  EXPECT_TRUE(deep.evaluate(10e-3).outside_data);
  EXPECT_DOUBLE_EQ(hb(deep(11.6e-3)), 300.0);
  EXPECT_FALSE(deep.evaluate(8.9e-3).outside_data);
}

TEST(Hardness, PolynomialWithoutPositiveCoreIsAnInputError) {
  // The cubic is negative at 12 mm: with core 0 there is nothing to clamp to.
  EXPECT_THROW(HardnessModel(test::wear_paper_polynomial(12e-3, 0)), InputError);
  EXPECT_THROW(HardnessModel(test::wear_paper_polynomial(0)), InputError);
}

TEST(Hardness, TableInterpolatesAndClamps) {
  HardnessProfile p;
  p.kind = HardnessProfile::Kind::kTable;
  p.depths = {0.5e-3, 1e-3, 2e-3};
  p.values = {600 * kPaPerHB, 580 * kPaPerHB, 500 * kPaPerHB};
  const HardnessModel m(p);
  EXPECT_NEAR(hb(m(0.75e-3)), 590, 1e-9);
  EXPECT_NEAR(hb(m(1.5e-3)), 540, 1e-9);
  EXPECT_NEAR(hb(m(0)), 600, 1e-9);  // above the first point: first value, not flagged
  EXPECT_FALSE(m.evaluate(0).outside_data);
  EXPECT_TRUE(m.evaluate(3e-3).outside_data);
  EXPECT_NEAR(hb(m(3e-3)), 500, 1e-9);
  // A core above the last value: clamped where the table crosses 520 HB (1.75 mm).
  p.core = 520 * kPaPerHB;
  const HardnessModel c(p);
  EXPECT_NEAR(c.first_clamped_depth(), 1.75e-3, 1e-15);
  EXPECT_NEAR(hb(c(1.9e-3)), 520, 1e-9);
  p.depths = {1e-3, 0.5e-3, 2e-3};
  EXPECT_THROW(HardnessModel{p}, InputError);
}

// docs/models/wear.md: H_c + (H_s - H_c) exp(-(h/delta)^n) passes through H_lim at
// D_eff exactly and falls monotonically from H_s to H_c.
TEST(Hardness, CaseHardenedThroughLimitAtDepthAndMonotone) {
  for (double n : {1.5, 2.0, 3.0, 4.0}) {
    HardnessProfile p;
    p.kind = HardnessProfile::Kind::kCaseHardened;
    p.surface = 600 * kPaPerHB;
    p.core = 300 * kPaPerHB;
    p.case_depth = 6e-3;
    p.exponent = n;
    const HardnessModel m(p);
    EXPECT_NEAR(m(6e-3) / (0.8 * p.surface), 1.0, 1e-13) << n;  // default limit 0.8 H_s (ISO 18203 SHD)
    EXPECT_DOUBLE_EQ(m(0), p.surface);
    double prev = m(0);
    for (int i = 1; i <= 400; ++i) {
      const double v = m(30e-3 * i / 400);
      EXPECT_LE(v, prev);
      EXPECT_GT(v, p.core * (1 - 1e-15));
      prev = v;
    }
    EXPECT_NEAR(hb(m(1.0)), 300, 1e-9);
    EXPECT_FALSE(m.evaluate(1.0).outside_data);
    p.limit = 400 * kPaPerHB;
    EXPECT_NEAR(hb(HardnessModel(p)(6e-3)), 400, 1e-9);
  }
}

TEST(Hardness, CaseHardenedValidation) {
  HardnessProfile p;
  p.kind = HardnessProfile::Kind::kCaseHardened;
  p.surface = 600 * kPaPerHB;
  p.core = 500 * kPaPerHB;  // default limit 0.8*600 = 480 HB is below the core
  p.case_depth = 2e-3;
  EXPECT_THROW(HardnessModel{p}, InputError);
  p.core = 300 * kPaPerHB;
  p.limit = 650 * kPaPerHB;  // above the surface
  EXPECT_THROW(HardnessModel{p}, InputError);
  p.limit = 0;
  p.case_depth = 0;
  EXPECT_THROW(HardnessModel{p}, InputError);
  p.case_depth = 2e-3;
  p.core = 700 * kPaPerHB;
  EXPECT_THROW(HardnessModel{p}, InputError);
  p.core = 0;
  EXPECT_THROW(HardnessModel{p}, InputError);
  try {
    p.core = 500 * kPaPerHB;
    HardnessModel m(p, "wear.rack_hardness");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "wear.rack_hardness.limit");
  }
}

}  // namespace
}  // namespace rackopt
