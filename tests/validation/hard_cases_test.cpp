// Hard cases: extreme geometry, spans, face widths,
// contact ratio exactly 1 and 2, contacts at supports. Each gives finite,
// positive values or a DesignError with a code: never NaN, a hang or a crash.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "test_drives.hpp"

namespace rackopt {
namespace {

// Returns true when a curve was computed (and checks it), false on DesignError.
bool check_curve(const Drive& d) {
  try {
    const MeshStiffnessModel model(d);
    const StiffnessCurve c = model.curve();
    for (const MeshState& s : c.samples) {
      EXPECT_TRUE(std::isfinite(s.stiffness) && s.stiffness > 0) << "X = " << s.travel;
      for (const PairState& p : s.pairs) {
        EXPECT_TRUE(std::isfinite(p.local()) && p.local() > 0);
        EXPECT_TRUE(std::isfinite(p.load_share) && p.load_share >= 0 && p.load_share <= 1 + 1e-12);
      }
    }
    EXPECT_TRUE(std::isfinite(c.k_mean) && c.k_min > 0 && c.k_max >= c.k_min);
    return true;
  } catch (const DesignError& e) {
    EXPECT_FALSE(e.code().empty());
    EXPECT_FALSE(std::string(e.what()).empty());
    return false;
  }
}

Drive small_fast(Drive d) {
  d.numerics.positions_per_period = 12;
  d.rack.span = 6 * M_PI * d.pinion.module;
  return d;
}

TEST(HardCases, TeethPressureAngleProfileShiftGrid) {
  const Drive base = small_fast(test::problem("ship_lift.yaml"));
  int computed = 0, rejected = 0;
  for (int z : {8, 10, 13, 17, 25, 40, 80, 150}) {
    for (double a_deg : {12.0, 14.5, 20.0, 25.0, 30.0}) {
      for (double x : {-0.5, 0.0, 0.5, 1.0}) {
        SCOPED_TRACE("z=" + std::to_string(z) + " a=" + std::to_string(a_deg) + " x=" + std::to_string(x));
        Drive d = base;
        d.pinion.teeth = z;
        d.pinion.pressure_angle = a_deg * M_PI / 180;
        d.pinion.profile_shift = x;
        d.load.force = 1e5;
        (check_curve(d) ? computed : rejected)++;
      }
    }
  }
  // Most of the grid is buildable; the rest is rejected with a reason.
  EXPECT_GT(computed, 60);
  RecordProperty("computed", computed);
  RecordProperty("rejected", rejected);
}

TEST(HardCases, SpansAndFaceWidths) {
  const Drive base = test::problem("rack_railway.yaml");
  for (double span : {0.2, 0.5, 2.4, 10.0}) {
    for (double b : {0.005, 0.06, 0.5}) {
      SCOPED_TRACE("span=" + std::to_string(span) + " b=" + std::to_string(b));
      Drive d = base;
      d.rack.span = span;
      d.pinion.face_width = b;
      d.rack.face_width = b;
      d.numerics.positions_per_period = 10;
      EXPECT_TRUE(check_curve(d));
    }
  }
}

TEST(HardCases, ContactRatioExactlyOneAndTwo) {
  // eps drops by Delta / (p_b sin a0) per unit clearance (docs/models/geometry.md)
  // while the rack tip limits the start: solve for the clearance that gives
  // eps = target exactly. eps = 1: the ship lift pinion; eps = 2: a 60-tooth,
  // 14 deg, x = 0.6 pinion with a 0.3 m cutter tip round (eps > 2 at zero clearance).
  int checked = 0;
  for (double target : {1.0, 2.0}) {
    SCOPED_TRACE("target eps " + std::to_string(target));
    Drive d = small_fast(test::problem("ship_lift.yaml"));
    if (target == 2.0) {
      d.pinion.teeth = 60;
      d.pinion.pressure_angle = 14.0 * M_PI / 180;
      d.pinion.profile_shift = 0.6;
      // The standard 0.38 m cutter tip round does not fit below the working
      // depth at 14 deg (limit 0.25/(1 - sin 14 deg) = 0.33): use 0.3.
      d.pinion.tip_radius_coef = 0.3;
    }
    const MeshGeometry g = MeshStiffnessModel(d).geometry();
    ASSERT_EQ(g.path.start_limited_by, "rack_tip");
    ASSERT_GT(g.path.contact_ratio, target);
    d.mounting.clearance = (g.path.contact_ratio - target) * g.path.base_pitch * std::sin(d.pinion.pressure_angle);
    const MeshStiffnessModel m(d);
    EXPECT_NEAR(m.geometry().path.contact_ratio, target, 1e-9);
    ASSERT_EQ(m.geometry().zones.size(), 1u);  // one zone: always `target` pairs
    EXPECT_EQ(m.geometry().zones.front().pairs, static_cast<int>(target));
    EXPECT_TRUE(check_curve(d));
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(HardCases, ContactExactlyAtSupportAndMidspan) {
  // Tooth 0 centred a quarter pitch from the left hinge: its pitch-line
  // contact (half thickness p/4 there) is over the hinge, so contacts cross
  // the supports while in mesh.
  Drive d = test::problem("rack_railway.yaml");
  d.rack.tooth_offset = 0.25 * M_PI * d.pinion.module;
  const MeshStiffnessModel model(d);
  const std::vector<double> br = model.breakpoints(0.0, d.rack.span);
  ASSERT_FALSE(br.empty());
  for (double x : br) {
    for (int side : {-1, 1}) {
      const MeshState s = model.at(x, side);
      EXPECT_TRUE(std::isfinite(s.stiffness) && s.stiffness > 0) << x;
    }
  }
  // A contact exactly over a hinge: with the couple term off the pin-pin beam
  // does not move there (vertical, shear and axial terms vanish at a hinge);
  // the couple still rotates the section (docs/models/rack_span.md).
  Drive no_couple = d;
  no_couple.effects.couple_term = false;
  const MeshStiffnessModel model_nc(no_couple);
  int at_hinge = 0;
  for (double x : br) {
    const MeshState a = model.at(x, +1), b = model_nc.at(x, +1);
    for (std::size_t j = 0; j < a.pairs.size(); ++j) {
      const PairState& p = a.pairs[j];
      if (std::min(p.a, d.rack.span - p.a) > 1e-9) continue;
      ++at_hinge;
      EXPECT_GT(p.body, 0.0);
      EXPECT_LT(b.pairs[j].body, 1e-9 * p.body);
    }
  }
  EXPECT_GT(at_hinge, 0);
  const MeshState mid = model.at(0.5 * d.rack.span);
  EXPECT_TRUE(std::isfinite(mid.stiffness) && mid.stiffness > 0);
}

TEST(HardCases, SpallTouchingRootOrTip) {
  const Drive base = test::problem("large_module.yaml", {"variant=severe"});
  ASSERT_FALSE(base.spalls.empty());
  Drive d = base;
  d.spalls.front().start = 0.0;  // touches the start of the active profile
  EXPECT_TRUE(check_curve(small_fast(d)));
  // Touching the tip: the band ends exactly at the tip radius.
  {
    const MeshGeometry g = MeshStiffnessModel(base).geometry();
    const double active_height = g.pinion.tip_radius - g.pinion_contact_radius(g.path.s_start);
    d = base;
    d.spalls.front().start = active_height - d.spalls.front().length;
    EXPECT_TRUE(check_curve(small_fast(d)));
  }
  // A rack spall touching the rack tip (top of the rack's active flank).
  {
    const MeshGeometry g = MeshStiffnessModel(base).geometry();
    const double rack_active = g.contact_height_above_datum(g.path.s_start) - g.contact_height_above_datum(g.path.s_end);
    d = base;
    d.spalls.front().member = Member::kRack;
    d.spalls.front().tooth = 1;
    d.spalls.front().start = rack_active - d.spalls.front().length;
    EXPECT_TRUE(check_curve(small_fast(d)));
  }
  // Too deep, too wide and off-profile spalls are rejected with their code.
  auto code_of = [](const Drive& bad) {
    try {
      MeshStiffnessModel m(bad);
    } catch (const DesignError& e) {
      return e.code();
    }
    return std::string("none");
  };
  d = base;
  d.spalls.front().depth = 0.1;
  EXPECT_EQ(code_of(d), "spall_too_deep");
  d = base;
  d.spalls.front().width = 2 * d.pinion.face_width;
  EXPECT_EQ(code_of(d), "spall_too_wide");
  d = base;
  d.spalls.front().start = 1.0;
  EXPECT_EQ(code_of(d), "spall_off_profile");
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// The load-dependent contact term at the ends of the load range: a vanishing
// load (the term grows as -ln F, floored at 1 N per metre of width) and
// loads up to where the contact strip outgrows the teeth (refused with a
// code, never NaN). The stiffness rises with the load and is continuous in
// it across the floor.
TEST(HardCases, ContactTermFromVanishingToAbsurdLoads) {
  const Drive base = small_fast(test::problem("rack_railway.yaml"));
  ASSERT_EQ(base.effects.hertz, HertzModel::kWeberBanaschek);
  double previous = 0;
  int computed = 0;
  bool refused = false;
  for (double force : {1e-9, 1e-3, 1.0, 60.0, 1e3, 5e4, 1e6, 1e7, 1e8, 1e9, 1e10, 1e12}) {
    SCOPED_TRACE("F = " + std::to_string(force));
    Drive d = base;
    d.load.force = force;
    if (!check_curve(d)) {
      refused = true;
      continue;
    }
    EXPECT_FALSE(refused) << "a larger load computed after a smaller one was refused";
    const double k = MeshStiffnessModel(d).curve().k_mean;
    EXPECT_GE(k, previous * (1 - 1e-12));  // stiffening with load (equal below the floor)
    previous = k;
    ++computed;
  }
  EXPECT_GE(computed, 7);
  EXPECT_TRUE(refused) << "a 1e12 N load should outgrow the teeth";
  // Across the floor (1 N/m x 60 mm = 0.06 N) the term is continuous.
  Drive below = base, above = base;
  below.load.force = 0.06 * (1 - 1e-9);
  above.load.force = 0.06 * (1 + 1e-9);
  const double kb = MeshStiffnessModel(below).at(0.3).stiffness, ka = MeshStiffnessModel(above).at(0.3).stiffness;
  EXPECT_NEAR(ka / kb, 1.0, 1e-6);
}

}  // namespace
}  // namespace rackopt
