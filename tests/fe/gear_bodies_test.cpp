// Meshes of the real gear bodies: the generated pinion (undercut or not)
// around its bore and a rack segment, checked against areas computed
// without the mesh (pinion_section.hpp's outline area, the rack trapezoids'
// closed form) and against the outline polygons themselves.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/geometry/pinion_section.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe {
namespace {

Drive railway() { return test_support::load_shipped_problem("rack_railway.yaml"); }

double shoelace_area(const Polygon2D& p) {
  double twice = 0;
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    const Point2 &a = p.vertices[i], &b = p.vertices[(i + 1) % p.vertices.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;  // signed: > 0 counter-clockwise
}

double radius(Point2 p) { return std::hypot(p.x, p.y); }

void expect_pinion_mesh_matches_outline(const PinionSpec& pinion, const MeshGeometry& g, double bore, int level) {
  const Mesh2D m = mesh_pinion_body(pinion, g, bore, level);
  const double expected = pinion_outline_area(pinion, g) - M_PI * bore * bore;
  EXPECT_NEAR(m.area(), expected, 1e-3 * expected);
  // The mesh fills the outline polygon exactly (straight chords throughout).
  const double size = gear_element_size(pinion.module, level);
  const BodyOutline o = pinion_body_outline(pinion, g, bore, size / 2);
  EXPECT_GT(shoelace_area(o.outer), 0);  // counter-clockwise
  double polygon_area = shoelace_area(o.outer);
  for (const Polygon2D& h : o.holes) polygon_area -= std::abs(shoelace_area(h));
  EXPECT_NEAR(m.area(), polygon_area, 1e-9 * polygon_area);
  EXPECT_LT(m.largest_edge(), 1.6 * size);
  if (bore > 0) {
    ASSERT_FALSE(m.node_set("BORE").empty());
    for (int n : m.node_set("BORE")) EXPECT_NEAR(radius(m.nodes[n]), bore, 1e-3 * bore);  // chords of the 180-gon
  }
  for (int k : {0, pinion.teeth - 1}) {
    for (const std::string side : {"_FLANK_R", "_FLANK_L"}) {
      const std::vector<int>& set = m.node_set("T" + std::to_string(k) + side);
      ASSERT_GE(set.size(), 5u);
      for (int n : set) {
        EXPECT_GE(radius(m.nodes[n]), g.pinion.form_radius * (1 - 1e-9));
        EXPECT_LE(radius(m.nodes[n]), g.pinion.tip_radius * (1 + 1e-9));
      }
    }
  }
  // Each flank is on its own side of its tooth's centre line (tooth 0 along +y).
  for (int n : m.node_set("T0_FLANK_R")) EXPECT_GT(m.nodes[n].x, 0);
  for (int n : m.node_set("T0_FLANK_L")) EXPECT_LT(m.nodes[n].x, 0);
}

TEST(GearBodies, UndercutRailwayPinionMeshesToItsOutlineArea) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  ASSERT_TRUE(g.pinion.undercut);  // z = 22 at 14 deg: the undercut case is what this test is about
  expect_pinion_mesh_matches_outline(d.pinion, g, d.pinion.bore_radius, 0);
}

TEST(GearBodies, PinionWithoutUndercutWithAndWithoutBore) {
  Drive d;  // z = 20, 20 deg, standard cutter: no undercut
  d.pinion.module = 0.004;
  const MeshGeometry g = build_mesh_geometry(d);
  ASSERT_FALSE(g.pinion.undercut);
  expect_pinion_mesh_matches_outline(d.pinion, g, 0.7 * g.pinion.root_radius, 0);
  expect_pinion_mesh_matches_outline(d.pinion, g, 0.0, 0);  // no bore: a solid disc
}

// Closed-form area of a rack segment: the body, the trapezoid teeth, and per
// root round (radius rho, two per tooth) the material it adds in the corner,
// rho t - rho^2 (pi/2 - a0)/2 with t = rho cos a0 / (1 + sin a0), plus the
// circular segments its 12 chords add beyond the arc.
double rack_segment_area(const MeshGeometry& g, int teeth, double body, double rho) {
  const RackGeometry& r = g.rack;
  const double a0 = g.pressure_angle, t = rho * std::cos(a0) / (1 + std::sin(a0));
  const double sweep = M_PI / 2 - a0, chord = sweep / 12;
  const double round = rho * t - rho * rho * sweep / 2 + 12 * rho * rho / 2 * (chord - std::sin(chord));
  return teeth * r.pitch * body + teeth * (r.half_thickness_at_root + r.half_thickness_at_tip) * (r.addendum + r.dedendum) +
         2 * teeth * round;
}

TEST(GearBodies, RackSegmentAreaAndSets) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  const RackGeometry& r = g.rack;
  const int teeth = 3;
  const double body = d.rack.body_height;
  ASSERT_GT(body, 0);
  ASSERT_EQ(d.rack.root_radius, 0);  // the cutter tip radius, 0.2 m
  const double rho = g.pinion.cutter_tip_radius;
  ASSERT_GT(rho, 0);
  const Mesh2D m = mesh_rack_segment(g, teeth, body);
  const double expected = rack_segment_area(g, teeth, body, rho);
  EXPECT_NEAR(m.area(), expected, 1e-9 * expected);
  // The rounds add what the closed form says over the sharp trapezoids (a check of the check).
  EXPECT_GT(expected - rack_segment_area(g, teeth, body, 0), 6 * 0.5 * rho * rho * 0.01);
  const double y_base = -r.dedendum - body;
  ASSERT_FALSE(m.node_set("BASE").empty());
  for (int n : m.node_set("BASE")) EXPECT_NEAR(m.nodes[n].y, y_base, 1e-12);
  for (int n : m.node_set("RIGHT_END")) EXPECT_NEAR(m.nodes[n].x, teeth * r.pitch, 1e-12);
  const double tan_a0 = std::tan(g.pressure_angle);
  const double round_top = -r.dedendum + rho * (1 - std::sin(g.pressure_angle));
  for (int k = 0; k < teeth; ++k) {
    const double xc = (k + 0.5) * r.pitch;
    for (int n : m.node_set("T" + std::to_string(k) + "_FLANK_R")) {  // x = xc + w_f - (y - y_root) tan a0
      EXPECT_NEAR(m.nodes[n].x, xc + r.half_thickness_at_root - (m.nodes[n].y + r.dedendum) * tan_a0, 1e-12);
      EXPECT_GE(m.nodes[n].y, round_top - 1e-12);  // the straight flank starts where the round ends
    }
    EXPECT_GE(m.node_set("T" + std::to_string(k) + "_FLANK_L").size(), 5u);
  }
  // The outline's round points are rho from their centres.
  const BodyOutline o = rack_segment_outline(g, teeth, body);
  const double t = rho * std::cos(g.pressure_angle) / (1 + std::sin(g.pressure_angle));
  const Point2 centre{0.5 * r.pitch + r.half_thickness_at_root + t, -r.dedendum + rho};
  int on_round = 0;
  for (const Point2& v : o.outer.vertices) on_round += std::abs(std::hypot(v.x - centre.x, v.y - centre.y) - rho) < 1e-12;
  EXPECT_EQ(on_round, 13);
  // One refinement level: same body, elements half the size.
  const Mesh2D fine = mesh_rack_segment(g, teeth, body, 1);
  EXPECT_NEAR(fine.area(), expected, 1e-9 * expected);
  EXPECT_GT(fine.triangles.size(), 3 * m.triangles.size());
  EXPECT_LT(fine.largest_edge(), 1.6 * gear_element_size(d.pinion.module, 1));
  // An explicit radius, and a sharp cutter (no round at all).
  const double explicit_rho = 0.1 * d.pinion.module;
  EXPECT_NEAR(mesh_rack_segment(g, 2, body, 0, {}, explicit_rho).area(), rack_segment_area(g, 2, body, explicit_rho),
              1e-9 * expected);
  MeshGeometry sharp = g;
  sharp.pinion.cutter_tip_radius = 0;
  EXPECT_NEAR(mesh_rack_segment(sharp, 2, body).area(), rack_segment_area(g, 2, body, 0), 1e-9 * expected);
}

TEST(GearBodies, RackRootRoundsThatDoNotFitAreDesignErrors) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  const RackGeometry& r = g.rack;
  const double a0 = g.pressure_angle;
  // The largest round the root holds: 2 t = p - 2 w_f.
  const double fits = (r.pitch - 2 * r.half_thickness_at_root) / 2 * (1 + std::sin(a0)) / std::cos(a0);
  EXPECT_NO_THROW(rack_segment_outline(g, 2, 0.05, fits * (1 - 1e-9)));
  try {
    rack_segment_outline(g, 2, 0.05, fits * 1.01);
    FAIL() << "overlapping root rounds were accepted";
  } catch (const DesignError& e) {
    EXPECT_EQ(e.code(), "rack_root_round");
  }
  EXPECT_THROW(rack_segment_outline(g, 2, 0.05, -1e-3), std::invalid_argument);
}

// Longest corner-to-corner edge of the triangles whose centroid lies within `r` of `c`.
double largest_edge_near(const Mesh2D& m, Point2 c, double r) {
  double h = 0;
  for (const Triangle6& t : m.triangles) {
    const Point2 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &d = m.nodes[t[2]];
    if (std::hypot((a.x + b.x + d.x) / 3 - c.x, (a.y + b.y + d.y) / 3 - c.y) > r) continue;
    for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, d}, std::pair{d, a}}) h = std::max(h, std::hypot(q.x - p.x, q.y - p.y));
  }
  return h;
}

template <class F>
double seconds_of(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(GearBodies, GradedPinionIsFineOnlyOnItsFocusTeeth) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  const double bore = d.pinion.bore_radius, size = gear_element_size(d.pinion.module, 0);
  Mesh2D full, graded;
  const double t_full = seconds_of([&] { full = mesh_pinion_body(d.pinion, g, bore, 0); });
  MeshGrading grading;
  grading.focus_teeth = {21, 0, 1};
  const double t_graded = seconds_of([&] { graded = mesh_pinion_body(d.pinion, g, bore, 0, grading); });
  std::printf("railway pinion level 0: %zu triangles %.2f s ungraded, %zu triangles %.2f s graded on 3 teeth\n",
              full.triangles.size(), t_full, graded.triangles.size(), t_graded);
  // The mesh fills its own (mixed-spacing) outline polygon, and that polygon
  // is still the pinion to the coarse chords' sag.
  const double coarse = std::min(4 * size, d.pinion.module);
  const BodyOutline o = pinion_body_outline(d.pinion, g, bore, size / 2, grading.focus_teeth, coarse / 2);
  double polygon_area = shoelace_area(o.outer);
  for (const Polygon2D& h : o.holes) polygon_area -= std::abs(shoelace_area(h));
  EXPECT_NEAR(graded.area(), polygon_area, 1e-9 * polygon_area);
  // The far teeth's curves may be as coarse as 2 chords: 2.3e-3 of the area.
  const double expected = pinion_outline_area(d.pinion, g) - M_PI * bore * bore;
  EXPECT_NEAR(graded.area(), expected, 5e-3 * expected);
  EXPECT_LT(graded.triangles.size(), full.triangles.size() / 3);
  // The focus teeth keep the level's size and their flank spacing; a far tooth is coarse.
  for (int k : grading.focus_teeth) {
    const Refinement disc = pinion_focus_disc(d.pinion, g, k, size);
    EXPECT_LT(largest_edge_near(graded, disc.center, disc.radius), 1.6 * size) << "tooth " << k;
    for (const std::string side : {"_FLANK_R", "_FLANK_L"}) {
      const std::string set = "T" + std::to_string(k) + side;
      EXPECT_EQ(graded.node_set(set).size(), full.node_set(set).size()) << set;
    }
  }
  const Refinement far = pinion_focus_disc(d.pinion, g, 11, size);
  EXPECT_GT(largest_edge_near(graded, far.center, far.radius), 2.5 * size);
  EXPECT_LT(graded.node_set("T11_FLANK_R").size(), full.node_set("T11_FLANK_R").size());
  EXPECT_LT(graded.largest_edge(), 1.6 * coarse);
  grading.focus_teeth = {22};
  EXPECT_THROW(mesh_pinion_body(d.pinion, g, bore, 0, grading), std::invalid_argument);
}

TEST(GearBodies, GradedRackAndExtraRefinementDiscs) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  const RackGeometry& r = g.rack;
  const double size = gear_element_size(d.pinion.module, 0), body = 3 * d.pinion.module;
  const Mesh2D full = mesh_rack_segment(g, 3, body);
  MeshGrading grading;
  grading.focus_teeth = {1};
  // A disc of a quarter of the size on tooth 1's +x flank at the datum line.
  const Point2 spot{1.5 * r.pitch + r.half_thickness_at_datum, 0};
  grading.refinements = {{spot, 0.3 * d.pinion.module, size / 4}};
  const Mesh2D graded = mesh_rack_segment(g, 3, body, 0, grading);
  const double expected = rack_segment_area(g, 3, body, g.pinion.cutter_tip_radius);
  EXPECT_NEAR(graded.area(), expected, 1e-9 * expected);
  // Inside the disc (its rim already sees the steep growth to the coarse size).
  EXPECT_LT(largest_edge_near(graded, spot, 0.15 * d.pinion.module), 0.35 * size);
  const Refinement disc = rack_focus_disc(g, 1, size);
  EXPECT_LT(largest_edge_near(graded, disc.center, disc.radius), 1.6 * size);
  EXPECT_GT(largest_edge_near(graded, {0.1 * r.pitch, -r.dedendum - 0.8 * body}, 0.1 * body), 2 * size);
  // The ungraded mesh takes the extra disc too.
  MeshGrading only_disc;
  only_disc.refinements = grading.refinements;
  const Mesh2D refined = mesh_rack_segment(g, 3, body, 0, only_disc);
  EXPECT_LT(largest_edge_near(refined, spot, 0.15 * d.pinion.module), 0.35 * size);
  EXPECT_GT(refined.triangles.size(), full.triangles.size());
  grading.focus_teeth = {3};
  EXPECT_THROW(mesh_rack_segment(g, 3, body, 0, grading), std::invalid_argument);
}

TEST(GearBodies, ImpossibleBodiesAreDesignErrorsBeforeMeshing) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  try {
    mesh_pinion_body(d.pinion, g, g.pinion.root_radius * 1.01);
    FAIL() << "a bore beyond the root circle was meshed";
  } catch (const DesignError& e) {
    EXPECT_EQ(e.code(), "bore_beyond_root");
  }
  MeshGeometry pointed = g;
  pointed.rack.half_thickness_at_tip = -1e-4;
  try {
    mesh_rack_segment(pointed, 2, 0.05);
    FAIL() << "a pointed rack tooth was meshed";
  } catch (const DesignError& e) {
    EXPECT_EQ(e.code(), "pointed_tooth");
  }
  EXPECT_THROW(mesh_pinion_body(d.pinion, g, -0.01), std::invalid_argument);
  EXPECT_THROW(mesh_rack_segment(g, 0, 0.05), std::invalid_argument);
  EXPECT_THROW(gear_element_size(d.pinion.module, 7), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt::fe
