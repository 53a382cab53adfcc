// Archard wear life (src/rackopt/wear/wear_life.hpp) on the wear paper's ship-lift
// drive: closed forms, scaling laws, the wear paper's trends, exact finish, hard cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/wear/contact.hpp"
#include "rackopt/wear/wear_life.hpp"
#include "wear_drives.hpp"

namespace rackopt {
namespace {

constexpr double kH0 = 596 * kPaPerHB;

Drive constant_hardness_drive() {
  Drive d = test::ship_lift_wear();
  d.wear.pinion_hardness = test::constant_hardness(596);
  d.wear.rack_hardness = test::constant_hardness(596);
  return d;
}

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

// Closed form (docs/models/wear.md): with a single pair in contact over
// the whole path (contact ratio exactly 1), frozen load (no profile update)
// and constant hardness, a point at s wears k w g(s) per own pass, so the life
// is h_max / (k w g_max) passes EXACTLY, with k = K/H, w = F/b and
// g = |s - s_P|/s (pinion, x3 passes per rack pass here) or |s - s_P|/s_P (rack).
TEST(WearLife, ClosedFormSinglePairFrozenLoad) {
  Drive d = constant_hardness_drive();
  d.wear.update_profile = false;
  d.duty.pinion_meshes_per_year = 3 * d.duty.rack_meshes_per_year;
  const WearModel model(d, WearOptions{.hertz_band = false});
  const MeshGeometry& g = model.geometry();
  const double s_end = g.path.s_end, s_start = s_end - g.path.base_pitch, sP = g.path.s_pitch;
  const double w = d.load.force / 0.120, k = d.wear.coefficient / kH0;
  const double g_rack = std::max(std::abs(s_end - sP), std::abs(s_start - sP)) / sP;
  const double g_pin = std::max(std::abs(s_end - sP) / s_end, std::abs(s_start - sP) / s_start);
  const double rack_life = d.wear.max_depth / (k * w * g_rack);
  const double pinion_life = d.wear.max_depth / (k * w * g_pin * 3);
  const WearLifeResult r = model.life({.contact_ratio = 1.0});
  EXPECT_EQ(r.criterion, "max_depth");
  EXPECT_NEAR(r.life_cycles / std::min(rack_life, pinion_life), 1.0, 1e-12);
  EXPECT_NEAR(r.life_years, r.life_cycles / d.duty.rack_meshes_per_year, 1e-9 * r.life_years);
  EXPECT_NEAR(r.life_pinion_cycles, 3 * r.life_cycles, 1e-9 * r.life_cycles);
  EXPECT_EQ(r.limiting_member, rack_life < pinion_life ? Member::kRack : Member::kPinion);
  EXPECT_EQ(r.blocks, 1);  // frozen load: hardness integrated exactly, no blocks needed
}

// Same with the wear paper's polynomial hardness: dh/dn = k(h) w g with k = K/H(h)
// integrates to n = int_0^hmax H(h) dh / (K w g), the integral done here
// analytically from the cubic's coefficients (the model tabulates H).
TEST(WearLife, ClosedFormPolynomialHardness) {
  Drive d = test::ship_lift_wear();
  d.wear.update_profile = false;
  const WearModel model(d, WearOptions{.hertz_band = false});
  const MeshGeometry& g = model.geometry();
  const double s_end = g.path.s_end, s_start = s_end - g.path.base_pitch, sP = g.path.s_pitch;
  const double w = d.load.force / 0.120;
  const double g_max = std::max({std::abs(s_end - sP) / sP, std::abs(s_start - sP) / sP,
                                 std::abs(s_end - sP) / s_end, std::abs(s_start - sP) / s_start});
  double G = 0;
  const auto& c = d.wear.rack_hardness.coefficients;
  for (std::size_t i = 0; i < c.size(); ++i) G += c[i] * std::pow(d.wear.max_depth, i + 1.0) / (i + 1.0);
  const WearLifeResult r = model.life({.contact_ratio = 1.0});
  EXPECT_NEAR(r.life_cycles / (G / (d.wear.coefficient * w * g_max)), 1.0, 1e-9);
}

// Sliding distance of a pinion flank point through a band of half-width a,
// per unit band width, by quadrature: the point at s is in the band while
// the involute arc to the contact centre c, |c^2 - s^2|/(2 r_b), is at most
// a, and the contact slides |c - s_P| per unit of c/r_b.
double involute_window_sliding(double s, double a, double rb, double sP) {
  const double lo = std::sqrt(std::max(0.0, s * s - 2 * a * rb)), hi = std::sqrt(s * s + 2 * a * rb);
  const int n = 20000;
  double sum = 0;
  for (int j = 0; j < n; ++j) sum += std::abs(lo + (j + 0.5) * (hi - lo) / n - sP);
  return sum * (hi - lo) / n / rb / (2 * a);
}

// With the Hertz band average, points whose band lies inside a constant-load
// stretch still wear exactly k w g per pass (the elliptic weight integrates
// to 1): g = |s - s_P|/s_P on the rack; on the pinion g is the sliding over
// the band's exact window on the involute, which is |s - s_P|/s to second
// order in a r_b/s^2 (here within 0.3 %).
TEST(WearLife, BandAverageKeepsConstantLoadExact) {
  Drive d = constant_hardness_drive();
  const WearModel model(d);
  const WearModel::PassWear pw = model.initial_wear_per_pass({.contact_ratio = 1.0});
  const double sP = model.geometry().path.s_pitch, w = d.load.force / 0.120, k = d.wear.coefficient / kH0;
  const double rb = model.geometry().pinion.base_radius;
  const double e_star = effective_modulus(d.pinion.material, d.rack.material);
  const std::size_t n = pw.rack.s.size();
  for (std::size_t i = n / 4; i < 3 * n / 4; ++i) {
    const double s = pw.rack.s[i];
    EXPECT_NEAR(pw.rack.depth[i], k * w * std::abs(s - sP) / sP, 1e-12 * k * w) << s;
    const double a = hertz_line_contact(w, s, e_star).half_width;
    EXPECT_NEAR(pw.pinion.depth[i], k * w * involute_window_sliding(s, a, rb, sP), 1e-7 * k * w) << s;
    EXPECT_NEAR(pw.pinion.depth[i], k * w * std::abs(s - sP) / s, 3e-3 * k * w * std::abs(s - sP) / s) << s;
  }
  // At the path ends only half the band is on the path.
  EXPECT_NEAR(pw.load_per_width.back() / w, 0.5, 1e-9);
}

// The pair loads are the tooth models' rigid-body shares (docs/models/mesh.md), not
// an equal split: compare with MeshStiffnessModel (an independent assembly of
// the same tooth models and the same pairs' coupling) with a rigid rack body,
// the coupling on (the default) and off.
void expect_load_sharing_matches_the_stiffness_model(bool pair_coupling) {
  SCOPED_TRACE(pair_coupling ? "pair coupling on" : "pair coupling off");
  Drive d = test::ship_lift_wear();
  d.effects.rack_span = RackSpanModel::kRigid;
  d.effects.pair_coupling = pair_coupling;
  const WearModel model(d, WearOptions{.hertz_band = false});
  const WearModel::PassWear pw = model.initial_wear_per_pass();
  const MeshStiffnessModel mesh(d);
  const MeshGeometry& g = model.geometry();
  const double pb = g.path.base_pitch, eps = g.path.contact_ratio, b = 0.120;
  const double t1 = g.path.s_start + (eps - 1) * pb, t2 = g.path.s_start + pb;  // zone transitions
  const double ds = pw.rack.s[1] - pw.rack.s[0];
  int checked = 0, unequal = 0;
  for (const MeshState& st : mesh.curve().samples) {
    for (const PairState& p : st.pairs) {
      if (std::abs(p.s - t1) < ds || std::abs(p.s - t2) < ds || p.s > g.path.s_end - ds) continue;
      const auto it = std::upper_bound(pw.rack.s.begin(), pw.rack.s.end(), p.s);
      const std::size_t i = static_cast<std::size_t>(it - pw.rack.s.begin()) - 1;
      const double f = (p.s - pw.rack.s[i]) / ds;
      const double ours = pw.load_per_width[i] * (1 - f) + pw.load_per_width[i + 1] * f;
      EXPECT_NEAR(ours, p.load_share * d.load.force / b, 2e-3 * d.load.force / b) << p.s;
      if (st.pairs.size() == 2 && std::abs(p.load_share - 0.5) > 0.02) ++unequal;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
  EXPECT_GT(unequal, 10);  // double contact is not shared equally
}

TEST(WearLife, LoadSharingMatchesTheStiffnessModel) {
  expect_load_sharing_matches_the_stiffness_model(true);
  expect_load_sharing_matches_the_stiffness_model(false);
}

// The pairs' coupling reaches the wear model through the same effect: the
// double-contact loads move when it is switched off.
TEST(WearLife, PairCouplingMovesTheDoubleContactLoads) {
  Drive d = test::ship_lift_wear();
  ASSERT_TRUE(d.effects.pair_coupling);
  const WearModel::PassWear on = WearModel(d, WearOptions{.hertz_band = false}).initial_wear_per_pass();
  d.effects.pair_coupling = false;
  const WearModel::PassWear off = WearModel(d, WearOptions{.hertz_band = false}).initial_wear_per_pass();
  ASSERT_EQ(on.load_per_width.size(), off.load_per_width.size());
  double largest = 0, w = 0;
  for (std::size_t i = 0; i < on.load_per_width.size(); ++i) {
    largest = std::max(largest, std::abs(on.load_per_width[i] - off.load_per_width[i]));
    w = std::max(w, off.load_per_width[i]);
  }
  EXPECT_GT(largest, 1e-3 * w);
}

// Archard: life is proportional to 1/K (six decades) and to H, exactly, even
// with the profile update: the whole depth history is the same, only the pass
// count scales. Load: life ~ 1/F exactly for the pointwise frozen-load law
// (w is linear in F and nothing else depends on F); the Hertz band (a ~ sqrt F)
// and the update (deflection vs wear gap) make it approximate.
TEST(WearLife, ArchardScaling) {
  const Drive d = test::ship_lift_wear();
  const WearModel model(d);
  const double base = model.life().life_cycles;
  for (double s : {1e-3, 1e-2, 1e-1, 10.0, 100.0, 1e3}) {
    const WearLifeResult r = model.life({.wear_coefficient_scale = s});
    EXPECT_NEAR(r.life_cycles * s / base, 1.0, 1e-9) << s;
    EXPECT_TRUE(std::isfinite(r.life_years));
  }
  for (double s : {0.5, 2.0}) EXPECT_NEAR(model.life({.surface_hardness_scale = s}).life_cycles / s / base, 1.0, 1e-9);

  Drive frozen = d;
  frozen.wear.update_profile = false;
  const WearModel pointwise(frozen, WearOptions{.hertz_band = false});
  const double b0 = pointwise.life().life_cycles;
  for (double s : {0.25, 0.5, 2.0, 4.0})
    EXPECT_NEAR(pointwise.life({.force_scale = s}).life_cycles * s / b0, 1.0, 1e-12) << s;
  const WearModel banded(frozen);
  const double b1 = banded.life().life_cycles;
  for (double s : {0.5, 2.0}) {
    const double ratio = banded.life({.force_scale = s}).life_cycles * s / b1;
    EXPECT_NEAR(ratio, 1.0, 0.1) << s;
    std::printf("[ info ] band, frozen: life*F at F x %.1f / nominal = %.4f\n", s, ratio);
  }
  for (double s : {0.5, 2.0})
    std::printf("[ info ] full model: life*F at F x %.1f / nominal = %.4f\n", s,
                model.life({.force_scale = s}).life_cycles * s / base);
}

// The wear paper (docs/models/wear.md): "wear rate of tooth root is greater than the
// crown": the rack root (meets the pinion tip, specific sliding -1.12) wears
// more than the rack tip; the pinion wears most towards its root (-1.15).
TEST(WearLife, WearPaperRackRootWearsMoreThanTip) {
  const Drive d = test::ship_lift_wear();
  const WearModel model(d);
  const double sP = model.geometry().path.s_pitch;
  const WearModel::PassWear pw = model.initial_wear_per_pass();
  const WearLifeResult r = model.life();
  for (const WearProfile* rack : {&pw.rack, &r.rack}) {
    double root = 0, tip = 0;
    for (std::size_t i = 0; i < rack->s.size(); ++i) (rack->s[i] > sP ? root : tip) = std::max(rack->s[i] > sP ? root : tip, rack->depth[i]);
    EXPECT_GT(root, 1.2 * tip);
  }
  // Unworn, also at the path ends themselves (sliding ratio 1.12 vs 0.53, both
  // ends in double contact). Not after the whole life: the worn ends unload.
  EXPECT_GT(pw.rack.depth.back(), 1.5 * pw.rack.depth.front());
  EXPECT_GT(pw.pinion.depth.front(), pw.pinion.depth.back());
  EXPECT_EQ(r.max_depth_member, Member::kRack);
  EXPECT_GT(r.max_depth_s, sP);
  // The rack flank position is measured from the point that meets the pinion tip.
  EXPECT_NEAR(r.rack.position.back(), 0.0, 1e-15);
  EXPECT_NEAR(r.rack.position.front(), (r.rack.s.back() - r.rack.s.front()) * std::tan(20 * M_PI / 180), 1e-12);
}

// docs/models/wear.md: K = 3e-6 gives ~2.6e5 meshes to 1.5 mm with the seed's
// p0 law and full load on one pair at the worst point. Our law is 4/pi lower
// per pass and a pair never carries more than F, so the life is at least
// 2.6e5 * 4/pi (less the 0.27 % hardness drop) and of the same order.
TEST(WearLife, WearPaperOrderOfMagnitude) {
  const WearModel model(test::ship_lift_wear());
  const WearLifeResult r = model.life();
  std::printf("[ info ] the wear paper, K = 3e-6: %.4g rack passes (%.1f years at 4000/yr), %s, eps %.4f -> %.4f\n",
              r.life_cycles, r.life_years, r.criterion.c_str(), r.initial_contact_ratio, r.final_contact_ratio);
  EXPECT_GT(r.life_cycles, 2.6e5 * 4 / M_PI * 0.99);
  EXPECT_LT(r.life_cycles, 2.6e6);
  EXPECT_LT(r.final_contact_ratio, r.initial_contact_ratio);  // worn ends carry less
  EXPECT_GE(r.final_contact_ratio, 1.0);                      // one loaded pair always remains
  EXPECT_NEAR(r.initial_contact_ratio, 1.536, 0.001);         // docs/models/reliability.md
}

// The run ends exactly at the threshold whatever the block size, and the life
// converges as the blocks shrink.
TEST(WearLife, ExactFinishAndBlockConvergence) {
  Drive d = test::ship_lift_wear();
  std::vector<double> lives;
  for (double f : {0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.0025}) {
    d.wear.block_fraction = f;
    const WearLifeResult r = WearModel(d).life();
    EXPECT_EQ(r.criterion, "max_depth");
    EXPECT_NEAR(r.max_depth / d.wear.max_depth, 1.0, 1e-9) << f;
    EXPECT_GE(r.blocks, static_cast<int>(0.5 / f));
    lives.push_back(r.life_cycles);
    std::printf("[ info ] block_fraction %.4f: life %.8g passes, %d blocks, %.3f ms\n", f, r.life_cycles, r.blocks,
                r.seconds * 1e3);
    // Snapshots: 25/50/75/100 % with growing wear, the last one the final state.
    ASSERT_EQ(r.snapshots.size(), 4u);
    for (std::size_t k = 1; k < 4; ++k) EXPECT_GT(max_of(r.snapshots[k].rack.depth), max_of(r.snapshots[k - 1].rack.depth));
    EXPECT_DOUBLE_EQ(max_of(r.snapshots[3].rack.depth), r.max_depth);
  }
  const double ref = lives.back();
  EXPECT_LT(std::abs(lives[5] - ref), std::abs(lives[2] - ref));  // 0.005 closer than 0.05
  EXPECT_LT(std::abs(lives[4] - ref) / ref, 0.01);                 // 0.01: within 1 %
}

// Failure on the loaded contact ratio (the wear paper's correct-mesh criterion):
// finishes where it reaches the allowable value, before h_max.
TEST(WearLife, ContactRatioCriterionFinishesAtTheLimit) {
  Drive d = test::ship_lift_wear();
  const WearLifeResult whole = WearModel(d).life();
  const double full = whole.life_cycles;
  // A limit a little above the loaded contact ratio the flanks reach at
  // h_max: the wear must stop on it first.
  ASSERT_EQ(whole.criterion, "max_depth");
  const double limit = whole.final_contact_ratio + 0.02;
  d.wear.min_contact_ratio = limit;
  const WearLifeResult r = WearModel(d).life();
  EXPECT_EQ(r.criterion, "contact_ratio");
  EXPECT_NEAR(r.final_contact_ratio, limit, 1e-6);
  EXPECT_LT(r.life_cycles, full);
  EXPECT_GT(r.life_cycles, 0);
  EXPECT_LT(r.max_depth, d.wear.max_depth);
  EXPECT_FALSE(r.reason.empty());
}

// A sampled contact ratio below 1 (or the allowable) fails at once, above the
// zero-clearance maximum too; never a crash or NaN.
TEST(WearLife, SampledContactRatioOutOfRange) {
  const WearModel model(test::ship_lift_wear());
  for (double eps : {0.9, 0.999999, -1.0}) {
    const WearLifeResult r = model.life({.contact_ratio = eps});
    EXPECT_EQ(r.life_cycles, 0.0);
    EXPECT_EQ(r.life_years, 0.0);
    EXPECT_EQ(r.criterion, "initial_contact_ratio");
    EXPECT_FALSE(r.reason.empty());
    EXPECT_EQ(r.snapshots.size(), 4u);
  }
  const WearLifeResult hi = model.life({.contact_ratio = model.max_contact_ratio() + 0.01});
  EXPECT_EQ(hi.criterion, "contact_ratio_above_max");
  EXPECT_EQ(hi.life_cycles, 0.0);
  // Within range: a shorter path gives a finite, different life; eps = 1 works.
  for (double eps : {1.0, 1.2, 1.4, model.max_contact_ratio()}) {
    const WearLifeResult r = model.life({.contact_ratio = eps});
    EXPECT_TRUE(std::isfinite(r.life_cycles) && r.life_cycles > 0) << eps;
    EXPECT_NEAR(r.initial_contact_ratio, eps, 1e-12);
  }
  EXPECT_THROW(model.life({.contact_ratio = std::nan("")}), InputError);
  EXPECT_THROW(model.life({.force_scale = 0}), InputError);
  EXPECT_THROW(model.life({.wear_coefficient_scale = -1}), InputError);
}

// Zero sliding at the pitch point: zero wear there, no division by zero.
TEST(WearLife, PitchPointOnAProfilePointWearsNothing) {
  const Drive d = test::ship_lift_wear();
  const WearModel model(d);
  const MeshGeometry& g = model.geometry();
  // Contact ratio that puts profile point i = 18 (of 60) exactly on s_P.
  const int N = d.wear.profile_points, i = 18;
  const double eps = (g.path.s_end - g.path.s_pitch) * (N - 1) / ((N - 1 - i) * g.path.base_pitch);
  for (bool band : {false, true}) {
    const WearModel m(d, WearOptions{.hertz_band = band});
    const WearModel::PassWear pw = m.initial_wear_per_pass({.contact_ratio = eps});
    ASSERT_NEAR(pw.rack.s[i], g.path.s_pitch, 1e-12);
    EXPECT_LT(pw.rack.depth[i], 1e-12 * max_of(pw.rack.depth));
    // The pinion point at s_P slides while the contact centre passes on either
    // side of it within the band: a r_b/(2 s_P^2) per unit band width, about
    // 2 % here against a largest sliding ratio near 0.5.
    EXPECT_LT(pw.pinion.depth[i], (band ? 0.1 : 1e-12) * max_of(pw.pinion.depth));
    const WearLifeResult r = m.life({.contact_ratio = eps});
    EXPECT_TRUE(std::isfinite(r.life_cycles) && r.life_cycles > 0);
    EXPECT_LT(r.rack.depth[i], 0.05 * r.max_depth);
  }
}

// h_max tiny, deeper than the case, beyond the measured hardness data.
TEST(WearLife, DepthHardCases) {
  Drive d = test::ship_lift_wear();
  d.wear.max_depth = 1e-6;
  WearLifeResult r = WearModel(d).life();
  EXPECT_EQ(r.criterion, "max_depth");
  EXPECT_NEAR(r.max_depth, 1e-6, 1e-15);
  EXPECT_GT(r.life_cycles, 0);

  // Case-hardened 600 -> 300 HB, case 2 mm; h_max 3 mm.
  HardnessProfile ch;
  ch.kind = HardnessProfile::Kind::kCaseHardened;
  ch.surface = 600 * kPaPerHB;
  ch.core = 300 * kPaPerHB;
  ch.case_depth = 2e-3;
  d.wear.pinion_hardness = d.wear.rack_hardness = ch;
  d.wear.max_depth = 3e-3;
  d.wear.stop_at_case_depth = true;
  const WearLifeResult at_case = WearModel(d).life();
  EXPECT_EQ(at_case.criterion, "case_depth");
  EXPECT_NEAR(at_case.max_depth, 2e-3, 1e-12);
  d.wear.stop_at_case_depth = false;
  const WearLifeResult through = WearModel(d).life();
  EXPECT_EQ(through.criterion, "max_depth");
  EXPECT_NEAR(through.max_depth, 3e-3, 1e-12);
  EXPECT_GT(through.life_cycles, at_case.life_cycles);
  d.wear.pinion_hardness = d.wear.rack_hardness = test::constant_hardness(600);
  EXPECT_LT(through.life_cycles, WearModel(d).life().life_cycles);  // the soft core wears faster

  // Measured data only to 1 mm: clamped below it, warned, finite.
  d = test::ship_lift_wear();
  d.wear.pinion_hardness = d.wear.rack_hardness = test::wear_paper_polynomial(1e-3);
  r = WearModel(d).life();
  EXPECT_TRUE(std::isfinite(r.life_cycles));
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("beyond the measured hardness data"), std::string::npos);
  d = test::ship_lift_wear();
  EXPECT_TRUE(WearModel(d).life().warnings.empty());
}

TEST(WearLife, InputErrors) {
  Drive d = test::ship_lift_wear();
  d.wear.coefficient = 0;
  EXPECT_THROW(WearModel{d}, InputError);
  d = test::ship_lift_wear();
  d.wear.block_fraction = 0;
  EXPECT_THROW(WearModel{d}, InputError);
  d = test::ship_lift_wear();
  d.wear.max_depth = -1;
  EXPECT_THROW(WearModel{d}, InputError);
  d = test::ship_lift_wear();
  d.wear.rack_hardness = HardnessProfile{};  // constant with no surface value
  EXPECT_THROW(WearModel{d}, InputError);
}

// const, thread-safe, deterministic: the same samples in 4 threads give
// bit-identical results.
TEST(WearLife, ThreadSafeAndDeterministic) {
  const WearModel model(test::ship_lift_wear());
  std::vector<WearSample> samples;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 40; ++i)
    samples.push_back({0.5 + u(rng), 0.8 + 0.4 * u(rng), 0.9 + 0.2 * u(rng), 1.2 + 0.3 * u(rng)});
  std::vector<double> serial;
  for (const auto& s : samples) serial.push_back(model.life(s).life_cycles);
  std::vector<double> par(samples.size());
  std::vector<std::thread> th;
  for (int t = 0; t < 4; ++t)
    th.emplace_back([&, t] {
      for (std::size_t i = t; i < samples.size(); i += 4) par[i] = model.life(samples[i]).life_cycles;
    });
  for (auto& x : th) x.join();
  for (std::size_t i = 0; i < samples.size(); ++i) EXPECT_EQ(serial[i], par[i]);
}

// Cost (targets: one life < 1 ms, 1000 lives < 100 ms on one core).
// Printed; the assertion only catches gross regressions (sanitizer builds).
TEST(WearLife, Cost) {
  const WearModel model(test::ship_lift_wear());
  auto t0 = std::chrono::steady_clock::now();
  const int reps = 50;
  double sink = 0;
  for (int i = 0; i < reps; ++i) sink += model.life().life_cycles;
  const double one = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> eps(1.45, 0.03);
  std::lognormal_distribution<double> k(0, 0.3);
  t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 1000; ++i) sink += model.life({k(rng), 1.0, 1.0, eps(rng)}).life_cycles;
  const double thousand = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Drive frozen = test::ship_lift_wear();
  frozen.wear.update_profile = false;
  const WearModel fm(frozen);
  t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 1000; ++i) sink += fm.life({k(rng), 1.0, 1.0, eps(rng)}).life_cycles;
  const double thousand_frozen = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ info ] one life %.3f ms; 1000 sampled lives %.1f ms (update on), %.1f ms (update off)\n", one * 1e3,
              thousand * 1e3, thousand_frozen * 1e3);
  EXPECT_GT(sink, 0);
  EXPECT_LT(one, 0.05);
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// A path that starts next to the pinion base circle (interference ignored,
// so the start is the rack tip line's crossing s_A, set by the clearance):
// the thin-band law |s - s_P|/s made the wear per pass grow as 1/s_start and
// the life collapse in proportion to s_start (0.05 mm vs 5 mm of start: a
// hundredfold). The exact band window bounds the sliding, so the life tends
// to a finite limit, changes smoothly, and the model says so in a warning.
TEST(WearLife, StartAtTheBaseCircleHasAFiniteLifeAndAWarning) {
  Drive d = test::ship_lift_wear();
  d.pinion.teeth = 17;
  d.pinion.profile_shift = 0;
  d.effects.interference_limit = false;
  d.wear.update_profile = false;
  auto life_with_start = [&](double s_start) {
    Drive e = d;
    const MeshGeometry g = build_mesh_geometry(e);
    // s_A = s_P - (h_a2 m - x m - clearance) / sin a0
    const double sa = std::sin(e.pinion.pressure_angle);
    e.mounting.clearance = (s_start - g.path.s_pitch) * sa + e.rack.addendum_coef * e.pinion.module;
    const WearModel m(e);
    EXPECT_NEAR(m.geometry().path.s_start, s_start, 1e-9);
    return m.life();
  };
  const WearLifeResult at_base = life_with_start(0.05e-3), near = life_with_start(0.5e-3),
                       clear = life_with_start(5e-3);
  // The thin-band law gives lives in the ratio of the starts: 0.1 and 0.1.
  EXPECT_GT(at_base.life_cycles, 0.5 * near.life_cycles);
  EXPECT_GT(near.life_cycles, 0.4 * clear.life_cycles);
  EXPECT_LT(at_base.life_cycles, near.life_cycles * (1 + 1e-9));  // a start nearer the base circle wears more
  EXPECT_LT(near.life_cycles, clear.life_cycles);
  bool warned = false;
  for (const std::string& w : at_base.warnings) warned = warned || w.find("near the pinion base circle") != std::string::npos;
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace rackopt
