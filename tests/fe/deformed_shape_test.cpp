// What a mesh position hands back for pictures, and extended contact, on the
// small drive of mesh_position_test.cpp (the gantry axis with 14 teeth,
// x = +0.3, 12 mm rack body) at twice the gantry's thrust, just before a pair
// enters mesh: the entering pair's flanks are then a few micrometres apart
// unloaded (the gap grows with the square of the distance to the entry), far
// less than the mesh deflection, so without tip relief they touch early.
//
// One solve with theoretical contacts only (its shape kept) and one with
// extended contact, side by side:
//  * the shape: meshes and displacements of both bodies, the bore turned
//    rigidly by the hub rotation, the rack base still, the loaded pinion
//    flanks turned counter-clockwise (the loaded direction) but less than the
//    hub (the teeth bend back), the loaded rack flanks pushed along +x; the
//    two pictures are valid PNGs;
//  * extended contact: a neighbouring pair carries load (theoretical =
//    false), K is not smaller, the shares (theoretical + extended) sum to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <string>
#include <vector>

#include <unistd.h>

#include "fe_test_helpers.hpp"
#include "rackopt/fe/deformed_shape.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/fe/mesh_position_fe.hpp"
#include "rackopt/fe/shape_plot.hpp"
#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/file_check.hpp"
#include "rackopt/output/plot.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/scratch_dir.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe {
namespace {

namespace fs = std::filesystem;

Drive loaded_small_drive() { return testing::small_gantry({"load.thrust=12 kN"}); }

// A travel 3 % of a pitch before a pair enters mesh.
double just_before_an_entry(const Drive& d) {
  double entry = 0;
  fe_positions(MeshStiffnessModel(fe_reference_drive(d)), 1, &entry);
  return entry - 0.03 * M_PI * d.pinion.module;
}

using testing::share_sum;

void check_shape(const FePosition& p) {
  ASSERT_TRUE(p.shape);
  const DeformedShape& s = *p.shape;
  ASSERT_EQ(s.bodies.size(), 2u);
  const ShapeBody& pinion = s.bodies[0];
  const ShapeBody& rack = s.bodies[1];
  EXPECT_EQ(static_cast<int>(pinion.mesh.nodes.size() + rack.mesh.nodes.size()), p.nodes);
  ASSERT_EQ(pinion.displacement.size(), pinion.mesh.nodes.size());
  ASSERT_EQ(rack.displacement.size(), rack.mesh.nodes.size());
  EXPECT_GT(s.hub_rotation, 0);

  const Point2 o = s.pinion_centre;
  // Counter-clockwise turn of a pinion node about O [rad] (small rotations).
  const auto turn = [&](int n) {
    const Point2 x = pinion.mesh.nodes[static_cast<std::size_t>(n)], u = pinion.displacement[static_cast<std::size_t>(n)];
    const double dx = x.x - o.x, dy = x.y - o.y;
    return (dx * u.y - dy * u.x) / (dx * dx + dy * dy);
  };
  // The bore turns rigidly with the hub (7 printed digits).
  for (int n : pinion.mesh.node_set("BORE")) EXPECT_NEAR(turn(n) / s.hub_rotation, 1.0, 1e-5);
  for (int n : rack.mesh.node_set("BASE")) {
    EXPECT_EQ(rack.displacement[static_cast<std::size_t>(n)].x, 0.0);
    EXPECT_EQ(rack.displacement[static_cast<std::size_t>(n)].y, 0.0);
  }
  int pinion_nodes = 0, rack_nodes = 0;
  double least_turn = INFINITY, most_turn = -INFINITY;
  for (const FlankContact& c : s.contacts) {
    ASSERT_TRUE(c.theoretical);
    for (int n : pinion.mesh.node_set(c.pinion_set)) {
      least_turn = std::min(least_turn, turn(n));
      most_turn = std::max(most_turn, turn(n));
      ++pinion_nodes;
    }
    for (int n : rack.mesh.node_set(c.rack_set)) {
      EXPECT_GT(rack.displacement[static_cast<std::size_t>(n)].x, 0) << "rack node " << n;
      ++rack_nodes;
    }
  }
  EXPECT_GT(pinion_nodes, 10);
  EXPECT_GT(rack_nodes, 10);
  // Every loaded pinion flank node turned the loaded way, by less than the
  // hub: the tooth bends back against the rack.
  EXPECT_GT(least_turn, 0);
  EXPECT_LT(most_turn, s.hub_rotation);

  const ShapeScale scale = shape_scale(s, shape_window(s));
  EXPECT_NEAR(scale.factor * scale.largest, kDrawnDisplacementPerModule * s.module, 1e-15);
  std::printf("[ FE shape ] hub %.4g mrad, loaded pinion flanks turned %.3f..%.3f of it; largest displacement in "
              "view %.3g um, drawn x %.4g\n",
              s.hub_rotation * 1e3, least_turn / s.hub_rotation, most_turn / s.hub_rotation, scale.largest * 1e6,
              scale.factor);

  // Both pictures render to valid PNGs.
  const fs::path dir = test_support::scratch_dir("shape_plot");
  write_file_atomic((dir / "mesh.gp").string(), mesh_gnuplot(s, "small drive", "mesh.png.tmp"));
  write_file_atomic((dir / "deformed.gp").string(), deformed_gnuplot(s, "small drive", "deformed.png.tmp"));
  std::vector<std::string> warnings;
  const std::string mesh_png = render_plot(dir.string(), "mesh.gp", "mesh.png", warnings);
  const std::string deformed_png = render_plot(dir.string(), "deformed.gp", "deformed.png", warnings);
  if (!warnings.empty() && warnings[0].find("not found") != std::string::npos) {
    fs::remove_all(dir);
    GTEST_SKIP() << warnings[0];
  }
  ASSERT_FALSE(mesh_png.empty()) << (warnings.empty() ? "" : warnings[0]);
  ASSERT_FALSE(deformed_png.empty()) << (warnings.empty() ? "" : warnings.back());
  EXPECT_EQ(check_output_file(mesh_png, mesh_png), "");
  EXPECT_EQ(check_output_file(deformed_png, deformed_png), "");
  EXPECT_GT(fs::file_size(mesh_png), 10000u);
  if (std::getenv("RACKOPT_KEEP_PICTURES") == nullptr) fs::remove_all(dir);
}

void check_extended_contact(const FePosition& a, const FePosition& b) {
  int extra = 0;
  double extra_share = 0;
  for (const FePair& q : b.pairs) {
    std::printf("[ FE ext.  ] pair rack %d pinion %d s %.4f mm %s share %.4f force %.1f N\n", q.rack_tooth, q.pinion_tooth,
                q.s * 1e3, q.theoretical ? "theoretical" : "extended", q.load_share, q.force);
    EXPECT_GT(q.load_share, 0);
    if (!q.theoretical) {
      ++extra;
      extra_share += q.load_share;
      EXPECT_GT(q.force, 0);
    }
  }
  for (const FePair& q : a.pairs) EXPECT_TRUE(q.theoretical);
  EXPECT_EQ(extra, 1);
  EXPECT_GT(extra_share, 0.01);
  EXPECT_EQ(b.pairs.size(), a.pairs.size() + static_cast<std::size_t>(extra));
  EXPECT_NEAR(share_sum(a), 1.0, 1e-3);
  // The neighbour (s_q beyond the path's end s_E: the pair about to enter)
  // touches the rack flank with the pinion's tip corner, which lies off the
  // line of action: turned back by delta = (s_q - s_E) / r_b from the
  // involute's conjugate point, the corner is d = r_b (1 - cos delta) +
  // s_E sin delta nearer the pinion centre than the LOA. Its force, normal
  // to the straight rack flank and so parallel to the LOA, has the lever arm
  // r_b - d: the torque at the bore counts it d / r_b short, and the shares,
  // forces over F = T / r_b, sum to 1 + share x d / r_b.
  const Drive d = loaded_small_drive();
  const MeshStiffnessModel model(fe_reference_drive(d));
  const MeshGeometry& geo = model.geometry();
  const double rb = geo.pinion.base_radius, s_end = geo.path.s_end;
  double excess = 0;
  for (const FePair& q : b.pairs) {
    if (q.theoretical) continue;
    ASSERT_GT(q.s, s_end);
    const double delta = (q.s - s_end) / rb;
    excess += q.load_share * (rb * (1 - std::cos(delta)) + s_end * std::sin(delta)) / rb;
  }
  EXPECT_NEAR(share_sum(b) - 1, excess, 5e-4);
  EXPECT_GE(b.stiffness, a.stiffness * (1 - 1e-4));
  std::printf("[ FE ext.  ] K %.4g -> %.4g N/m (%+.2f %%) with extended contact; the neighbour's share %.3f, shares "
              "sum - 1: %.2e (lever arm predicts %.2e); %.1f s + %.1f s\n",
              a.stiffness, b.stiffness, 100 * (b.stiffness / a.stiffness - 1), extra_share, share_sum(b) - 1, excess,
              a.seconds, b.seconds);
}

// One test, so that the two solves (about 15 s and 30 s of CPU, run side by
// side) are made once: ctest runs every test in a process of its own.
TEST(FeShapeAndExtendedContact, ShapeOfTheLoadedMeshAndANeighbourInExtendedContact) {
  const Drive d = loaded_small_drive();
  const double X = just_before_an_entry(d);
  FeOptions plain;
  plain.keep_shape = true;
  FeOptions extended;
  extended.extended_contact = true;
  auto b = std::async(std::launch::async, [&] { return fe_mesh_position(d, X, extended); });
  const FePosition theoretical = fe_mesh_position(d, X, plain);
  const FePosition with_neighbours = b.get();
  EXPECT_FALSE(with_neighbours.shape);  // only when asked for
  {
    SCOPED_TRACE("deformed shape");
    check_shape(theoretical);
  }
  {
    SCOPED_TRACE("extended contact");
    check_extended_contact(theoretical, with_neighbours);
  }
}

}  // namespace
}  // namespace rackopt::fe
