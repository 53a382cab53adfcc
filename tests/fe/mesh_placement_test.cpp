// Placing the pinion and the rack segment of a mesh position: every
// theoretical contact on both outlines (and the exact involute and rack-flank
// points at it coincide), the bodies apart everywhere else, and with a
// mounting clearance the non-working flanks apart by the normal backlash
// 2 Delta sin a0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/fe/mesh_placement.hpp"
#include "rackopt/geometry/pinion_generation.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe {
namespace {

Drive problem(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return test_support::load_shipped_problem(name + ".yaml", overrides);
}

Point2 rotate(Point2 p, double a) { return {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a)}; }

MeshPlacement place(const Drive& d, const MeshStiffnessModel& model, double X, double spacing_in_modules = 1.0 / 6) {
  const double m = d.pinion.module;
  return place_mesh(d, model, X, PlacementSpacing{m * spacing_in_modules, m * std::min(spacing_in_modules, 0.01), 0.25}, 2 * m, true);
}

// The pinion's tooth-k flank point at radius R, placed as the placement says.
Point2 placed_involute(const Drive& d, const MeshPlacement& pl, int k, double R, bool ccw_flank) {
  const ToothPoint q = involute_point(d.pinion, R);
  const Point2 local = rotate({ccw_flank ? -q.x : q.x, q.y}, 2 * M_PI * k / d.pinion.teeth + pl.pinion_rotation);
  return {local.x + pl.pinion_centre.x, local.y + pl.pinion_centre.y};
}

void expect_contacts_on_both_flanks(const Drive& d, double X) {
  SCOPED_TRACE(d.name + " at X = " + std::to_string(X));
  const MeshStiffnessModel model(d);
  const MeshGeometry& g = model.geometry();
  const MeshPlacement pl = place(d, model, X);
  const double a0 = d.pinion.pressure_angle, m = d.pinion.module, pitch = M_PI * m;
  const double offset = d.rack.tooth_offset >= 0 ? d.rack.tooth_offset : pitch / 2;
  const MeshState st = model.at(X);
  int theoretical = 0;
  for (const FlankContact& c : pl.contacts) {
    if (!c.theoretical) continue;
    ++theoretical;
    // On both polylines (a vertex of each).
    EXPECT_LT(distance_to_polygon(pl.pinion.outer, c.contact), 1e-9);
    EXPECT_LT(distance_to_polygon(pl.rack.outer, c.contact), 1e-9);
    // The exact involute point at that radius (pinion turned once for all
    // pairs) and the exact rack flank (tooth j's -x flank: x = x_t - (pi m/4 - h tan a0)).
    const double R = std::hypot(c.contact.x - pl.pinion_centre.x, c.contact.y - pl.pinion_centre.y);
    EXPECT_NEAR(R, std::sqrt(g.pinion.base_radius * g.pinion.base_radius + c.s * c.s), 1e-12);
    const Point2 inv = placed_involute(d, pl, c.pinion_tooth, R, true);
    EXPECT_LT(std::hypot(inv.x - c.contact.x, inv.y - c.contact.y), 1e-9);
    const double xt = offset + c.rack_tooth * pitch;
    EXPECT_NEAR(c.contact.x, xt - (pitch / 4 - c.contact.y * std::tan(a0)), 1e-9);
    EXPECT_NEAR(c.contact.y, g.contact_height_above_datum(c.s), 1e-12);
  }
  EXPECT_EQ(theoretical, static_cast<int>(st.pairs.size()));
  EXPECT_EQ(pl.rack_teeth, static_cast<int>(st.pairs.size()) + 2 * rack_teeth_each_side(pl.rack_body_depth, pitch));
  EXPECT_GE(pl.rack_teeth, static_cast<int>(st.pairs.size()) + 2);
  // No overlap: the vertices and chord midpoints of each outline are outside
  // the other. At zero backlash the non-working flanks touch too, and a
  // chord across a concave fillet lies outside the true fillet by its sag,
  // so the check draws the outlines at m/1000 (sag below 1e-7 m) and allows
  // 1e-6 m: an error of the placement would show as a much deeper overlap.
  const MeshPlacement fine = place(d, model, X, 1e-3);
  const Point2 O = fine.pinion_centre;
  const auto expect_apart = [&](const Polygon2D& a, const Polygon2D& b, const char* what) {
    double worst = 0;
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
      const Point2 p = a.vertices[i], q = a.vertices[(i + 1) % a.vertices.size()];
      for (Point2 t : {p, Point2{(p.x + q.x) / 2, (p.y + q.y) / 2}}) {
        if (std::hypot(t.x - O.x, t.y - O.y) > g.pinion.tip_radius * 1.01) continue;  // far from the pinion
        if (t.y > g.rack.addendum * 1.01) continue;                                    // above the rack
        if (inside_polygon(b, t)) worst = std::max(worst, distance_to_polygon(b, t));
      }
    }
    EXPECT_LT(worst, 1e-6 * m) << what;
  };
  // (The rack's outline is exact at any spacing: its coarse drawing, in the same place, suffices.)
  expect_apart(fine.pinion.outer, pl.rack.outer, "pinion points inside the rack");
  expect_apart(pl.rack.outer, fine.pinion.outer, "rack points inside the pinion");
}

TEST(MeshPlacement, ContactsOnBothOutlinesAndNoOverlap) {
  for (const char* name : {"gantry_axis", "ship_lift", "rack_railway"}) {
    const Drive d = problem(name);
    const double p = M_PI * d.pinion.module;
    for (double f : {0.0, 0.23, 0.5, 0.77}) expect_contacts_on_both_flanks(d, 1.3 * p + f * p);
  }
  // A clearance moves the pinion away; the working flanks still touch.
  expect_contacts_on_both_flanks(problem("rack_railway", {"mounting.clearance=2 mm"}), 0.4);
}

TEST(MeshPlacement, NonWorkingFlanksApartByTheBacklash) {
  for (double clearance_mm : {0.0, 2.0}) {
    const Drive d = problem("rack_railway", {"mounting.clearance=" + std::to_string(clearance_mm) + " mm"});
    const MeshStiffnessModel model(d);
    const MeshGeometry& g = model.geometry();
    const MeshPlacement pl = place(d, model, 0.41);
    const double a0 = d.pinion.pressure_angle, pitch = g.rack.pitch;
    const double offset = d.rack.tooth_offset >= 0 ? d.rack.tooth_offset : pitch / 2;
    // Smallest distance from the pinion teeth's clockwise flanks (exact
    // involute points) to the rack teeth's +x flanks (finite segments).
    double gap = INFINITY;
    for (int k = 0; k < d.pinion.teeth; ++k) {
      for (int i = 0; i < 200; ++i) {
        const double R = g.pinion.form_radius + (g.pinion.tip_radius - g.pinion.form_radius) * (i + 0.5) / 200;
        const Point2 q = placed_involute(d, pl, k, R, false);
        if (q.y > g.rack.addendum + 1e-3) continue;
        for (int j = pl.first_rack_tooth; j < pl.first_rack_tooth + pl.rack_teeth; ++j) {
          const double xt = offset + j * pitch;
          const double h = std::clamp(q.y - (q.x - (xt + pitch / 4 - q.y * std::tan(a0))) * std::sin(a0) * std::cos(a0),
                                      -g.rack.dedendum, g.rack.addendum);
          const Point2 f{xt + pitch / 4 - h * std::tan(a0), h};
          gap = std::min(gap, std::hypot(q.x - f.x, q.y - f.y));
        }
      }
    }
    // Normal backlash of a rack pair whose datum moved Delta away: 2 Delta sin a0
    // (the circumferential backlash 2 Delta tan a0 times cos a0).
    EXPECT_NEAR(gap, 2 * clearance_mm * 1e-3 * std::sin(a0), 2e-7) << "clearance " << clearance_mm << " mm";
  }
}

TEST(MeshPlacement, NeighboursAreTheTeethEachSide) {
  const Drive d = problem("gantry_axis");
  const MeshStiffnessModel model(d);
  const MeshPlacement pl = place(d, model, 0.05);
  const MeshState st = model.at(0.05);
  ASSERT_EQ(pl.contacts.size(), st.pairs.size() + 2);
  const FlankContact& enter = pl.contacts[st.pairs.size()];
  const FlankContact& leave = pl.contacts[st.pairs.size() + 1];
  EXPECT_FALSE(enter.theoretical);
  EXPECT_EQ(enter.rack_tooth, st.pairs.back().rack_tooth - 1);
  EXPECT_EQ(leave.rack_tooth, st.pairs.front().rack_tooth + 1);
  EXPECT_LT(enter.s, model.geometry().path.s_start);
  EXPECT_GE(leave.s, model.geometry().path.s_end);
  // The segment carries rack_teeth_each_side teeth before the pairs in mesh;
  // the entering tooth is the last of them.
  const int side = rack_teeth_each_side(pl.rack_body_depth, model.geometry().rack.pitch);
  EXPECT_EQ(enter.rack_tooth - pl.first_rack_tooth, side - 1);
  EXPECT_EQ(enter.rack_set, "T" + std::to_string(side - 1) + "_FLANK_L");
}

}  // namespace
}  // namespace rackopt::fe
