// Gmsh meshing: geometry, node sets, element order and orientation,
// refinement, and the serialized global Gmsh session.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <future>
#include <set>

#include "rackopt/fe/edge_loads.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/fe/gmsh_mesher.hpp"

namespace rackopt::fe {
namespace {

bool gmsh_mapped() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    if (line.find("libgmsh") != std::string::npos) return true;
  }
  return false;
}

// Gmsh is opened at the first mesh, not at program start: a program that
// never meshes never pays for loading it (gmsh_library.hpp).
TEST(GmshMesher, TheLibraryIsOpenedAtTheFirstMeshOnly) {
  if (gmsh_loaded()) GTEST_SKIP() << "another test of this process meshed first (ctest runs each test alone)";
  EXPECT_FALSE(gmsh_mapped());
  (void)mesh_rectangle(0, 0, 1, 1, 0.5);
  EXPECT_TRUE(gmsh_loaded());
  EXPECT_TRUE(gmsh_mapped());
  EXPECT_NE(gmsh_library_name().find("libgmsh.so"), std::string::npos);
}

TEST(GmshMesher, RectangleAreaSetsAndQuadraticTriangles) {
  const double L = 0.03, H = 0.01;
  const Mesh2D m = mesh_rectangle(0.01, -0.005, L, H, 0.0025);
  EXPECT_NEAR(m.area(), L * H, 1e-12 * L * H);
  EXPECT_LT(m.largest_edge(), 1.5 * 0.0025);
  for (const Triangle6& t : m.triangles) {
    const Point2 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
    EXPECT_GT((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y), 0);  // counter-clockwise
    for (int k = 0; k < 3; ++k) {  // mid-side nodes at the middle of the straight edges
      const Point2 &p = m.nodes[t[k]], &q = m.nodes[t[(k + 1) % 3]], &mid = m.nodes[t[3 + k]];
      EXPECT_NEAR(mid.x, 0.5 * (p.x + q.x), 1e-12);
      EXPECT_NEAR(mid.y, 0.5 * (p.y + q.y), 1e-12);
    }
  }
  for (int n : m.node_set("RIGHT")) EXPECT_NEAR(m.nodes[n].x, 0.01 + L, 1e-15);
  for (int n : m.node_set("TOP")) EXPECT_NEAR(m.nodes[n].y, -0.005 + H, 1e-15);
  // A 3-node quadratic edge on each 2.5 mm: 4 edges, 9 nodes along the 10 mm side.
  EXPECT_EQ(m.node_set("LEFT").size(), 9u);
  ASSERT_EQ(m.node_set("TOP_RIGHT").size(), 1u);
  const Point2 corner = m.nodes[m.node_set("TOP_RIGHT")[0]];
  EXPECT_NEAR(corner.x, 0.04, 1e-15);
  EXPECT_NEAR(corner.y, 0.005, 1e-15);
  EXPECT_THROW(m.node_set("NOPE"), std::out_of_range);
}

TEST(GmshMesher, RefinementMakesTheMeshFinerThere) {
  const Mesh2D plain = mesh_rectangle(0, 0, 0.02, 0.01, 0.002);
  const Mesh2D refined = mesh_rectangle(0, 0, 0.02, 0.01, 0.002, {{{0.0, 0.0}, 0.002, 0.0004}});
  EXPECT_GT(refined.triangles.size(), plain.triangles.size() + 20);
  // The smallest edge near the corner is about the asked size.
  double shortest = 1;
  for (const Triangle6& t : refined.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Point2 &a = refined.nodes[t[k]], &b = refined.nodes[t[(k + 1) % 3]];
      shortest = std::min(shortest, std::hypot(b.x - a.x, b.y - a.y));
    }
  }
  EXPECT_LT(shortest, 0.0007);
  EXPECT_NEAR(refined.area(), 2e-4, 1e-15);
}

TEST(GmshMesher, BadInputIsRejected) {
  EXPECT_THROW(mesh_rectangle(0, 0, 1, 1, 0), std::invalid_argument);
  EXPECT_THROW(mesh_rectangle(0, 0, -1, 1, 0.1), std::invalid_argument);
  Polygon2D p;
  p.vertices = {{0, 0}, {1, 0}};
  EXPECT_THROW(mesh_polygon(p, 0.1), std::invalid_argument);
  p.vertices = {{0, 0}, {1, 0}, {0, 1}};
  p.edge_names = {"bad name"};
  EXPECT_THROW(mesh_polygon(p, 0.1), std::invalid_argument);
}

// Gmsh's session is global: concurrent calls are serialized, each gets its own model.
TEST(GmshMesher, ConcurrentCallsAreSerialized) {
  const std::size_t expected = mesh_rectangle(0, 0, 0.02, 0.01, 0.002).triangles.size();
  auto a = std::async(std::launch::async, [] { return mesh_rectangle(0, 0, 0.02, 0.01, 0.002).triangles.size(); });
  auto b = std::async(std::launch::async, [] { return mesh_rectangle(0, 0, 0.02, 0.01, 0.002).triangles.size(); });
  EXPECT_EQ(a.get(), expected);
  EXPECT_EQ(b.get(), expected);
}

TEST(EdgeLoads, ConsistentForcesOfUniformAndLinearTractions) {
  const Mesh2D m = mesh_rectangle(0, 0, 0.02, 0.01, 0.005);
  double fx = 0, moment = 0;
  std::set<int> loaded;
  for (const NodeLoad& l : edge_traction_loads(m, "RIGHT", [](Point2 p) { return Point2{3e6 * p.y, 0}; })) {
    fx += l.fx;
    moment += l.fx * m.nodes[l.node].y;
    loaded.insert(l.node);
    EXPECT_EQ(l.fy, 0);
  }
  // Resultant and first moment of the linear traction 3e6 y over y in [0, 0.01].
  EXPECT_NEAR(fx, 3e6 * 0.01 * 0.01 / 2, 1e-9);
  EXPECT_NEAR(moment, 3e6 * 0.01 * 0.01 * 0.01 / 3, 1e-11);
  EXPECT_EQ(loaded.size(), m.node_set("RIGHT").size());
  // One quadratic edge under a uniform traction: 1/6, 4/6, 1/6 of q l.
  const Mesh2D coarse = mesh_rectangle(0, 0, 0.01, 0.01, 0.01);
  std::vector<double> f;
  for (const NodeLoad& l : edge_traction_loads(coarse, "TOP", [](Point2) { return Point2{0, -600}; })) f.push_back(l.fy);
  std::sort(f.begin(), f.end());
  ASSERT_EQ(f.size(), 3u);
  EXPECT_NEAR(f[0], -4.0, 1e-12);
  EXPECT_NEAR(f[1], -1.0, 1e-12);
  EXPECT_NEAR(f[2], -1.0, 1e-12);
}

}  // namespace
}  // namespace rackopt::fe
