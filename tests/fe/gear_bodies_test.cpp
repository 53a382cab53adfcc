// Meshes of the real gear bodies: the generated pinion (undercut or not)
// around its bore and a rack segment, checked against areas computed
// without the mesh (pinion_section.hpp's outline area, the rack trapezoids'
// closed form) and against the outline polygons themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/geometry/pinion_section.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt::fe {
namespace {

Drive railway() { return load_problem(std::string(RACKOPT_SOURCE_DIR) + "/problems/rack_railway.yaml"); }

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

TEST(GearBodies, RackSegmentAreaAndSets) {
  const Drive d = railway();
  const MeshGeometry g = build_mesh_geometry(d);
  const RackGeometry& r = g.rack;
  const int teeth = 3;
  const double body = d.rack.body_height;
  ASSERT_GT(body, 0);
  const Mesh2D m = mesh_rack_segment(g, teeth, body);
  const double expected = teeth * r.pitch * body +
                          teeth * (r.half_thickness_at_root + r.half_thickness_at_tip) * (r.addendum + r.dedendum);
  EXPECT_NEAR(m.area(), expected, 1e-9 * expected);
  const double y_base = -r.dedendum - body;
  ASSERT_FALSE(m.node_set("BASE").empty());
  for (int n : m.node_set("BASE")) EXPECT_NEAR(m.nodes[n].y, y_base, 1e-12);
  for (int n : m.node_set("RIGHT_END")) EXPECT_NEAR(m.nodes[n].x, teeth * r.pitch, 1e-12);
  const double tan_a0 = std::tan(g.pressure_angle);
  for (int k = 0; k < teeth; ++k) {
    const double xc = (k + 0.5) * r.pitch;
    for (int n : m.node_set("T" + std::to_string(k) + "_FLANK_R")) {  // x = xc + w_f - (y - y_root) tan a0
      EXPECT_NEAR(m.nodes[n].x, xc + r.half_thickness_at_root - (m.nodes[n].y + r.dedendum) * tan_a0, 1e-12);
    }
    EXPECT_GE(m.node_set("T" + std::to_string(k) + "_FLANK_L").size(), 5u);
  }
  // One refinement level: same body, elements half the size.
  const Mesh2D fine = mesh_rack_segment(g, teeth, body, 1);
  EXPECT_NEAR(fine.area(), expected, 1e-9 * expected);
  EXPECT_GT(fine.triangles.size(), 3 * m.triangles.size());
  EXPECT_LT(fine.largest_edge(), 1.6 * gear_element_size(d.pinion.module, 1));
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
