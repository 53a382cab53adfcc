// The mesh force law tabulated from the static stiffness model
// (docs/models/dynamics.md, "Mesh force law"): the law's own arrays against
// the static curve (load, stiffness, relief), continuity of the force in
// travel with corner contact, the corner gaps against rolling the pinion in
// an independent construction, the backlash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "rackopt/dynamics/mesh_force_law_builder.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt {
namespace {

// The law's force in row r at approach delta >= 0, from its arrays (front flank).
double row_force(const MeshForceLaw& law, std::size_t r, double delta) {
  double f = 0;
  for (int i = 0; i < law.slots; ++i) {
    const std::size_t at = r * static_cast<std::size_t>(law.slots) + static_cast<std::size_t>(i);
    f += law.stiffness[at] * std::max(0.0, delta - law.gap[at]);
  }
  return f;
}
// dF/d delta in row r at delta (slots whose gap is closed).
double row_tangent(const MeshForceLaw& law, std::size_t r, double delta) {
  double k = 0;
  for (int i = 0; i < law.slots; ++i) {
    const std::size_t at = r * static_cast<std::size_t>(law.slots) + static_cast<std::size_t>(i);
    if (delta > law.gap[at]) k += law.stiffness[at];
  }
  return k;
}
double row_full(const MeshForceLaw& law, std::size_t r) {
  double k = 0;
  for (int i = 0; i < law.slots; ++i) k += law.stiffness[r * static_cast<std::size_t>(law.slots) + static_cast<std::size_t>(i)];
  return k;
}
int regular_pairs(const MeshForceLaw& law, std::size_t r, int curve_slots) {
  int n = 0;
  for (int i = 0; i < curve_slots; ++i) n += law.stiffness[r * static_cast<std::size_t>(law.slots) + static_cast<std::size_t>(i)] > 0;
  return n;
}

void check_sizes(const MeshForceLaw& law) {
  ASSERT_GT(law.travel.size(), 2u);
  ASSERT_EQ(law.stiffness.size(), law.travel.size() * static_cast<std::size_t>(law.slots));
  ASSERT_EQ(law.gap.size(), law.stiffness.size());
  // What MeshForceLaw::validate asks: travel from 0 to the period, ascending,
  // at most two samples at one travel, some slot touching in every row.
  EXPECT_EQ(law.travel.front(), 0.0);
  EXPECT_EQ(law.travel.back(), law.period);
  for (std::size_t r = 1; r < law.travel.size(); ++r) ASSERT_GE(law.travel[r], law.travel[r - 1]);
  for (std::size_t r = 2; r < law.travel.size(); ++r) ASSERT_NE(law.travel[r], law.travel[r - 2]);
  for (std::size_t r = 0; r < law.travel.size(); ++r) ASSERT_GT(row_full(law, r), 0.0);
  for (double g : law.gap) ASSERT_GE(g, 0.0);
  for (double k : law.stiffness) ASSERT_TRUE(std::isfinite(k) && k >= 0);
}

// Without corner contact every row is a curve sample: the law at the static
// approach carries load.force, and its full stiffness is the curve's K.
TEST(MeshForceLawBuilder, CarriesTheLoadAtTheStaticApproachOfEverySample) {
  for (const char* file : {"gantry_axis.yaml", "rack_railway.yaml", "rack_railway_paper.yaml", "large_module.yaml",
                           "ship_lift.yaml"}) {
    SCOPED_TRACE(file);
    const Drive d = test_support::load_shipped_problem(file);
    const MeshStiffnessModel model(d);
    MeshForceLawOptions off;
    off.corner_contact = false;
    const MeshForceLaw law = build_mesh_force_law(d, model, 20, off);
    const StiffnessCurve curve = model.curve(CurveDetail::kFull, 20);
    check_sizes(law);
    ASSERT_EQ(law.travel.size(), curve.samples.size());
    EXPECT_EQ(law.slots, curve.max_pairs);
    EXPECT_DOUBLE_EQ(law.period, d.rack.span);
    EXPECT_DOUBLE_EQ(law.mesh_pitch, std::numbers::pi * d.pinion.module);
    const double F = d.load.force;
    for (std::size_t r = 0; r < law.travel.size(); ++r) {
      const MeshState& st = curve.samples[r];
      ASSERT_EQ(law.travel[r], st.travel);
      ASSERT_NEAR(row_force(law, r, st.approach), F, 1e-9 * F) << "X = " << st.travel;
      ASSERT_NEAR(row_full(law, r), st.stiffness, 1e-9 * st.stiffness) << "X = " << st.travel;
      ASSERT_NEAR(row_tangent(law, r, st.approach), st.stiffness, 1e-9 * st.stiffness);
    }
  }
}

// With corner contact the corner slots act only near the path ends: every
// row whose corner gaps stay open at the static approach still carries
// load.force; near a pair entry or exit the corner pair closes its gap and
// carries some of the load.
TEST(MeshForceLawBuilder, CornerSlotsActOnlyNextToThePathEnds) {
  for (const char* file : {"gantry_axis.yaml", "rack_railway.yaml", "rack_railway_paper.yaml", "large_module.yaml",
                           "ship_lift.yaml"}) {
    SCOPED_TRACE(file);
    const Drive d = test_support::load_shipped_problem(file);
    const MeshStiffnessModel model(d);
    const MeshForceLaw law = build_mesh_force_law(d, model, 40);
    const StiffnessCurve curve = model.curve(CurveDetail::kFull, 40);
    check_sizes(law);
    const int S = curve.max_pairs;
    ASSERT_EQ(law.slots, S + 2);
    const double F = d.load.force;
    std::size_t c = 0, open_rows = 0, acting_rows = 0, limit_rows = 0;
    for (std::size_t r = 0; r < law.travel.size(); ++r) {
      double delta0 = 0;
      if (c < curve.samples.size() && curve.samples[c].travel == law.travel[r]) {
        delta0 = curve.samples[c++].approach;
      } else {
        delta0 = model.at(law.travel[r]).approach;  // a corner slot's limit
        ++limit_rows;
      }
      bool acting = false;
      for (int i = S; i < S + 2; ++i) {
        const std::size_t at = r * static_cast<std::size_t>(law.slots) + static_cast<std::size_t>(i);
        acting = acting || (law.stiffness[at] > 0 && law.gap[at] < delta0);
      }
      if (acting) {
        ++acting_rows;
        EXPECT_GT(row_force(law, r, delta0), F);
      } else {
        ++open_rows;
        ASSERT_NEAR(row_force(law, r, delta0), F, 1e-9 * F) << "X = " << law.travel[r];
      }
    }
    EXPECT_EQ(c, curve.samples.size());
    EXPECT_GT(open_rows, acting_rows);
    EXPECT_GT(limit_rows, 0u);
    if (std::string(file) == "gantry_axis.yaml") {
      EXPECT_GT(acting_rows, 0u);
    }
    std::printf("%s, 40 per period: %zu rows, a corner acting at the static approach in %zu, %zu limit rows\n", file,
                law.travel.size(), acting_rows, limit_rows);
  }
}

// The largest jump of the force in travel at fixed approach (the left row's
// static approach), relative to F: at every jump of the law's rows, or
// (entries_only) where the number of pairs in the path changes.
double largest_entry_jump(const MeshForceLaw& law, const MeshStiffnessModel& model, int curve_slots, double F,
                          bool entries_only = true) {
  double worst = 0;
  for (std::size_t r = 0; r + 1 < law.travel.size(); ++r) {
    if (law.travel[r] != law.travel[r + 1]) continue;
    if (entries_only && regular_pairs(law, r, curve_slots) == regular_pairs(law, r + 1, curve_slots)) continue;
    const double delta = model.at(law.travel[r], -1).approach;
    worst = std::max(worst, std::abs(row_force(law, r, delta) - row_force(law, r + 1, delta)) / F);
  }
  return worst;
}

TEST(MeshForceLawBuilder, CornerContactMakesTheForceContinuousInTravel) {
  MeshForceLawOptions off;
  off.corner_contact = false;
  // Independent pairs (rigid rack body, no pair coupling, a load-independent
  // contact term): each pair's stiffness does not depend on the others, so
  // the corner pair at the path end is the pair inside: no jump at all.
  {
    const Drive d = test_support::load_shipped_problem(
        "gantry_axis.yaml", {"effects.rack_span=rigid", "effects.pair_coupling=off", "effects.hertz=linear"});
    const MeshStiffnessModel model(d);
    const MeshForceLaw on_law = build_mesh_force_law(d, model, 40);
    const MeshForceLaw off_law = build_mesh_force_law(d, model, 40, off);
    const int S = off_law.slots;
    const double jump_on = largest_entry_jump(on_law, model, S, d.load.force);
    const double jump_off = largest_entry_jump(off_law, model, S, d.load.force);
    std::printf("independent pairs: largest force jump at a pair entry/exit %.3g F with corner contact, %.3g F without\n",
                jump_on, jump_off);
    EXPECT_LT(jump_on, 1e-9);
    EXPECT_GT(jump_off, 0.2);
  }
  // As shipped (coupled rack body, coupled pairs, load-dependent contact):
  // the corner pair adds what the mesh stiffness gains when the pair enters.
  // At every jump of the law's rows (entries, exits, corner slot limits,
  // supports), on every shipped problem.
  for (const char* file : {"gantry_axis.yaml", "rack_railway.yaml", "rack_railway_paper.yaml", "large_module.yaml",
                           "ship_lift.yaml"}) {
    SCOPED_TRACE(file);
    const Drive d = test_support::load_shipped_problem(file);
    const MeshStiffnessModel model(d);
    const MeshForceLaw on_law = build_mesh_force_law(d, model, 40);
    const MeshForceLaw off_law = build_mesh_force_law(d, model, 40, off);
    const int S = off_law.slots;
    const double jump_on = largest_entry_jump(on_law, model, S, d.load.force, false);
    const double jump_off = largest_entry_jump(off_law, model, S, d.load.force);
    std::printf("%s: largest force jump in travel %.3g F with corner contact, %.3g F without\n", file, jump_on,
                jump_off);
    EXPECT_GT(jump_off, 0.2);
    const std::string name = file;
    if (name == "rack_railway_paper.yaml") {
      // Interference ignored: the path starts behind the base circle, where no
      // corner is modelled; the tip side alone is continuous.
      EXPECT_LT(jump_on, jump_off);
    } else if (name == "rack_railway.yaml") {
      // The cutter's full tip round ends its straight flank at the rack's tip
      // height: the rack tip corner grazes the undercut form corner (gap 0)
      // until a corner slot of a few 1e5 N/m ends there.
      EXPECT_LT(jump_on, 1e-5);
    } else {
      EXPECT_LT(jump_on, 1e-9);
    }
  }
  {
    const Drive d = test_support::load_shipped_problem("gantry_axis.yaml");
    const MeshStiffnessModel model(d);
    const MeshForceLaw on_law = build_mesh_force_law(d, model, 40);
    const MeshForceLaw off_law = build_mesh_force_law(d, model, 40, off);
    const int S = off_law.slots;
    const double jump_on = largest_entry_jump(on_law, model, S, d.load.force);
    const double jump_off = largest_entry_jump(off_law, model, S, d.load.force);
    std::printf("gantry as shipped: largest force jump at a pair entry/exit %.3g F with corner contact, %.3g F without\n",
                jump_on, jump_off);
    EXPECT_LT(jump_on, 1e-9);
    EXPECT_GT(jump_off, 0.2);
  }
}

// --- corner gaps by rolling the pinion (drive frame: pinion centre at the
// origin, y up, rack below; the line of action through the pitch point (0, -r)
// at alpha, s growing along d = (cos a, -sin a) from T, the base-circle
// tangency point). The pinion flank of the pair at s is the involute through
// T + s d; turning the pinion counter-clockwise by Delta moves it along +d.
struct Frame {
  double r, rb, a, s_end, s_form, y_tip;
  double dx, dy;  // d
  double tx, ty;  // T
};

Frame frame_of(const MeshGeometry& g) {
  Frame f{};
  f.r = g.pinion.pitch_radius;
  f.rb = g.pinion.base_radius;
  f.a = g.pressure_angle;
  f.s_end = g.path.s_end;
  f.s_form = std::sqrt(std::max(0.0, g.pinion.form_radius * g.pinion.form_radius - f.rb * f.rb));
  f.y_tip = -(f.r + g.profile_shift_length + g.clearance - g.rack.addendum);
  f.dx = std::cos(f.a);
  f.dy = -std::sin(f.a);
  f.tx = -f.rb * std::sin(f.a);
  f.ty = -f.rb * std::cos(f.a);
  return f;
}

struct P2 {
  double x, y;
};
P2 rotate(P2 p, double t) { return {p.x * std::cos(t) - p.y * std::sin(t), p.x * std::sin(t) + p.y * std::cos(t)}; }

// The involute point at roll length L of the flank whose LOA point is s, and
// its outward normal (the unwound string's direction).
P2 involute_point(const Frame& f, double s, double L, P2* normal = nullptr) {
  const double tau_T = std::atan2(f.ty, f.tx);
  const double phi = tau_T + s / f.rb - L / f.rb;
  const P2 w{-std::sin(phi), std::cos(phi)};
  if (normal) *normal = w;
  return {f.rb * std::cos(phi) + L * w.x, f.rb * std::sin(phi) + L * w.y};
}

double bisect(const std::function<double(double)>& h, double lo, double hi) {
  for (int it = 0; it < 64; ++it) {  // 0.05 rad / 2^64: below rounding
    const double mid = 0.5 * (lo + hi);
    ((h(mid) < 0) == (h(lo) < 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A pinion corner (roll length L on the flank) against the rack flank of the
// pair at s: turn the pinion until the corner reaches the flank line.
double rolled_pinion_corner_gap(const Frame& f, double s, double L) {
  const P2 c = involute_point(f, s, L);
  const P2 q{f.tx + s * f.dx, f.ty + s * f.dy};
  auto h = [&](double t) {
    const P2 p = rotate(c, t);
    return (p.x - q.x) * f.dx + (p.y - q.y) * f.dy;  // < 0: behind the rack flank
  };
  EXPECT_LT(h(0), 0);
  return f.rb * bisect(h, 0.0, 0.05);
}

// The rack tip corner of the pair at s against the pinion flank: turn the
// pinion until the involute (sampled densely, the nearest point refined)
// passes through the corner.
double rolled_rack_corner_gap(const Frame& f, double s) {
  const P2 q{f.tx + s * f.dx, f.ty + s * f.dy};
  const double lambda = (f.y_tip - q.y) / std::cos(f.a);
  const P2 k{q.x + lambda * std::sin(f.a), q.y + lambda * std::cos(f.a)};
  auto signed_distance = [&](double t) {
    const P2 kk = rotate(k, -t);  // the corner seen from the pinion turned by t
    auto d2 = [&](double L) {
      const P2 p = involute_point(f, s, L);
      return (p.x - kk.x) * (p.x - kk.x) + (p.y - kk.y) * (p.y - kk.y);
    };
    const int n = 1000;
    int best = 0;
    for (int i = 1; i <= n; ++i) {
      if (d2(f.s_end * i / n) < d2(f.s_end * best / n)) best = i;
    }
    double lo = f.s_end * std::max(best - 1, 0) / n, hi = f.s_end * std::min(best + 1, n) / n;
    for (int it = 0; it < 80; ++it) {  // ternary search: (2/3)^80 of one sample step
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      (d2(m1) < d2(m2) ? hi : lo) = d2(m1) < d2(m2) ? m2 : m1;
    }
    P2 w{};
    const P2 p = involute_point(f, s, 0.5 * (lo + hi), &w);
    return (kk.x - p.x) * w.x + (kk.y - p.y) * w.y;  // > 0: outside the tooth
  };
  EXPECT_GT(signed_distance(0), 0);
  return f.rb * bisect(signed_distance, 0.0, 0.05);
}

TEST(MeshForceLawBuilder, CornerGapsMatchRollingThePinion) {
  // Gantry: no undercut, the path starts at the rack tip; rack railway: an
  // undercut pinion, the path starts at its form circle.
  for (const char* file : {"gantry_axis.yaml", "rack_railway.yaml"}) {
    SCOPED_TRACE(file);
    const Drive d = test_support::load_shipped_problem(file);
    const MeshGeometry g = build_mesh_geometry(d);
    const Frame f = frame_of(g);
    const double pb = g.path.base_pitch;
    EXPECT_NEAR(*corner_gap(g, g.path.s_end), 0.0, 1e-15);
    EXPECT_NEAR(*corner_gap(g, g.path.s_start), 0.0, 1e-15);
    EXPECT_FALSE(corner_gap(g, 0.5 * (g.path.s_start + g.path.s_end)));
    int compared = 0;
    double previous_tip = 0, previous_root = 0;
    for (double u : {1e-3, 5e-3, 0.02, 0.05, 0.1}) {
      const std::optional<double> tip = corner_gap(g, g.path.s_end + u * pb);
      ASSERT_TRUE(tip);
      const double rolled = rolled_pinion_corner_gap(f, g.path.s_end + u * pb, f.s_end);
      EXPECT_NEAR(*tip, rolled, 1e-10 + 1e-7 * rolled) << "tip side, u = " << u;
      EXPECT_GT(*tip, previous_tip);
      previous_tip = *tip;
      const double s = g.path.s_start - u * pb;
      const std::optional<double> root = corner_gap(g, s);
      ASSERT_TRUE(root);
      const double rolled_root = g.path.start_limited_by == "rack_tip" ? rolled_rack_corner_gap(f, s)
                                                                       : rolled_pinion_corner_gap(f, s, f.s_form);
      EXPECT_NEAR(*root, rolled_root, 1e-10 + 1e-6 * rolled_root) << "root side, u = " << u;
      EXPECT_GT(*root, previous_root);
      previous_root = *root;
      compared += 2;
      if (u == 0.02) {
        std::printf("%s: start limited by %s; corner gaps 0.02 p_b outside the path: tip side %.4g um, root side %.4g um\n",
                    file, g.path.start_limited_by.c_str(), *tip * 1e6, *root * 1e6);
      }
    }
    EXPECT_EQ(compared, 10);
  }
}

TEST(MeshForceLawBuilder, BacklashIsTheNormalBacklashOfTheClearance) {
  for (const char* clearance : {"0 mm", "0.2 mm"}) {
    const Drive d = test_support::load_shipped_problem("gantry_axis.yaml",
                                                       {std::string("mounting.clearance=") + clearance});
    const MeshStiffnessModel model(d);
    const MeshForceLaw law = build_mesh_force_law(d, model, 10);
    const double a = d.pinion.pressure_angle;
    EXPECT_NEAR(law.backlash, 2 * d.mounting.clearance * std::sin(a), 1e-18);
    EXPECT_TRUE(std::isfinite(law.backlash));
  }
}

// A relieved design: each pair's gap is its relief, and the law (stiffness
// C_A^-1 1 per loaded pair) still carries load.force with tangent K at the
// static approach, on the coupled rack body. K x load_share would not: the
// loaded pairs' forces are not proportional to their stiffness under relief.
TEST(MeshForceLawBuilder, RelievedDesignKeepsTheReliefGaps) {
  const Drive d = test_support::load_shipped_problem(
      "gantry_axis.yaml", {"pinion.tip_relief.amount=15 um", "pinion.tip_relief.length=1.0",
                           "pinion.root_relief.amount=10 um", "pinion.root_relief.length=0.8"});
  const MeshStiffnessModel model(d);
  MeshForceLawOptions off;
  off.corner_contact = false;
  const MeshForceLaw law = build_mesh_force_law(d, model, 40, off);
  const StiffnessCurve curve = model.curve(CurveDetail::kFull, 40);
  ASSERT_EQ(law.travel.size(), curve.samples.size());
  const double F = d.load.force;
  int relieved = 0, open = 0;
  double worst_share_law = 0;
  for (std::size_t r = 0; r < law.travel.size(); ++r) {
    const MeshState& st = curve.samples[r];
    double f_load_share = 0;
    for (const PairState& p : st.pairs) {
      const std::size_t at = r * static_cast<std::size_t>(law.slots) + static_cast<std::size_t>(p.slot);
      if (p.load_share > 0) {
        ASSERT_EQ(law.gap[at], p.relief);
        relieved += p.relief > 0;
      } else if (p.relief > 0) {
        ++open;
        EXPECT_GE(law.gap[at], st.approach);  // an open relieved pair engages beyond the static approach
        EXPECT_GT(law.stiffness[at], 0);
      }
      f_load_share += st.stiffness * p.load_share * std::max(0.0, st.approach - p.relief);
    }
    ASSERT_NEAR(row_force(law, r, st.approach), F, 1e-9 * F) << "X = " << st.travel;
    ASSERT_NEAR(row_tangent(law, r, st.approach), st.stiffness, 1e-9 * st.stiffness) << "X = " << st.travel;
    worst_share_law = std::max(worst_share_law, std::abs(f_load_share - F) / F);
  }
  std::printf("relieved gantry: %d loaded relieved pairs, %d open ones; K x load_share would miss F by up to %.3g\n",
              relieved, open, worst_share_law);
  EXPECT_GT(relieved, 0);
  EXPECT_GT(worst_share_law, 1e-6);
}

}  // namespace
}  // namespace rackopt
